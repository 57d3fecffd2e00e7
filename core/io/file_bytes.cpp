#include "core/io/file_bytes.h"

#include <algorithm>
#include <fstream>

#include "core/common/errors.h"

namespace ew {
namespace {

std::uintmax_t checkedSize(const std::filesystem::path& file) {
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) {
    throw Error(ErrorKind::Io, file.string(), "", "no such file");
  }
  if (std::filesystem::is_directory(file, ec)) {
    throw Error(ErrorKind::Io, file.string(), "", "is a directory, not a file");
  }
  auto size = std::filesystem::file_size(file, ec);
  if (ec) throw Error(ErrorKind::Io, file.string(), "", "cannot read size: " + ec.message());
  if (size > kMaxInputFileBytes) {
    throw Error(ErrorKind::Io, file.string(), "",
                "file is " + std::to_string(size) + " bytes, over the 1 GiB limit");
  }
  return size;
}

template <typename Buffer>
Buffer readAll(const std::filesystem::path& file) {
  auto size = checkedSize(file);
  std::ifstream in(file, std::ios::binary);
  if (!in) throw Error(ErrorKind::Io, file.string(), "", "cannot open for reading");
  Buffer buffer(static_cast<size_t>(size), {});
  if (size > 0 && !in.read(reinterpret_cast<char*>(buffer.data()),
                           static_cast<std::streamsize>(size))) {
    throw Error(ErrorKind::Io, file.string(), "", "read failed");
  }
  return buffer;
}

}  // namespace

std::vector<std::uint8_t> readFileBytes(const std::filesystem::path& file) {
  return readAll<std::vector<std::uint8_t>>(file);
}

std::string readFileText(const std::filesystem::path& file) {
  return readAll<std::string>(file);
}

std::string readFileStart(const std::filesystem::path& file, std::size_t bytes) {
  std::ifstream in(file, std::ios::binary);
  std::string text(bytes, '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  text.resize(static_cast<std::size_t>(std::max<std::streamsize>(in.gcount(), 0)));
  return text;
}

}  // namespace ew

#include "core/io/atomic_write.h"

#include <fstream>
#include <random>

#include "core/common/errors.h"

namespace ew {
namespace {

std::filesystem::path temporarySibling(const std::filesystem::path& target) {
  std::random_device rd;
  auto name = "." + target.filename().string() + ".tmp" + std::to_string(rd() % 1000000);
  return target.parent_path() / name;
}

}  // namespace

void writeFileAtomically(const std::filesystem::path& target,
                         const std::function<void(std::ostream&)>& write) {
  const auto temp = temporarySibling(target);
  try {
    {
      std::ofstream out(temp, std::ios::binary | std::ios::trunc);
      if (!out) throw Error(ErrorKind::Io, target.string(), "", "cannot create file");
      write(out);
      out.flush();
      if (!out) throw Error(ErrorKind::Io, target.string(), "", "write failed (disk full?)");
    }
    std::error_code ec;
    std::filesystem::rename(temp, target, ec);
    if (ec) throw Error(ErrorKind::Io, target.string(), "", "cannot rename into place: " + ec.message());
  } catch (...) {
    std::error_code ignored;
    std::filesystem::remove(temp, ignored);
    throw;
  }
}

std::filesystem::path folderPathWithoutTrailingSeparator(const std::filesystem::path& path) {
  std::filesystem::path p = path.lexically_normal();
  while (!p.empty() && p.filename().empty() && p.has_relative_path()) p = p.parent_path();
  return p;
}

}  // namespace ew

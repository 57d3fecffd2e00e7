#include "core/io/binary_arrays.h"

#include <bit>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "core/common/errors.h"

namespace ew {

using nlohmann::json;

// [SECTION] Checksums and float64 arrays

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  return h;
}

std::string hex64(std::uint64_t value) {
  char buf[17];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(value));
  return buf;
}

std::string encodeFloat64(const double* values, std::size_t count) {
  std::string out(count * 8, '\0');
  for (std::size_t i = 0; i < count; ++i) {
    const auto bits = std::bit_cast<std::uint64_t>(values[i]);
    for (std::size_t b = 0; b < 8; ++b)
      out[i * 8 + b] = static_cast<char>((bits >> (8 * b)) & 0xff);
  }
  return out;
}

void decodeFloat64(std::string_view bytes, double* values) {
  const std::size_t count = bytes.size() / 8;
  for (std::size_t i = 0; i < count; ++i) {
    std::uint64_t bits = 0;
    for (std::size_t b = 0; b < 8; ++b)
      bits |= static_cast<std::uint64_t>(static_cast<unsigned char>(bytes[i * 8 + b])) << (8 * b);
    values[i] = std::bit_cast<double>(bits);
  }
}

std::string byteAt(std::size_t offset) { return "byte " + std::to_string(offset); }

// [SECTION] Header lines

namespace {

// The end of the line starting at `begin` (its '\n'), or Malformed "truncated".
std::size_t lineEnd(std::string_view bytes, std::size_t begin, int line, const std::string& file) {
  const std::size_t end = bytes.find('\n', begin);
  if (end == std::string_view::npos)
    throwMalformed(file, "line " + std::to_string(line),
                   "truncated: the header line has no end (" + std::to_string(bytes.size()) +
                       " bytes in file)");
  return end;
}

}  // namespace

std::string headerText(std::string_view magic, int version, const std::string& metadataLine) {
  return std::string(magic) + " " + std::to_string(version) + "\n" + metadataLine + "\n" +
         "fnv1a64 " + hex64(fnv1a64(metadataLine)) + "\n";
}

int parseHeaderVersion(std::string_view bytes, std::string_view magic, std::string_view description,
                       const std::string& file) {
  const std::string_view first = bytes.substr(0, lineEnd(bytes, 0, 1, file));
  const std::string prefix = std::string(magic) + " ";
  if (first.rfind(prefix, 0) != 0)
    throwMalformed(file, "byte 0",
                   "not an " + std::string(description) + " (expected \"" + std::string(magic) +
                       " <version>\")");
  const std::string v(first.substr(prefix.size()));
  if (v.empty() || v.find_first_not_of("0123456789") != std::string::npos || v.size() > 6)
    throwMalformed(file, "line 1", "bad version \"" + v + "\"");
  return std::stoi(v);
}

HeaderMetadata readHeaderMetadata(std::string_view bytes, const std::string& file) {
  const std::size_t end1 = lineEnd(bytes, 0, 1, file);
  const std::size_t end2 = lineEnd(bytes, end1 + 1, 2, file);
  const std::size_t end3 = lineEnd(bytes, end2 + 1, 3, file);
  const std::string_view sumLine = bytes.substr(end2 + 1, end3 - end2 - 1);
  if (sumLine.rfind("fnv1a64 ", 0) != 0 || sumLine.size() != 8 + 16)
    throwMalformed(file, "line 3", "expected \"fnv1a64 <16 hex digits>\"");
  const std::string_view metadata = bytes.substr(end1 + 1, end2 - end1 - 1);
  if (sumLine.substr(8) != hex64(fnv1a64(metadata)))
    throwMalformed(file, "line 2", "metadata checksum mismatch: the file is damaged");
  return {metadata, end3 + 1};
}

// [SECTION] Metadata (line 2)

json parseMetadataJson(std::string_view line, const std::string& file) {
  json meta;
  try {
    meta = json::parse(line.begin(), line.end());
  } catch (const json::exception& e) {
    throwMalformed(file, "line 2", std::string("bad metadata JSON: ") + e.what());
  }
  if (!meta.is_object()) throwMalformed(file, "line 2", "metadata is not a JSON object");
  return meta;
}

long long metadataInteger(const json& object, const char* key, std::string_view owner,
                          const std::string& file) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number_integer())
    throwMalformed(file, "line 2", std::string(owner) + " has no integer '" + key + "'");
  return object[key].get<long long>();
}

double metadataNumber(const json& object, const char* key, std::string_view owner,
                      const std::string& file) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_number() ||
      !std::isfinite(object[key].get<double>()))
    throwMalformed(file, "line 2", std::string(owner) + " has no finite number '" + key + "'");
  return object[key].get<double>();
}

std::vector<std::string> metadataStrings(const json& object, const char* key,
                                         std::string_view owner, const std::string& file) {
  if (!object.is_object() || !object.contains(key) || !object[key].is_array())
    throwMalformed(file, "line 2", std::string(owner) + " has no list '" + key + "'");
  std::vector<std::string> out;
  for (const auto& v : object[key]) {
    if (!v.is_string())
      throwMalformed(file, "line 2", std::string("'") + key + "' holds a non-string");
    out.push_back(v.get<std::string>());
  }
  return out;
}

void appendArray(json& list, std::string& payload, const std::string& name,
                 const Eigen::MatrixXd& values) {
  const std::string bytes = encodeFloat64(values.data(), static_cast<std::size_t>(values.size()));
  list.push_back({{"name", name},
                  {"rows", values.rows()},
                  {"cols", values.cols()},
                  {"fnv1a64", hex64(fnv1a64(bytes))}});
  payload += bytes;
}

std::vector<ArraySpec> metadataArraySpecs(const json& object, std::string_view owner,
                                          const std::string& file) {
  if (!object.is_object() || !object.contains("arrays") || !object["arrays"].is_array())
    throwMalformed(file, "line 2", std::string(owner) + " has no 'arrays' list");
  std::vector<ArraySpec> specs;
  for (const auto& a : object["arrays"]) {
    if (!a.is_object() || !a.contains("name") || !a["name"].is_string() || !a.contains("rows") ||
        !a["rows"].is_number_integer() || !a.contains("cols") || !a["cols"].is_number_integer() ||
        !a.contains("fnv1a64") || !a["fnv1a64"].is_string())
      throwMalformed(file, "line 2", "an 'arrays' entry lacks name, rows, cols or fnv1a64");
    ArraySpec s;
    s.name = a["name"].get<std::string>();
    s.rows = a["rows"].get<Eigen::Index>();
    s.cols = a["cols"].get<Eigen::Index>();
    const auto hex = a["fnv1a64"].get<std::string>();
    char* end = nullptr;
    s.checksum = std::strtoull(hex.c_str(), &end, 16);
    if (hex.size() != 16 || end != hex.c_str() + hex.size())
      throwMalformed(file, "line 2", "bad checksum text for array '" + s.name + "'");
    if (s.rows < 0 || s.cols < 0 || s.rows > 1'000'000 || s.cols > 1'000'000)
      throwMalformed(file, "line 2", "absurd size for array '" + s.name + "'");
    specs.push_back(s);
  }
  return specs;
}

void checkArrayShapes(const std::vector<ArraySpec>& arrays, const std::vector<ArraySpec>& expected,
                      std::string_view owner, const std::string& file) {
  if (arrays.size() != expected.size())
    throwMalformed(file, "line 2",
                   "expected " + std::to_string(expected.size()) + " arrays, " +
                       std::string(owner) + " lists " + std::to_string(arrays.size()));
  for (std::size_t i = 0; i < arrays.size(); ++i) {
    const ArraySpec& want = expected[i];
    if (arrays[i].name != want.name || arrays[i].rows != want.rows || arrays[i].cols != want.cols)
      throwMalformed(file, "line 2",
                     "array " + std::to_string(i) + " should be '" + want.name + "' " +
                         std::to_string(want.rows) + " x " + std::to_string(want.cols) + ", " +
                         std::string(owner) + " says '" + arrays[i].name + "' " +
                         std::to_string(arrays[i].rows) + " x " + std::to_string(arrays[i].cols));
  }
}

// [SECTION] Payload

void checkPayloadSize(std::string_view bytes, std::size_t payloadStart, std::size_t expectedBytes,
                      const std::string& file) {
  const std::size_t available = bytes.size() - payloadStart;
  if (available < expectedBytes)
    throwMalformed(file, byteAt(bytes.size()),
                   "truncated: payload has " + std::to_string(available) + " of " +
                       std::to_string(expectedBytes) + " bytes");
  if (available > expectedBytes)
    throwMalformed(
        file, byteAt(payloadStart + expectedBytes),
        std::to_string(available - expectedBytes) + " unexpected bytes after the payload");
}

Eigen::MatrixXd readFloat64Array(std::string_view bytes, std::size_t offset, const ArraySpec& spec,
                                 const std::string& what, const std::string& file) {
  if (offset > bytes.size() || bytes.size() - offset < spec.byteCount())
    throwMalformed(file, byteAt(bytes.size()), "truncated in " + what);
  const std::string_view data = bytes.substr(offset, spec.byteCount());
  if (fnv1a64(data) != spec.checksum)
    throwMalformed(file,
                   "bytes " + std::to_string(offset) + "-" + std::to_string(offset + data.size()),
                   "checksum mismatch in " + what + ": the file is damaged");
  Eigen::MatrixXd m(spec.rows, spec.cols);
  decodeFloat64(data, m.data());
  return m;
}

}  // namespace ew

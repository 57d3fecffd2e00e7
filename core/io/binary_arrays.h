#pragma once
// The pieces shared by core's checksummed binary files (docs/MODEL_FORMAT.md,
// docs/SNIPPET_FORMAT.md), which all have the same shape:
//   line 1  "<MAGIC> <version>"
//   line 2  one line of JSON metadata, listing each array's name, shape and checksum
//   line 3  "fnv1a64 <16 hex digits>": FNV-1a 64 of line 2's bytes
//   then    float64 arrays, little-endian IEEE-754, column-major, back to back
// Readers work on the file's bytes in memory and throw Error(Malformed) naming the file and
// the line or byte; they never read outside the bytes and check a payload's size against
// the bytes there before allocating it. Core-internal: the metadata helpers take
// nlohmann::json, so only code linking nlohmann_json (core, tests) includes this.

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <nlohmann/json_fwd.hpp>
#include <string>
#include <string_view>
#include <vector>

namespace ew {

// [SECTION] Checksums and float64 arrays

// FNV-1a 64 (Fowler–Noll–Vo; offset basis 14695981039346656037, prime 1099511628211).
std::uint64_t fnv1a64(std::string_view bytes);

// 16 lower-case hex digits.
std::string hex64(std::uint64_t value);

// The 8 bytes of each IEEE-754 double, least significant first, whatever the host's byte
// order: decodeFloat64(encodeFloat64(v)) == v bit for bit.
std::string encodeFloat64(const double* values, std::size_t count);
// Decodes bytes.size() / 8 values into `values`.
void decodeFloat64(std::string_view bytes, double* values);

// "byte N", the position of an error in the payload.
std::string byteAt(std::size_t offset);

// [SECTION] Header lines

// Lines 1–3 for `magic`, `version` and one line of JSON (no newline inside).
std::string headerText(std::string_view magic, int version, const std::string& metadataLine);

// The version from line 1. Throws Malformed at byte 0 when the magic is wrong ("not an
// <description> (expected "<MAGIC> <version>")"), at line 1 for a bad version number or a
// line without its newline. The caller decides which versions it reads.
int parseHeaderVersion(std::string_view bytes, std::string_view magic, std::string_view description,
                       const std::string& file);

// Line 2 (checked against line 3's checksum) and where the payload starts. Throws
// Malformed for a missing newline ("truncated", line 2 or 3), a badly formed line 3, or a
// checksum mismatch (line 2: the metadata is damaged).
struct HeaderMetadata {
  std::string_view line;
  std::size_t payloadStart = 0;
};
HeaderMetadata readHeaderMetadata(std::string_view bytes, const std::string& file);

// [SECTION] Metadata (line 2)

// Line 2 as a JSON object; Malformed at line 2 for bad JSON or anything but an object.
nlohmann::json parseMetadataJson(std::string_view line, const std::string& file);

// `object[key]`, which must be an integer / a finite number / a list of strings; else
// Malformed at line 2: "<owner> has no integer 'key'" (owner: "metadata", "cluster 3").
long long metadataInteger(const nlohmann::json& object, const char* key, std::string_view owner,
                          const std::string& file);
double metadataNumber(const nlohmann::json& object, const char* key, std::string_view owner,
                      const std::string& file);
std::vector<std::string> metadataStrings(const nlohmann::json& object, const char* key,
                                         std::string_view owner, const std::string& file);

// One array of the payload as the metadata describes it.
struct ArraySpec {
  std::string name;
  Eigen::Index rows = 0, cols = 0;
  std::uint64_t checksum = 0;
  Eigen::Index count() const { return rows * cols; }
  std::size_t byteCount() const { return static_cast<std::size_t>(count()) * 8; }
};

// Appends {name, rows, cols, fnv1a64} to `list` and the array's bytes to `payload`.
void appendArray(nlohmann::json& list, std::string& payload, const std::string& name,
                 const Eigen::MatrixXd& values);

// `object["arrays"]`, each entry {name, rows, cols, fnv1a64}; Malformed at line 2 when the
// list or a field is missing, a checksum is not 16 hex digits or a size is negative or
// over 1,000,000.
std::vector<ArraySpec> metadataArraySpecs(const nlohmann::json& object, std::string_view owner,
                                          const std::string& file);

// The arrays must be exactly `expected` (names and shapes, in order); Malformed at line 2
// "array i should be 'name' r x c, <owner> says …" otherwise.
void checkArrayShapes(const std::vector<ArraySpec>& arrays, const std::vector<ArraySpec>& expected,
                      std::string_view owner, const std::string& file);

// [SECTION] Payload

// The payload (from payloadStart to the end of the bytes) must hold exactly
// `expectedBytes`: Malformed "truncated" at the end of the file, or "unexpected bytes
// after the payload" at the first extra byte. Call before allocating the arrays.
void checkPayloadSize(std::string_view bytes, std::size_t payloadStart, std::size_t expectedBytes,
                      const std::string& file);

// The array at `offset` (its checksum checked first: Malformed "bytes A-B: checksum
// mismatch in <what>") decoded into a rows × cols matrix. The caller has checked the
// payload's size.
Eigen::MatrixXd readFloat64Array(std::string_view bytes, std::size_t offset, const ArraySpec& spec,
                                 const std::string& what, const std::string& file);

}  // namespace ew

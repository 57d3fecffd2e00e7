// libFuzzer harness: the two binary files of the project's own layout (header lines, JSON
// metadata, sizes, checksums, payload) -> ew::parseModel (.ewm, core/eigenwalker/model_file.h, the
// in-memory half of loadModel) and ew::parseSnippetPrior (.ewsp, core/snippet/snippet_file.h).
// Each input goes to both readers, twice: as it is, then with line 3 rewritten to hold the right
// FNV-1a 64 checksum of line 2, so that mutated metadata gets past the header checksum
// and reaches the size and shape checks (a fuzzer rarely forges a 64-bit hash itself).
// A typed ew::Error is the correct outcome; anything else is a finding (fuzz_common.h).

#include <cinttypes>
#include <cstdio>
#include <string>

#include "core/eigenwalker/model_file.h"
#include "core/snippet/snippet_file.h"
#include "tests/fuzz/fuzz_common.h"

namespace {

// FNV-1a 64 (docs/MODEL_FORMAT.md), as lower-case hex.
std::string fnv1a64Hex(std::string_view bytes) {
  std::uint64_t h = 14695981039346656037ull;
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 1099511628211ull;
  }
  char text[17];
  std::snprintf(text, sizeof text, "%016" PRIx64, h);
  return text;
}

// The input with line 3 replaced by "fnv1a64 <checksum of line 2>"; empty when the input
// has fewer than three lines.
std::string withHeaderChecksumFixed(std::string_view bytes) {
  const std::size_t end1 = bytes.find('\n');
  if (end1 == std::string_view::npos) return {};
  const std::size_t end2 = bytes.find('\n', end1 + 1);
  if (end2 == std::string_view::npos) return {};
  const std::size_t end3 = bytes.find('\n', end2 + 1);
  if (end3 == std::string_view::npos) return {};
  std::string fixed(bytes.substr(0, end2 + 1));
  fixed += "fnv1a64 " + fnv1a64Hex(bytes.substr(end1 + 1, end2 - end1 - 1));
  fixed += bytes.substr(end3);
  return fixed;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view bytes = ew::fuzz::asText(data, size);
  const auto readBoth = [](std::string_view input) {
    ew::fuzz::acceptTypedErrors([&] { ew::parseModel(input, "fuzz.ewm"); });
    ew::fuzz::acceptTypedErrors([&] { ew::parseSnippetPrior(input, "fuzz.ewsp"); });
  };
  readBoth(bytes);
  const std::string fixed = withHeaderChecksumFixed(bytes);
  if (!fixed.empty()) readBoth(fixed);
  return 0;
}

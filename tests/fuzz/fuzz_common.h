#pragma once
// Shared by the libFuzzer harnesses of tests/fuzz/ (docs/FUZZING.md).
//
// The rule every harness follows: a typed ew::Error is the correct answer to a bad input,
// so it is caught here and the input counts as handled. Anything else — a crash, another
// exception, a sanitizer report, a timeout, a memory blow-up — is a finding: other
// exceptions are deliberately not caught, so libFuzzer sees std::terminate's abort as a
// crash and the replay runner (replay_main.cpp) reports the input that threw.

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <span>
#include <string_view>
#include <utility>

#include "core/common/errors.h"

// The libFuzzer entry point each harness defines (one per executable).
extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size);

namespace ew::fuzz {

// The fuzzer's bytes as the text a text reader takes (no copy; any byte value, no NUL end).
inline std::string_view asText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

inline std::span<const std::uint8_t> asBytes(const std::uint8_t* data, std::size_t size) {
  return {data, size};
}

// EW_FUZZ_VERBOSE set: print each rejection's message (to see how far seeds get).
inline bool verbose() {
  static const bool on = std::getenv("EW_FUZZ_VERBOSE") != nullptr;
  return on;
}

// Runs `parse` on one input; an ew::Error is a rejection, the correct outcome for bad
// input. Returns 0, as libFuzzer requires.
template <class Parse>
int acceptTypedErrors(Parse&& parse) {
  try {
    std::forward<Parse>(parse)();
    if (verbose()) std::fprintf(stderr, "  accepted\n");
  } catch (const ew::Error& e) {
    // Rejected with a typed error naming the file and the place: what we want.
    if (verbose()) std::fprintf(stderr, "  rejected: %s\n", e.what());
  }
  return 0;
}

// Two files in one input: everything before the first line that is exactly `separator`
// (a '\n' or the input's start before it, a '\n' or the input's end after it), and
// everything after that line. Without the line, the whole input is the first file and
// the second is empty. Lets one fuzzer input drive an ASF skeleton and its AMC motion.
inline std::pair<std::string_view, std::string_view> splitAtLine(std::string_view text,
                                                                 std::string_view separator) {
  std::size_t from = 0;
  while (from <= text.size()) {
    const std::size_t at = text.find(separator, from);
    if (at == std::string_view::npos) break;
    const std::size_t after = at + separator.size();
    const bool startsLine = at == 0 || text[at - 1] == '\n';
    const bool endsLine = after == text.size() || text[after] == '\n';
    if (startsLine && endsLine) {
      return {text.substr(0, at), text.substr(after == text.size() ? after : after + 1)};
    }
    from = at + 1;
  }
  return {text, std::string_view()};
}

// The line separating the ASF from the AMC in fuzz_asf_amc and fuzz_pipeline inputs.
inline constexpr std::string_view kAmcSeparator = "%%AMC%%";

}  // namespace ew::fuzz

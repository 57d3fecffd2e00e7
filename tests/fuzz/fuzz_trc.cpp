// libFuzzer harness: TRC text -> ew::parseTrc (core/io/trc_reader.h). A typed ew::Error is
// the correct outcome; anything else is a finding (fuzz_common.h).

#include "core/io/trc_reader.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors(
      [&] { ew::parseTrc(ew::fuzz::asText(data, size), "fuzz.trc"); });
}

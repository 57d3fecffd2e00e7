// libFuzzer harness: our 15-joint CSV text -> ew::parseJointCsv (core/io/joint_csv.h).
// A typed ew::Error is the correct outcome; anything else is a finding (fuzz_common.h).

#include "core/io/joint_csv.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors(
      [&] { ew::parseJointCsv(ew::fuzz::asText(data, size), "fuzz.csv"); });
}

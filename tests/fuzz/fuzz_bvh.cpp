// libFuzzer harness: BVH text -> ew::parseBvh (core/io/bvh_reader.h), hierarchy, motion
// and forward kinematics. A typed ew::Error is the correct outcome; anything else is a
// finding (fuzz_common.h).

#include "core/io/bvh_reader.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors(
      [&] { ew::parseBvh(ew::fuzz::asText(data, size), "fuzz.bvh"); });
}

// libFuzzer harness: TRC text -> ew::parseTrc (core/io/trc_reader.h), then what parses, as a
// 2D view (ew::planarTrcTrial, core/keypoints/keypoint_trial.h: refused unless it is planar). A
// typed ew::Error is the correct outcome; anything else is a finding (fuzz_common.h).

#include "core/io/trc_reader.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return ew::fuzz::acceptTypedErrors([&] {
    const ew::RawTrial raw = ew::parseTrc(ew::fuzz::asText(data, size), "fuzz.trc");
    (void)ew::planarTrcTrial(raw);
  });
}

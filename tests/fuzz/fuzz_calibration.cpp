// libFuzzer harness: calibration file text -> ew::parseCalibrationToml
// (core/camera/calibration_file.h). A typed ew::Error is the correct outcome; anything else
// is a finding (fuzz_common.h). Every camera read must have positive focal lengths.

#include <cstdlib>

#include "core/camera/calibration_file.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ew::fuzz::acceptTypedErrors([&] {
    for (const ew::CalibratedCamera& c : ew::parseCalibrationToml(ew::fuzz::asText(data, size), "fuzz.toml"))
      if (!(c.focalPx() > 0.0)) std::abort();
  });
  return 0;
}

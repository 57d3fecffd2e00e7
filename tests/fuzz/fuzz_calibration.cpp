// libFuzzer harness: calibration file text -> ew::parseCalibrationToml
// (core/camera/calibration_file.h). A typed ew::Error is the correct outcome; anything else
// is a finding (fuzz_common.h). Every camera read must have a camera's focal lengths
// (core/camera/focal_length.h) and an image size its callers can take as int pixels.

#include <cstdlib>

#include "core/camera/calibration_file.h"
#include "core/camera/focal_length.h"
#include "core/keypoints/keypoint_frames.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ew::fuzz::acceptTypedErrors([&] {
    for (const ew::CalibratedCamera& c : ew::parseCalibrationToml(ew::fuzz::asText(data, size), "fuzz.toml")) {
      if (!ew::isPlausibleFocalPx(c.fxPx) || !ew::isPlausibleFocalPx(c.fyPx)) std::abort();
      if (c.widthPx > ew::kMaxKeypointImageSidePx || c.heightPx > ew::kMaxKeypointImageSidePx) std::abort();
    }
  });
  return 0;
}

// libFuzzer harness: the calibrated-camera path of `reconstruct --unknown-camera --camera`
// (app/cli/reconstruct_camera.cpp), up to the fit: a calibration TOML, a line %%KEYPOINTS%%,
// then a keypoint file whose reader the first byte picks (fuzz_keypoint_readers.h). The
// calibration's first camera gives the image size, as the command's does for MediaPipe and
// YOLO; the keypoints are cleaned (cleanKeypoints), undistorted through the camera
// (undistortTrial) and their gait cycles found as the fit's are (gaitForTheFit: foot strikes,
// the trunk's bob). The keypoints harness never undistorts, so it could not reach issue 53's
// crash: a lens that drops every point, then the gait cycles of nobody. A typed ew::Error is
// the correct outcome; anything else is a finding (fuzz_common.h).

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "core/camera/calibration_file.h"
#include "core/camera/clip_reconstruction.h"
#include "core/camera/lens_distortion.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/fuzz/fuzz_common.h"
#include "tests/fuzz/fuzz_keypoint_readers.h"

namespace {

constexpr std::string_view kKeypointsSeparator = "%%KEYPOINTS%%";

// The image the camera's points are in: its `size` (bounded by the reader), else a 1920 × 1080 guess.
ew::KeypointImageSize imageOf(const ew::CalibratedCamera& c) {
  if (!(c.widthPx > 0 && c.heightPx > 0)) return {1920, 1080};
  return {static_cast<int>(c.widthPx), static_cast<int>(c.heightPx)};
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  // Not a structured binding: clang 14 cannot capture one in a lambda.
  const std::pair<std::string_view, std::string_view> files =
      ew::fuzz::splitAtLine(ew::fuzz::asText(data + 1, size - 1), kKeypointsSeparator);
  const std::string_view calibration = files.first, keypoints = files.second;
  ew::fuzz::acceptTypedErrors([&] {
    const std::vector<ew::CalibratedCamera> cameras = ew::parseCalibrationToml(calibration, "fuzz.toml");
    const ew::CalibratedCamera& camera = cameras.front();  // the reader returns one or throws
    ew::KeypointTrial trial =
        ew::cleanKeypoints(ew::fuzz::readKeypointsWith(data[0], std::string(keypoints), imageOf(camera)));
    (void)ew::undistortTrial(camera, trial);
    ew::CameraFitOptions options;
    options.focalPx = camera.focalPx();
    std::string source;
    (void)ew::gaitForTheFit(trial, options, source);
  });
  return 0;
}

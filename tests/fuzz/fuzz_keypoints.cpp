// libFuzzer harness: a pose estimator's keypoint file -> the reader its first byte picks
// (0 OpenPose frame JSON, 1 AlphaPose JSON, 2 MMPose JSON, 3 MediaPipe CSV, 4 DeepLabCut
// CSV, 5 a YOLO pose label file; core/keypoints/keypoint_frames.h), then, for what reads, the cleaning
// (cleanKeypoints: tracking, layout guess, joints) and the image gait cycles. A typed
// ew::Error is the correct outcome; anything else is a finding (fuzz_common.h).

#include <string>
#include <utility>
#include <vector>

#include "core/keypoints/image_gait.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/fuzz/fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const int reader = data[0] % 6;
  const std::string text(ew::fuzz::asText(data + 1, size - 1));
  ew::fuzz::acceptTypedErrors([&] {
    ew::KeypointFrames frames;
    switch (reader) {
      case 0:
        frames = ew::parseOpenPoseFrames({{"fuzz_000000000000_keypoints.json", text}}, "fuzz");
        break;
      case 1:
        frames = ew::parseAlphaPoseJson(text, "fuzz.json");
        break;
      case 2:
        frames = ew::parseMmposeJson(text, "fuzz.json");
        break;
      case 3:
        frames = ew::parseMediaPipeCsv(text, "fuzz.csv", ew::KeypointImageSize{640, 480});
        break;
      case 4:
        frames = ew::parseDeepLabCutCsv(text, "fuzz.csv");
        break;
      default:
        frames = ew::parseYoloPoseLabels({{"fuzz_1.txt", text}}, "fuzz", ew::KeypointImageSize{640, 480});
        break;
    }
    const ew::KeypointTrial trial = ew::cleanKeypoints(frames);
    (void)ew::imageGaitCycles(trial);
  });
  return 0;
}

// libFuzzer harness: a pose estimator's keypoint file -> the reader its first byte picks
// (fuzz_keypoint_readers.h), then, for what reads, the cleaning (cleanKeypoints: tracking,
// layout guess, joints) and the image gait cycles — on the whole clip, on its first frame with
// somebody in it and on no frame (the one-frame and empty cases of every format, issue 53). A
// typed ew::Error is the correct outcome; anything else is a finding (fuzz_common.h).

#include <string>

#include "core/keypoints/image_gait.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/fuzz/fuzz_common.h"
#include "tests/fuzz/fuzz_keypoint_readers.h"

namespace {

void cleanAndFindCycles(const ew::KeypointFrames& frames) {
  ew::fuzz::acceptTypedErrors([&] {
    const ew::KeypointTrial trial = ew::cleanKeypoints(frames);
    (void)ew::imageGaitCycles(trial);
  });
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  const std::string text(ew::fuzz::asText(data + 1, size - 1));
  ew::fuzz::acceptTypedErrors([&] {
    const ew::KeypointFrames frames = ew::fuzz::readKeypointsWith(data[0], text, ew::KeypointImageSize{640, 480});
    cleanAndFindCycles(frames);
    cleanAndFindCycles(ew::fuzz::firstFrameWithSomebody(frames));
    cleanAndFindCycles(ew::fuzz::noFrames(frames));
  });
  return 0;
}

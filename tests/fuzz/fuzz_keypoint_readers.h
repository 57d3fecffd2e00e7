#pragma once
// The keypoint readers behind fuzz_keypoints' and fuzz_calibrated_clip's selector byte
// (core/keypoints/keypoint_frames.h): 0 an OpenPose frame file, 1 AlphaPose JSON, 2 MMPose
// JSON, 3 MediaPipe CSV, 4 DeepLabCut CSV, 5 a YOLO pose label file. MediaPipe and YOLO hold
// fractions of the image: `imageSize` multiplies them.

#include <cstdint>
#include <string>
#include <utility>

#include "core/keypoints/keypoint_frames.h"

namespace ew::fuzz {

inline constexpr int kKeypointReaders = 6;

inline KeypointFrames readKeypointsWith(std::uint8_t selector, const std::string& text,
                                        const KeypointImageSize& imageSize) {
  switch (selector % kKeypointReaders) {
    case 0:
      return parseOpenPoseFrames({{"fuzz_000000000000_keypoints.json", text}}, "fuzz");
    case 1:
      return parseAlphaPoseJson(text, "fuzz.json");
    case 2:
      return parseMmposeJson(text, "fuzz.json");
    case 3:
      return parseMediaPipeCsv(text, "fuzz.csv", imageSize);
    case 4:
      return parseDeepLabCutCsv(text, "fuzz.csv");
    default:
      return parseYoloPoseLabels({{"fuzz_1.txt", text}}, "fuzz", imageSize);
  }
}

// The clip cut to its first frame with somebody in it, and to no frame at all: what a reader
// gives for a one-frame file and an empty one, whatever the format (the stages after the reader
// must answer both with a typed error or a result, issue 53).
inline KeypointFrames firstFrameWithSomebody(const KeypointFrames& frames) {
  KeypointFrames one = frames;
  one.frames.clear();
  for (const auto& f : frames.frames)
    if (!f.empty()) {
      one.frames.push_back(f);
      break;
    }
  return one;
}

inline KeypointFrames noFrames(const KeypointFrames& frames) {
  KeypointFrames none = frames;
  none.frames.clear();
  return none;
}

}  // namespace ew::fuzz

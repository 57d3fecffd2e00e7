#pragma once
// Joints marked by hand on a few frames of a video: where the tracker starts (issue 14;
// Howe, Leventon & Freeman 1999 §2 and Zou et al. 2009 §4 start the same way). The file
// (docs/TRACKING.md):
//   {"format": "eigenwalker-keyframes", "version": 1, "video": "demo.mp4",
//    "keyframes": [{"frame": 40, "joints": {"head": [812.5, 201.0], "l_wrist": null, …}}]}
// Pixels, x right, y down, as the video has them; a joint left out or null was not seen.

#include <Eigen/Core>
#include <filesystem>
#include <string>
#include <vector>

namespace ew {

struct Keyframe {
  int frame = 0;
  Eigen::RowVectorXd jointsPx;  // 30: x, y per joint (METHOD §1 order), NaN = not marked
};

struct Keyframes {
  std::string video;                // the clip they were marked on ("" when unsaid)
  std::vector<Keyframe> keyframes;  // increasing frame numbers
};

inline constexpr int kMaxKeyframes = 100000;

// Throws Error(Io) when unreadable, Error(Malformed) naming the file and keyframe for bad
// JSON, another format, an unknown joint name, a coordinate that is not a finite number
// pair, a negative or repeated frame, more than kMaxKeyframes; Error(BadData) when no
// keyframe has at least one joint. Keyframes come back sorted by frame.
Keyframes readKeyframes(const std::filesystem::path& file);
Keyframes parseKeyframes(const std::string& text, const std::string& name);

// How far outside the picture a mark may lie, as a share of the picture's width and height: a
// foot the frame's edge cuts off is marked a little outside it; further out, the keyframes were
// not marked on this video (or a coordinate was typed wrong).
inline constexpr double kMarkMarginShare = 0.25;

// Throws Error(BadData) naming `file`, the keyframe's frame and the joint for a mark further
// outside a widthPx × heightPx picture than kMarkMarginShare of its size.
void checkMarksWithin(const Keyframes& keyframes, int widthPx, int heightPx, const std::string& file);

// Throws Error(BadData) naming `file` (the keyframe file) and the keyframe for one on a frame
// the video does not have (frameCount frames, 0-based): marked on another, longer video, or a
// frame number typed wrong. Such a keyframe is no tracker's to skip: the file is at fault.
void checkKeyframesWithin(const Keyframes& keyframes, int frameCount, const std::string& file);

// True for a .json file whose start says it is a keyframe file (its "format" field), so a
// keyframe file and a pose estimator's JSON can be told apart without reading either whole.
bool isKeyframeFile(const std::filesystem::path& path);

// Writes atomically (core/io/atomic_write.h).
void writeKeyframes(const std::filesystem::path& file, const Keyframes& keyframes);
std::string formatKeyframes(const Keyframes& keyframes);

// Keyframes from a 2D track (T × 30 pixels, NaN = missing) at the given frames, e.g. a
// pose estimator's detections (keypoint_trial.h). Error(BadArgument) for a frame outside
// the track or one with no joint in it; a frame given twice is one keyframe.
Keyframes keyframesFromTrack(const Eigen::Ref<const Eigen::MatrixXd>& jointsPx,
                             const std::vector<int>& frames, const std::string& video);

}  // namespace ew

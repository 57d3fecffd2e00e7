#pragma once
// From what a pose estimator wrote (keypoint_frames.h) to one walker's 15 joints in the
// image: follow each person across the frames, choose the one who walks, decide the
// skeleton layout (stated, or guessed from which reading stands upright), drop points
// below a confidence, and build the 15 joints (docs/KEYPOINTS.md).
// Image coordinates throughout: pixels, u to the right, v down, as the video has them.

#include <Eigen/Core>
#include <array>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/common/skeleton.h"
#include "core/common/trial.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"

namespace ew {

struct KeypointOptions {
  std::optional<std::string> layout;  // a layout name (--layout): no guessing
  std::optional<double> fps;          // the video's frame rate; else the file's (CSV time), else 30
  double minConfidence = 0.3;         // points below are missing (Pose2Sim's default)
  std::optional<int> person;          // the track to use (index into KeypointTrial::people)
  // Which named points make each joint, for files that name their own (DeepLabCut).
  std::optional<std::filesystem::path> mappingFile;
  std::optional<KeypointImageSize> imageSize;  // the points' image (--image-size): MediaPipe's, YOLO's
  // The video the points were found in, when known (found beside them: video/video_beside.h):
  // its size and rate stand in where neither the options above nor the file give them.
  std::optional<KeypointVideo> video;
  std::optional<KeypointImageSize> videoSize() const {
    return video ? std::optional<KeypointImageSize>(video->size) : std::nullopt;
  }
  // Take the layout's detector offsets into account (KeypointLayout::detectorOffsetMm);
  // false (--no-detector-offsets): the detector's points are taken for joint centres.
  bool detectorOffsets = true;
};

inline constexpr double kDefaultKeypointFps = 30.0;

// One person followed across frames.
struct PersonTrack {
  std::vector<int> frames;            // frames it appears in, increasing
  std::vector<int> detection;         // its detection index in each of those frames
  double travelPx = 0.0;              // how far its centre moves from where it starts (max)
  double sizePx = 0.0;                // median height of its keypoints' bounding box
  // Its 15 joints (u, v per joint, METHOD §1 order, NaN = missing), one row per entry of
  // `frames`, built by the clip's layout: what the viewer draws of the people not chosen.
  Eigen::MatrixXd jointsPx;
};

struct KeypointTrial {
  std::string file, format;
  const KeypointLayout* layout = nullptr;
  std::shared_ptr<const KeypointLayout> builtLayout;  // keeps `layout` alive when made for this file
  std::string layoutSource;           // how the layout was decided, for the user
  double rateHz = kDefaultKeypointFps;
  bool rateAssumed = true;            // no --fps given: kDefaultKeypointFps
  int frameCount = 0;
  int maxPeople = 0;                  // most people in one frame
  std::vector<PersonTrack> people;    // every track, longest first
  int chosen = 0;                     // index into people
  std::string chosenReason;
  Eigen::MatrixXd jointsPx;           // frames x 30: u, v per joint (METHOD §1 order), NaN = missing
  // frames x 15: each joint's confidence, the least of the points it is made of (NaN where
  // missing); empty for a trial made otherwise (a tracker's, a planar TRC).
  Eigen::MatrixXd jointConfidence;
  // frames x 8: u, v of the walker's heel and toe per foot (FootPoint order), where the layout
  // has them (BODY_25's heels and toes, MediaPipe's heel and foot index); NaN where not seen;
  // empty (0 x 0) for a layout without feet or a trial made otherwise. Beside the 15 joints,
  // which stay the engines' input.
  Eigen::MatrixXd feetPx;
  std::array<bool, kJointCount> derived{};  // built from other points (head from the ears, …)
  // Where the points sit relative to joint centres: the layout's detector offsets, or zero
  // (options.detectorOffsets false, or the tracker's own joints). Used by the camera fit.
  JointOffsetsMm detectorOffsetMm{};
  // The layout's sternum is the midpoint of its shoulders (BODY_25's neck is OpenPose's, COCO has
  // none): the camera fit compares it with the model's shoulders' midpoint, not its sternum,
  // which sits 41 mm ahead of it and 66 mm above on the default model's mean walker
  // (core/camera/detector_offsets.h). False with options.detectorOffsets off.
  bool sternumFromShoulders = false;
  std::array<bool, kJointCount> missing{};  // never seen: for the model to estimate
  std::array<double, kJointCount> seenShare{};  // share of the clip's frames the joint has
  std::vector<std::string> warnings;
  // The image the points were found in (a video's, --image-size, a MediaPipe file's), when
  // known: the camera fit then expects its principal point near the centre.
  std::optional<KeypointImageSize> imageSize;
  // Where the rate and the size came from, for reports: "given", "the file", "the video
  // (PATH)", or for the rate "assumed" ("" for a size not known).
  std::string rateSource = "assumed", imageSizeSource;
};

// Follows people across frames: a detection joins the track whose last centre is nearest,
// within half that person's size and 15 frames; else it starts a track.
std::vector<PersonTrack> trackPeople(const KeypointFrames& frames);

// The row of `person.jointsPx` for `frame`, or -1 when the person is not in that frame.
int personRowAt(const PersonTrack& person, int frame);

// Cleans what a reader gave. Throws Error(BadArgument) for an unknown --layout, a layout
// whose point count differs from the file's, or a --person out of range; Error(BadData)
// naming the file when no layout has the file's point count, or the person chosen never
// shows the minimum joints (pelvis or hips, knees, ankles) in any frame. A file naming its
// own points (DeepLabCut) takes its layout from layoutForPointNames (options.mappingFile).
KeypointTrial cleanKeypoints(const KeypointFrames& frames, const KeypointOptions& options = {});

// Counts again which joints the trial sees (seenShare, missing) after its points changed (lens
// distortion taken out, core/camera/lens_distortion.h); returns the names of those never seen.
std::vector<std::string> countSeenJoints(KeypointTrial& trial);
// Error(BadData) naming the trial's file when the walk's minimum joints (pelvis, knees,
// ankles) are among those `missing`; `why` says since when ("above confidence 0.30").
void requireWalkJoints(const KeypointTrial& trial, const std::string& why);

// Reads a keypoint file or folder (readKeypointFrames, cleanKeypoints), or a 2D TRC
// (readPlanarTrc).
KeypointTrial readKeypointTrial(const std::filesystem::path& path, const KeypointOptions& options = {});

// [SECTION] 2D TRC files (planar_trc.cpp) ----------------------------------------------------

// A .trc whose first rows place every point (X or Y not 0) in the plane Z = 0: a view of the
// walker, not a 3D walk (Sports2D writes its _px and _m files so). Sniffed from the first
// 64 KiB.
bool isPlanarTrc(const std::filesystem::path& path);

// Reads one as the image of the walker: the file's point names give the 15 joints as for a
// 3D TRC (the marker-set tables, or options.mappingFile), the plane's axis along which the
// head stands from the ankles is the vertical (flipped when it points up: image v is down),
// the other the horizontal (X to the right as the file has it). Coordinates in the file's
// unit as millimetres, except points over 100 m from the origin: pixels under "Units m" (Sports2D),
// read as pixels. A point at 0, 0 is absent. The rate is options.fps, else the file's.
// Format "TRC (2D)". Throws what the TRC reader and the mapping throw, and Error(BadData)
// naming the frame and point when a point leaves the plane.
KeypointTrial readPlanarTrc(const std::filesystem::path& path, const KeypointOptions& options = {});
// The same on a TRC already read (core/io/trc_reader.h).
KeypointTrial planarTrcTrial(const RawTrial& raw, const KeypointOptions& options = {});

// A trial from 15 joints already in METHOD §1 order (a joint tracker's output, one person):
// a point whose confidence is below options.minConfidence is missing, as in a file. `file`
// and `format` name the source in errors and captions; the rate is options.fps (required).
// Throws Error(BadData) naming `file` as cleanKeypoints does when the walk's minimum joints
// are never seen, Error(BadArgument) for a rate missing or out of bounds or sizes that differ.
KeypointTrial trialFromJoints(const Eigen::MatrixXd& jointsPx, const Eigen::MatrixXd& confidence,
                              const std::string& file, const std::string& format, const KeypointOptions& options);

}  // namespace ew

#pragma once
// Video (video_actions.cpp, video_poll.cpp): opening, marking keyframes, tracking, detecting, its
// playback.
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

// [SECTION] Video (ui/app/video.h, docs/VIEWER.md "Video")
// Opens a video in Mode::Clip (closing the video and clip shown before): its frames show in
// the 2D view. Error (std::invalid_argument with the file and reason) when it cannot be read.
void openVideo(AppState& s, const std::filesystem::path& path);
// Reads a keyframe file (core/tracking/keyframes.h) into the open video's keyframes (one
// edit: undo takes it back). Throws when no video is open or the file is bad.
void loadKeyframes(AppState& s, const std::filesystem::path& path);
void saveKeyframes(AppState& s, const std::filesystem::path& path);
// The open video's keyframes into `dir` (made when missing) as <video name>_keyframes.json,
// the name saveTrack gives them beside a track.
void saveKeyframesInto(AppState& s, const std::filesystem::path& dir);
// The open video's last track into `dir` (video/track_files.h: OpenPose JSON, the 2D CSV, the
// confidences) with the keyframes it was tracked from beside them (DIR/<video>_keyframes.json).
// Throws when there is no track or a file cannot be written.
void saveTrack(AppState& s, const std::filesystem::path& dir);
// The open video's next keyframe after the frame shown (delta > 0) or the one before it
// (delta < 0); -1 when there is none that way.
int neighbouringKeyframe(const AppState& s, int delta);
// The tracked frame that is no keyframe where the track's mean confidence over the joints is
// lowest: where to look first for joints that strayed (-1 when there is no track, or every
// tracked frame is a keyframe).
int leastSureTrackedFrame(const AppState& s);
// The frame to mark next, no keyframe: the one that, marked, leaves the least of the joints'
// motion between each tracked frame and its nearest keyframe (framesToMarkNext,
// core/tracking/track_confidence.h); -1 when there is no track or nothing moved.
int nextFrameToMark(const AppState& s);
// Where the viewer offers to save the open video's keyframes and track: <video name>_track.
std::filesystem::path defaultTrackFolder(const AppState& s);
// The video's 2D view magnified `zoom` times (clamped to 1-16; 1 shows the whole picture) with
// the video pixel `centrePx` (x right, y down; kept on the picture) at its middle.
void setVideoZoom(AppState& s, double zoom, const Eigen::Vector2d& centrePx);
// The frame shown (0-based, clamped to the video); pauses a tracked clip's playback there.
void setVideoFrame(AppState& s, int frame);
// Guided marking on the frame shown: clicks place the joint asked for, then the next.
void startMarking(AppState& s);
void stopMarking(AppState& s);
void skipMarkedJoint(AppState& s);  // the joint asked for is not visible: ask for the next
// Places (or moves) a joint on the frame shown, in video pixels (x right, y down). A frame
// that is no keyframe yet becomes one, starting from the track's confident joints there.
// `newEdit` false: part of the edit before (a drag), not a step of its own for undo.
void markJoint(AppState& s, Joint joint, double xPx, double yPx, bool newEdit = true);
// A joint dragged (markJoint) and let go: on a tracked video, while not marking, the track is
// redone from the keyframes as they now are (issue 14: "drag a joint on any frame, it becomes a
// keyframe and the track is redone around it"); on a detected one, the detections are fitted
// again with the keyframes as corrections (issue 52). True when tracking or the fit started.
bool letGoOfJoint(AppState& s);
// Marks the frame shown with a pose estimator's detections on that frame (a keypoint file or
// folder, core/keypoints: OpenPose, AlphaPose, MMPose, CSV; the file's first frame is the
// video's first): the joints it found, replacing what was marked there, as one edit. Throws,
// naming the file, when it does not read or has no joint on that frame.
void markFromKeypoints(AppState& s, const std::filesystem::path& keypoints);
void removeKeyframe(AppState& s, int frame);
void undoKeyframes(AppState& s);
void redoKeyframes(AppState& s);
// The frames to track, inclusive (0-based; last -1: the video's end).
void setTrackRange(AppState& s, int first, int last);
// Which tracker the next track uses (optical flow, or Zou et al.'s appearance tracker).
void setTracker(AppState& s, TrackerKind tracker);
// Whether the next optical-flow track flattens a fixed camera's still background first
// (video/static_background.h).
void setFlattenBackground(AppState& s, bool flatten);
// The next flow track holds the shoulders and hips to the trunk (TrackerOptions::holdTheTrunk).
void setHoldTheTrunk(AppState& s, bool hold);
// Rounds of the model loop the next flow track runs (0-10; std::invalid_argument outside).
void setModelLoopRounds(AppState& s, int rounds);
// The model a clip is fitted with, and the model loop guides a track with (throws when none).
std::shared_ptr<const EigenwalkerModel> modelForTracking(AppState& s);
// Tracks the range from the keyframes on a worker; when done the track is fitted as a clip.
void startTracking(AppState& s);
void cancelTracking(AppState& s);
void closeVideo(AppState& s);
// The video frame the 2D view shows: the fitted clip's playback frame (its track's or its
// detections'), else the scrubbed one.
int shownVideoFrame(const AppState& s);
// The clip shown is the fit of the open video's last track.
bool showsTrackFit(const AppState& s);
// The clip shown is the fit of the open video's last detection.
bool showsDetectionFit(const AppState& s);
// Either: the open video's footage goes under the clip's fit.
bool showsVideoFit(const AppState& s);
// The video frames [first, last] the fitted clip covers (showsVideoFit), else nullopt.
std::optional<std::pair<int, int>> videoFitFrames(const AppState& s);

// [SECTION] Detecting the walker (ui/app/detection.h, docs/VIEWER.md "Detecting the walker")
// Finds the people in the open video with the built-in detector on a worker, through the
// detection cache; the 2D view draws each frame's people as they are found. When done, the
// walker's keypoints are fitted as a keypoint clip with the video (the fit over its footage);
// a video with nobody in it is reported. Throws std::invalid_argument when no video is open, a
// detection or a track is running, or the models are missing (missingPoseModelAdvice()).
void startDetection(AppState& s);
void cancelDetection(AppState& s);
// Which BlazePose landmark model the next detection uses (lite, full, heavy).
void setDetectorModel(AppState& s, PoseModelSize model);
// The last detection's keypoints fitted again as the clip (after a track took its place), the
// video's keyframes as corrections of them (ClipSettings::corrections).
void fitDetections(AppState& s);
// The open video's keyframes are corrections of its detections (issue 52: "marking and
// tracking become correction"): people were detected and no track replaced them. Then each
// edit of the keyframes outside guided marking (a joint let go, undo, redo, a keyframe
// removed or read, marking done) fits the detections again with them.
bool correctsDetections(const AppState& s);
// The open video's people found on `frame`: the running detection's, else the last one's.
std::vector<KeypointDetection> detectionsOn(const AppState& s, int frame);
// Whether a video opened alone (no keyframe file with it) is handed to the detector.
void setDetectWhenVideoOpens(AppState& s, bool detect);
// One frame on (delta > 0) or back, of what the views show: the video's own frames while its
// joints are marked or before it is tracked, the clip's frames (round its ends, as playback
// loops), else 1/60 s of the synthesised walker's cycle. Pauses a clip or video.
void stepFrame(AppState& s, int delta);
// True while the transport plays and steps the open video's own frames: its joints are being
// marked, or it has no track yet.
bool stepsVideoFrames(const AppState& s);
// Playback moves on by `seconds` × its speed: the video's own frames at its frame rate
// (stepsVideoFrames; round its end, as a walker's cycle loops), else the walker's cycle.
void advancePlayback(AppState& s, double seconds);
// The time one stepFrame moves, in seconds.
double frameStepS(const AppState& s);

}  // namespace ew::ui::actions

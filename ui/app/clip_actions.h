#pragma once
// Keypoint clips (clip_actions.cpp): opening one, the fit's settings, its frames.
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <filesystem>
#include <memory>
#include <optional>
#include <string>

#include <Eigen/Core>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

// [SECTION] Keypoint clips (ui/app/clip.h, docs/VIEWER.md "Keypoint clips")
// True for what openClip takes: an OpenPose folder, a keypoint JSON, a MediaPipe / DLC CSV.
bool isKeypointClip(const std::filesystem::path& path);
// Opens a pose estimator's clip in Mode::Clip; its camera fit runs in the background. A clip
// that cannot be read or fitted is reported as a failed open, and what was shown stays.
void openClip(AppState& s, const std::filesystem::path& path);
// The clip fit's choices, each refitting in the background; nullopt / "" / 0 / -1: estimated,
// guessed, the file's or 30 fps, the walker. Throw std::invalid_argument for values out of range.
void setClipFocal(AppState& s, std::optional<double> focalPx);
void setClipAzimuth(AppState& s, std::optional<double> alphaDeg);
void setClipElevation(AppState& s, std::optional<double> elevationDeg);
// Whether the fit holds its camera's height to the scene's horizon read off the clip's video
// (ClipSettings::holdToHorizon: a detection's does, a track's does not unless asked). Throws
// std::invalid_argument when no horizon was read for the clip.
void setClipHoldToHorizon(AppState& s, bool hold);
void setClipLayout(AppState& s, const std::string& layout);
void setClipFps(AppState& s, double fps);
void setClipPerson(AppState& s, int person);
// The image's size in pixels (nullopt: the file's, else the video's beside it); a clip whose
// points are fractions of the image opens without one and waits for it.
void setClipImageSize(AppState& s, std::optional<KeypointImageSize> size);
// A calibration file (Pose2Sim's Calib_*.toml, docs/CAMERA.md) for the clip's camera: its focal
// length, principal point and lens distortion, resolved as `reconstruct --camera` resolves it
// (core/camera/camera_knowledge.h). `camera` names one of the file's cameras; "" takes its
// only one, or the one whose name the clip's folder or file carries (cam_01 for cam01_json).
// A focal length held before gives way to the calibration's, as a focal length typed after
// clears the calibration. An empty `file` clears it. Throws std::invalid_argument naming the
// file and the problem (unreadable, several cameras and none chosen, not a camera's focal).
void setClipCalibration(AppState& s, const std::filesystem::path& file, const std::string& camera);
// A Pose2Sim-style calibration (.toml), what setClipCalibration takes.
bool isCalibrationFile(const std::filesystem::path& path);
void closeClip(AppState& s);
// Shows the clip's frame `frame` (from 1, as the 2D view's caption counts) and pauses.
void setClipFrame(AppState& s, int frame);
// The clip's 2D view magnified `zoom` times (clamped to 1-16, as a video's; 1 shows the region
// the walker crosses) with the image pixel `centrePx` (x right, y down) at its middle.
void setClipZoom(AppState& s, double zoom, const Eigen::Vector2d& centrePx);

}  // namespace ew::ui::actions

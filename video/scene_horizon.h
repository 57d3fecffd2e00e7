#pragma once
// The horizon of a fixed camera's footage, read from the scene's own straight lines: the
// sloped rows of a facade's windows, a wall's courses, a floor's tiles run to a vanishing point
// on the horizon. A check on the camera fit's height over the walker (its view elevation),
// which a walker 10 m away barely shows (docs/CAMERA.md, "The scene's horizon").
//
// Each sampled frame's line segments (OpenCV's LSD) sloped 3–30° from the image's rows vote
// for the point most of their length runs to (RANSAC over pairs, seeded, so the answer is the
// same every run); the frames' points are then taken together. The horizon of a level camera
// (no roll, as the camera fit's) is the row of that point. Lines that are not level in the
// world (stairs, a ramp, a pitched roof) would point elsewhere: the reading is reported and
// compared, never fed to the fit.
#include <filesystem>
#include <optional>
#include <string>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace ew {

// One frame's vote: the point its sloped segments run to, and how much of their length does.
struct VanishingVote {
  Eigen::Vector2d pointPx = Eigen::Vector2d::Zero();
  int segments = 0;          // sloped segments that run to it (within 1°)
  double supportPx = 0.0;    // their summed length
};

// The frame's vote (8-bit grey or BGR), unset when too few of its sloped segments agree on a
// point: under kMinVanishingSegments, or less length than kMinVanishingSupport of the
// image's longer side.
std::optional<VanishingVote> vanishingVoteOf(const cv::Mat& frame);
inline constexpr int kMinVanishingSegments = 8;
inline constexpr double kMinVanishingSupport = 0.75;

struct SceneHorizon {
  Eigen::Vector2d vanishingPointPx = Eigen::Vector2d::Zero();  // median of the frames' points
  double rowPx = 0.0;        // the horizon's row for a level camera: the point's
  double rowSpreadPx = 0.0;  // median absolute deviation of the frames' rows
  int framesRead = 0, framesAgreeing = 0;
};

// `frames` frames spread over `video`, read as above. Unset, with the reason in `why`, when
// fewer than half of them vote, or their rows spread more than kMaxHorizonSpread of the
// image's height (no steady family of level lines: a park, a plain wall, a moving camera). A
// stream that ends before its container said is read as far as it goes. Throws what
// VideoSource's constructor throws for a file it cannot open.
std::optional<SceneHorizon> sceneHorizonOf(const std::filesystem::path& video, int frames, std::string& why);
// The frames `reconstruct` and the viewer read a video's horizon on.
inline constexpr int kSceneHorizonFrames = 12;
inline constexpr double kMaxHorizonSpread = 0.02;

}  // namespace ew

#include "video/scene_horizon.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/imgproc.hpp>

#include "core/common/errors.h"
#include "core/common/statistics.h"
#include "video/video_source.h"

namespace ew {
namespace {

struct Segment {
  Eigen::Vector2d a, b;
  double length = 0.0;
};

// A segment counts when it is this long (share of the image's longer side), sloped at least
// kMinSlopeDeg (a level line seen square on runs to a point at infinity and says nothing of the
// horizon's height) and at most kMaxSlopeDeg (steeper: verticals, limbs).
constexpr double kMinSegmentShare = 0.022;
constexpr double kMinSlopeDeg = 3.0, kMaxSlopeDeg = 30.0;
// A segment runs to a point when its direction is within this of the direction to it.
constexpr double kRunsToDeg = 1.0;
constexpr int kRansacPairs = 3000;
// Farther than this many image sizes away a point is as good as at infinity: no horizon row.
constexpr double kMaxPointDistance = 12.0;

std::vector<Segment> slopedSegments(const cv::Mat& grey) {
  std::vector<cv::Vec4f> lines;
  cv::createLineSegmentDetector(cv::LSD_REFINE_STD)->detect(grey, lines);
  const double minLength = kMinSegmentShare * std::max(grey.cols, grey.rows);
  std::vector<Segment> out;
  for (const cv::Vec4f& l : lines) {
    const Eigen::Vector2d a(l[0], l[1]), b(l[2], l[3]);
    const Eigen::Vector2d d = b - a;
    const double slopeDeg = std::atan2(std::abs(d.y()), std::abs(d.x())) * 180.0 / std::numbers::pi;
    if (d.norm() >= minLength && slopeDeg >= kMinSlopeDeg && slopeDeg <= kMaxSlopeDeg) out.push_back({a, b, d.norm()});
  }
  return out;
}

// Called for every segment of every RANSAC pair: the tolerance's cosine is worked out once.
bool runsTo(const Segment& s, const Eigen::Vector2d& point) {
  static const double minCos = std::cos(kRunsToDeg * std::numbers::pi / 180.0);
  const Eigen::Vector2d d = s.b - s.a, t = point - 0.5 * (s.a + s.b);
  return std::abs(d.dot(t)) / (d.norm() * t.norm() + 1e-12) >= minCos;
}

// The point two segments' lines cross at, unset for parallel lines.
std::optional<Eigen::Vector2d> crossing(const Segment& p, const Segment& q) {
  const Eigen::Vector3d lp = Eigen::Vector3d(p.a.x(), p.a.y(), 1).cross(Eigen::Vector3d(p.b.x(), p.b.y(), 1));
  const Eigen::Vector3d lq = Eigen::Vector3d(q.a.x(), q.a.y(), 1).cross(Eigen::Vector3d(q.b.x(), q.b.y(), 1));
  const Eigen::Vector3d x = lp.cross(lq);
  if (std::abs(x.z()) < 1e-9) return std::nullopt;
  return Eigen::Vector2d(x.x() / x.z(), x.y() / x.z());
}

}  // namespace

// Segments are found on the frame shrunk to this longer side at most (LSD's time goes with the
// pixels; a facade's rows stay tens of pixels long) and scaled back.
constexpr int kMaxSegmentSearchSidePx = 1280;

std::optional<VanishingVote> vanishingVoteOf(const cv::Mat& frame) {
  cv::Mat grey;
  if (frame.channels() == 3) cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
  else grey = frame;
  const double shrink = std::min(1.0, kMaxSegmentSearchSidePx / static_cast<double>(std::max(grey.cols, grey.rows)));
  cv::Mat small = grey;
  if (shrink < 1.0) cv::resize(grey, small, cv::Size(), shrink, shrink, cv::INTER_AREA);
  std::vector<Segment> segments = slopedSegments(small);
  for (Segment& s : segments) s.a /= shrink, s.b /= shrink, s.length /= shrink;
  if (segments.size() < static_cast<std::size_t>(kMinVanishingSegments)) return std::nullopt;
  const double size = std::max(grey.cols, grey.rows);
  const Eigen::Vector2d centre(0.5 * grey.cols, 0.5 * grey.rows);
  std::mt19937 random(1);
  std::uniform_int_distribution<std::size_t> pick(0, segments.size() - 1);
  VanishingVote best;
  for (int i = 0; i < kRansacPairs; ++i) {
    const std::optional<Eigen::Vector2d> point = crossing(segments[pick(random)], segments[pick(random)]);
    if (!point || (*point - centre).norm() > kMaxPointDistance * size) continue;
    VanishingVote vote{*point, 0, 0.0};
    for (const Segment& s : segments)
      if (runsTo(s, *point)) ++vote.segments, vote.supportPx += s.length;
    if (vote.supportPx > best.supportPx) best = vote;
  }
  if (best.segments < kMinVanishingSegments || best.supportPx < kMinVanishingSupport * size) return std::nullopt;
  return best;
}

std::optional<SceneHorizon> sceneHorizonOf(const std::filesystem::path& video, int frames, std::string& why) {
  VideoSource source(video);
  const int count = source.info().frameCount;
  SceneHorizon h;
  std::vector<double> xs, ys;
  for (int i = 0; i < frames && count > 0; ++i) {
    const int index = static_cast<int>((static_cast<long long>(2 * i + 1) * count) / (2LL * frames));
    cv::Mat frame;
    try {
      frame = source.frame(index);
    } catch (const Error&) {
      break;  // the stream ends before its container said: the frames read so far decide
    }
    ++h.framesRead;
    if (const auto vote = vanishingVoteOf(frame)) xs.push_back(vote->pointPx.x()), ys.push_back(vote->pointPx.y());
  }
  if (2 * ys.size() < static_cast<std::size_t>(std::max(h.framesRead, 1))) {
    why = std::to_string(ys.size()) + " of " + std::to_string(h.framesRead) +
          " frames show sloped level lines running to one point (a facade's rows, a floor's tiles)";
    return std::nullopt;
  }
  h.vanishingPointPx = {median(xs), median(ys)};
  h.rowPx = h.vanishingPointPx.y();
  std::vector<double> deviations;
  for (double y : ys) deviations.push_back(std::abs(y - h.rowPx));
  h.rowSpreadPx = median(deviations);
  h.framesAgreeing = static_cast<int>(ys.size());
  if (h.rowSpreadPx > kMaxHorizonSpread * source.info().heightPx) {
    why = "the frames' vanishing points spread " + std::to_string(static_cast<int>(std::lround(h.rowSpreadPx))) +
          " px in height (a moving camera, or no one family of level lines)";
    return std::nullopt;
  }
  return h;
}

}  // namespace ew

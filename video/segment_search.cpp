#include "video/segment_search.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace ew {
namespace {

constexpr int kStripAlong = 20;
constexpr int kStripAcross = 7;

float sampleBilinear(const cv::Mat& grey, float x, float y) {
  const int x0 = static_cast<int>(std::floor(x)), y0 = static_cast<int>(std::floor(y));
  const float fx = x - static_cast<float>(x0), fy = y - static_cast<float>(y0);
  const unsigned char* r0 = grey.ptr<unsigned char>(y0);
  const unsigned char* r1 = grey.ptr<unsigned char>(y0 + 1);
  return (1 - fy) * ((1 - fx) * r0[x0] + fx * r0[x0 + 1]) +
         fy * ((1 - fx) * r1[x0] + fx * r1[x0 + 1]);
}

// Where a joint is placed, and its strip's match there.
struct Placement {
  cv::Point2f at;
  double match = -1.0;
};

// Zou et al.'s search region A (eq. 18) as a sector around the parent: the bone's angle
// within ±kAngleRangeDeg of where the prediction points (a shank swings up to ~15° a frame
// at 30 fps) and its image length 75-115 % of the predicted one (foreshortening), first on
// a coarse grid (1.5°, 2 % of the length), then finer around the best.
constexpr double kAngleRangeDeg = 40.0;

Placement placeChild(const cv::Mat& grey, cv::Point2f parent, cv::Point2f start,
                     const SegmentStrip& reference, const SearchBone& bone,
                     const SegmentSearchOptions& o) {
  Placement best{start, stripMatch(segmentStrip(grey, parent, start, bone, o.personPx), reference)};
  const cv::Point2f d = start - parent;
  const double length = std::hypot(d.x, d.y);
  if (length < 2.0) return best;
  const double angle = std::atan2(d.y, d.x);
  const auto sweep = [&](double angle0, double angleRange, double angleStep, double lengthLo,
                         double lengthHi, double lengthStep) {
    Placement found = best;
    for (double a = angle0 - angleRange; a <= angle0 + angleRange + 1e-9; a += angleStep)
      for (double l = lengthLo; l <= lengthHi + 1e-9; l += lengthStep) {
        const cv::Point2f c = parent + cv::Point2f(static_cast<float>(l * std::cos(a)),
                                                   static_cast<float>(l * std::sin(a)));
        const double m = stripMatch(segmentStrip(grey, parent, c, bone, o.personPx), reference);
        if (m > found.match) found = {c, m};
      }
    best = found;
  };
  constexpr double kDeg = 3.14159265358979323846 / 180.0;
  const double lengthStep = std::max(1.0, 0.02 * length);
  sweep(angle, kAngleRangeDeg * kDeg, 1.5 * kDeg, 0.75 * length, 1.15 * length, lengthStep);
  const cv::Point2f e = best.at - parent;
  const double bestLength = std::hypot(e.x, e.y), bestAngle = std::atan2(e.y, e.x);
  const double fineAngle = std::min(0.4 * kDeg, 0.5 / std::max(bestLength, 1.0));
  sweep(bestAngle, 1.5 * kDeg, fineAngle, bestLength - lengthStep, bestLength + lengthStep, 0.5);
  return best;
}

// The pelvis with the trunk: pelvis and sternum moved together, the trunk strip compared,
// in a square `radiusPx` around the prediction on a 2 px grid, then 0.5 px around the best.
Placement placeRoot(const cv::Mat& grey, cv::Point2f pelvis, cv::Point2f sternum,
                    const SegmentStrip& trunk, const SearchBone& bone,
                    const SegmentSearchOptions& o) {
  Placement best{pelvis, -2.0};
  for (float step : {2.0f, 0.5f}) {
    const cv::Point2f centre = best.match > -2.0 ? best.at : pelvis;
    const float radius = step > 1.0f ? static_cast<float>(o.radiusPx) : 1.5f;
    for (float dy = -radius; dy <= radius + 1e-3f; dy += step)
      for (float dx = -radius; dx <= radius + 1e-3f; dx += step) {
        const cv::Point2f shift = centre - pelvis + cv::Point2f(dx, dy);
        const double m = stripMatch(
            segmentStrip(grey, pelvis + shift, sternum + shift, bone, o.personPx), trunk);
        if (m > best.match) best = {pelvis + shift, m};
      }
  }
  return best;
}

}  // namespace

// Half-widths: a forearm or shank is about 5 % of the body height across, the upper arm
// and thigh 6-7 %, the trunk about 18 % (Drillis & Contini's proportions, rounded down so
// the strip stays on the segment).
SearchResult::SearchResult() {
  at.fill(cv::Point2f(kNaNf, kNaNf));
  match.fill(-1.0);
}

const std::array<SearchBone, kBones.size()> kSearchTree = {{
    {Joint::Pelvis, Joint::Sternum, 0.07, 0.0},
    {Joint::Sternum, Joint::Head, 0.04, 0.5},
    {Joint::Sternum, Joint::RShoulder, 0.025, 0.0},
    {Joint::RShoulder, Joint::RElbow, 0.025, 0.0},
    {Joint::RElbow, Joint::RWrist, 0.02, 0.3},
    {Joint::Sternum, Joint::LShoulder, 0.025, 0.0},
    {Joint::LShoulder, Joint::LElbow, 0.025, 0.0},
    {Joint::LElbow, Joint::LWrist, 0.02, 0.3},
    {Joint::Pelvis, Joint::RHip, 0.03, 0.0},
    {Joint::RHip, Joint::RKnee, 0.03, 0.0},
    {Joint::RKnee, Joint::RAnkle, 0.022, 0.2},
    {Joint::Pelvis, Joint::LHip, 0.03, 0.0},
    {Joint::LHip, Joint::LKnee, 0.03, 0.0},
    {Joint::LKnee, Joint::LAnkle, 0.022, 0.2},
}};

SegmentStrip segmentStrip(const cv::Mat& grey, cv::Point2f parent, cv::Point2f child,
                          const SearchBone& bone, double personPx) {
  const cv::Point2f along = child - parent;
  const float length = std::hypot(along.x, along.y);
  if (!(length > 1.0f)) return {};
  const cv::Point2f u = along / length;
  const cv::Point2f n(-u.y, u.x);
  const float reach = length * static_cast<float>(1.0 + bone.beyondShare);
  const float halfWidth = static_cast<float>(std::max(2.0, bone.halfWidthShare * personPx));
  cv::Mat strip(kStripAlong, kStripAcross, CV_32F);
  double sum = 0.0;
  for (int i = 0; i < kStripAlong; ++i) {
    const float s = reach * (static_cast<float>(i) + 0.5f) / kStripAlong;
    for (int k = 0; k < kStripAcross; ++k) {
      const float t = halfWidth * (2.0f * (static_cast<float>(k) + 0.5f) / kStripAcross - 1.0f);
      const cv::Point2f p = parent + u * s + n * t;
      if (p.x < 0.0f || p.y < 0.0f || p.x >= static_cast<float>(grey.cols - 1) ||
          p.y >= static_cast<float>(grey.rows - 1))
        return {};
      const float v = sampleBilinear(grey, p.x, p.y);
      strip.at<float>(i, k) = v;
      sum += v;
    }
  }
  strip -= static_cast<float>(sum / static_cast<double>(strip.total()));
  const double norm = cv::norm(strip);
  if (norm < 1e-3) return {};
  strip /= static_cast<float>(norm);
  return strip;
}

double stripMatch(const SegmentStrip& a, const SegmentStrip& b) {
  if (a.empty() || b.empty()) return -1.0;
  return a.dot(b);
}

SearchResult searchSegments(const cv::Mat& grey,
                            const std::array<cv::Point2f, kJointCount>& predicted,
                            const std::array<SegmentStrip, kBones.size()>& strips,
                            const SegmentSearchOptions& o) {
  SearchResult r;
  const int pelvis = index(Joint::Pelvis), sternum = index(Joint::Sternum);
  if (valid(predicted[pelvis])) {
    r.at[pelvis] = predicted[pelvis];
    if (valid(predicted[sternum]) && !strips[0].empty()) {
      const Placement root =
          placeRoot(grey, predicted[pelvis], predicted[sternum], strips[0], kSearchTree[0], o);
      r.at[pelvis] = root.at;
      r.match[pelvis] = root.match;
    }
  }
  for (std::size_t b = 0; b < kSearchTree.size(); ++b) {
    const SearchBone& bone = kSearchTree[b];
    const int parent = index(bone.parent), child = index(bone.child);
    if (!valid(predicted[child])) continue;
    // The root moved the trunk: its child starts shifted with it.
    cv::Point2f start = predicted[child];
    if (b == 0 && valid(r.at[pelvis])) start += r.at[pelvis] - predicted[pelvis];
    if (!valid(r.at[parent]) || strips[b].empty()) {
      r.at[child] = start;
      continue;
    }
    const Placement p = placeChild(grey, r.at[parent], start, strips[b], bone, o);
    r.at[child] = p.at;
    r.match[child] = p.match;
  }
  return r;
}

}  // namespace ew

#include "video/appearance_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

namespace ew {
namespace {

bool inside(cv::Point2f p, const cv::Mat& image) {
  return p.x >= 0.0f && p.y >= 0.0f && p.x < static_cast<float>(image.cols) &&
         p.y < static_cast<float>(image.rows);
}

int binOf(const cv::Vec3b& c) {
  constexpr int shift = 5;  // 256 / kColourLevels = 32
  return ((c[0] >> shift) * kColourLevels + (c[1] >> shift)) * kColourLevels + (c[2] >> shift);
}

// The parent of each joint in the search tree (−1 for the root and for joints not in it).
std::array<int, kJointCount> treeParents() {
  std::array<int, kJointCount> parent;
  parent.fill(-1);
  for (const SearchBone& b : kSearchTree) parent[index(b.child)] = index(b.parent);
  return parent;
}

// The best of a set of candidates: the lowest Bhattacharyya distance.
struct Candidate {
  cv::Point2f at{kNaNf, kNaNf};
  double distance = 2.0;
};

class AppearancePass final : public TrackingPass {
 public:
  AppearancePass(const Keyframe& key, const cv::Mat& keyBgr, const AppearanceOptions& o)
      : o_(o), parent_(treeParents()) {
    for (int j = 0; j < kJointCount; ++j) {
      const cv::Point2f p(static_cast<float>(key.jointsPx(2 * j)),
                          static_cast<float>(key.jointsPx(2 * j + 1)));
      now_[j] = before_[j] = p;
      active_[j] = valid(p);
    }
    for (std::size_t b = 0; b < kSearchTree.size(); ++b) {
      const int parent = index(kSearchTree[b].parent), child = index(kSearchTree[b].child);
      if (active_[parent] && active_[child])
        reference_[b] = segmentHistogram(keyBgr, now_[parent], now_[child], kSearchTree[b], o_.personPx);
    }
    const int side = patchSide();
    for (int j = 0; j < kJointCount; ++j)
      if (active_[j] && (parent_[j] < 0 || !active_[parent_[j]]))
        cv::getRectSubPix(keyBgr, cv::Size(side, side), now_[j], templates_[j]);
  }

  bool tracks(int j) const override { return active_[j]; }
  cv::Point2f position(int j) const override { return now_[j]; }

  std::array<double, kJointCount> advance(const cv::Mat& bgr, int /*frame*/) override {
    std::array<double, kJointCount> confidence{};
    std::array<cv::Point2f, kJointCount> next = now_;
    std::array<bool, kJointCount> placed{};
    for (int j = 0; j < kJointCount; ++j)
      if (active_[j] && !templates_[j].empty()) {
        confidence[j] = placeByTemplate(j, bgr, next[j]);
        placed[j] = true;
      }
    for (std::size_t b = 0; b < kSearchTree.size(); ++b) {
      const int parent = index(kSearchTree[b].parent), child = index(kSearchTree[b].child);
      if (!active_[child] || placed[child] || !placed[parent]) continue;
      // Eq. 18's centre: the segment at last frame's angle, hung from its parent's new place.
      const cv::Point2f centre = next[parent] + (now_[child] - now_[parent]);
      const Candidate c = searchChild(bgr, next[parent], centre, searchHalfSide(child), b);
      next[child] = valid(c.at) ? c.at : centre;
      confidence[child] = std::clamp(1.0 - c.distance, 0.0, 1.0);
      placed[child] = true;
    }
    for (int j = 0; j < kJointCount; ++j) {
      if (!active_[j]) continue;
      before_[j] = now_[j];
      now_[j] = next[j];
      // A joint that left the picture is lost for the rest of this pass, not extrapolated.
      if (!placed[j] || !inside(now_[j], bgr)) active_[j] = false;
    }
    return confidence;
  }

 private:
  int patchSide() const {
    const int side = std::max(9, static_cast<int>(std::lround(o_.rootPatchShare * o_.personPx)));
    return side % 2 == 0 ? side + 1 : side;
  }

  // Eq. 18: h = 1.5 × the joint's larger coordinate move over the last frame, within the
  // options' floor and ceiling.
  int searchHalfSide(int j) const {
    const cv::Point2f d = now_[j] - before_[j];
    const double h = 1.5 * std::max(std::abs(d.x), std::abs(d.y));
    return static_cast<int>(std::lround(std::clamp(h, std::max(2.0, o_.minSearchShare * o_.personPx),
                                                   std::max(3.0, o_.maxSearchShare * o_.personPx))));
  }

  // The root (and any joint without a marked parent): its keyframe patch sought in the
  // square A around its last place, placed to a fraction of a pixel by a parabola through
  // the scores around the best. Its normalised correlation is the confidence.
  double placeByTemplate(int j, const cv::Mat& bgr, cv::Point2f& at) const {
    const int h = searchHalfSide(j);
    const int side = templates_[j].cols + 2 * h;
    cv::Mat region, scores;
    cv::getRectSubPix(bgr, cv::Size(side, side), now_[j], region);
    cv::matchTemplate(region, templates_[j], scores, cv::TM_CCOEFF_NORMED);
    double best = 0.0;
    cv::Point at0;
    cv::minMaxLoc(scores, nullptr, &best, nullptr, &at0);
    const auto offset = [&](float left, float centre, float right) {
      const float curvature = left - 2.0f * centre + right;
      return std::abs(curvature) > 1e-6f ? std::clamp(0.5f * (left - right) / curvature, -0.5f, 0.5f) : 0.0f;
    };
    float dx = 0.0f, dy = 0.0f;
    if (at0.x > 0 && at0.x + 1 < scores.cols)
      dx = offset(scores.at<float>(at0.y, at0.x - 1), scores.at<float>(at0.y, at0.x), scores.at<float>(at0.y, at0.x + 1));
    if (at0.y > 0 && at0.y + 1 < scores.rows)
      dy = offset(scores.at<float>(at0.y - 1, at0.x), scores.at<float>(at0.y, at0.x), scores.at<float>(at0.y + 1, at0.x));
    at = now_[j] + cv::Point2f(static_cast<float>(at0.x - h) + dx, static_cast<float>(at0.y - h) + dy);
    return std::clamp(best, 0.0, 1.0);
  }

  // Eq. 17 over the square A: a grid of about 13 × 13 candidates, then every pixel around
  // the best of them.
  Candidate searchChild(const cv::Mat& bgr, cv::Point2f parent, cv::Point2f centre, int h,
                        std::size_t bone) const {
    Candidate best;
    if (!hasReference(bone)) return best;
    const int step = std::max(1, (h + 5) / 6);
    const auto sweep = [&](cv::Point2f around, int reach, int stride) {
      Candidate found = best;
      for (int dy = -reach; dy <= reach; dy += stride)
        for (int dx = -reach; dx <= reach; dx += stride) {
          const cv::Point2f c = around + cv::Point2f(static_cast<float>(dx), static_cast<float>(dy));
          const double d = bhattacharyyaDistance(
              reference_[bone], segmentHistogram(bgr, parent, c, kSearchTree[bone], o_.personPx));
          if (d < found.distance) found = {c, d};
        }
      best = found;
    };
    sweep(centre, h, step);
    if (step > 1 && valid(best.at)) sweep(best.at, step - 1, 1);
    return best;
  }

  bool hasReference(std::size_t bone) const {
    const auto& r = reference_[bone];
    return std::any_of(r.begin(), r.end(), [](float v) { return v > 0.0f; });
  }

  AppearanceOptions o_;
  std::array<int, kJointCount> parent_;
  std::array<cv::Point2f, kJointCount> now_{}, before_{};
  std::array<bool, kJointCount> active_{};
  std::array<ColourHistogram, kSearchTree.size()> reference_{};
  std::array<cv::Mat, kJointCount> templates_{};
};

}  // namespace

ColourHistogram segmentHistogram(const cv::Mat& bgr, cv::Point2f parent, cv::Point2f child,
                                 const SearchBone& bone, double personPx) {
  ColourHistogram h{};
  const cv::Point2f along = child - parent;
  const float length = std::hypot(along.x, along.y);
  if (!(length >= 1.0f) || bgr.type() != CV_8UC3) return h;
  const cv::Point2f u = along / length, n(-u.y, u.x);
  const float reach = length * static_cast<float>(1.0 + bone.beyondShare);
  const float halfWidth = static_cast<float>(std::max(2.0, bone.halfWidthShare * personPx));
  // About a sample per pixel, at most 48 along and 12 across: enough for 512 bins over a
  // segment's few colours, and a bounded cost per candidate.
  const int nAlong = std::clamp(static_cast<int>(reach), 4, 48);
  const int nAcross = std::clamp(static_cast<int>(2.0f * halfWidth), 3, 12);
  int counted = 0;
  for (int i = 0; i < nAlong; ++i) {
    const float s = reach * (static_cast<float>(i) + 0.5f) / static_cast<float>(nAlong);
    for (int k = 0; k < nAcross; ++k) {
      const float t = halfWidth * (2.0f * (static_cast<float>(k) + 0.5f) / static_cast<float>(nAcross) - 1.0f);
      const cv::Point2f p = parent + u * s + n * t;
      const int x = static_cast<int>(std::floor(p.x)), y = static_cast<int>(std::floor(p.y));
      if (x < 0 || y < 0 || x >= bgr.cols || y >= bgr.rows) continue;
      h[static_cast<std::size_t>(binOf(bgr.at<cv::Vec3b>(y, x)))] += 1.0f;
      ++counted;
    }
  }
  if (2 * counted < nAlong * nAcross) return ColourHistogram{};
  for (float& v : h) v /= static_cast<float>(counted);
  return h;
}

double bhattacharyyaDistance(const ColourHistogram& a, const ColourHistogram& b) {
  double overlap = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) overlap += std::sqrt(static_cast<double>(a[i]) * b[i]);
  return std::sqrt(std::max(0.0, 1.0 - std::min(1.0, overlap)));
}

std::unique_ptr<TrackingPass> makeAppearancePass(const Keyframe& key, const cv::Mat& keyBgr,
                                                 const AppearanceOptions& options) {
  return std::make_unique<AppearancePass>(key, keyBgr, options);
}

}  // namespace ew

#include "video/joint_tracker.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <map>
#include <memory>
#include <opencv2/imgproc.hpp>
#include <opencv2/video/tracking.hpp>
#include <optional>

#include "core/common/errors.h"
#include "core/common/nan.h"
#include "core/common/skeleton.h"
#include "video/appearance_tracker.h"
#include "video/segment_search.h"
#include "video/static_background.h"

namespace ew {
namespace {

// [SECTION] The body's tree (video/segment_search.h): the pelvis, then each child after its parent

std::array<int, kJointCount> parentsFirst() {
  std::array<int, kJointCount> order{};
  order[0] = index(kSearchTree[0].parent);
  for (std::size_t b = 0; b < kSearchTree.size(); ++b) order[b + 1] = index(kSearchTree[b].child);
  return order;
}

// The joints TrackerOptions::holdTheTrunk holds to the pelvis→sternum line. Not the head: on
// cam01 its own flow was nearer OpenPose's (26 px median) than the trunk's place for it (37 px).
bool heldWithTheTrunk(int j) {
  return j == index(Joint::RShoulder) || j == index(Joint::LShoulder) ||
         j == index(Joint::RHip) || j == index(Joint::LHip);
}

// [SECTION] Sizes from the person's height in the image ---------------------------------

struct Geometry {
  double personPx = 0.0;
  int windowPx = 21, patchPx = 21, searchPx = 20;
  double forwardBackwardLimitPx = 1.0;
};

int oddClamp(double value, int lo, int hi) {
  int v = std::clamp(static_cast<int>(std::lround(value)), lo, hi);
  return v % 2 == 0 ? v + 1 : v;
}

}  // namespace

double personHeightPx(const Keyframes& keys, int frameHeightPx) {
  for (const Keyframe& k : keys.keyframes) {
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    int seen = 0;
    for (int j = 0; j < kJointCount; ++j) {
      const double y = k.jointsPx(2 * j + 1);
      if (std::isnan(y)) continue;
      lo = std::min(lo, y);
      hi = std::max(hi, y);
      ++seen;
    }
    if (seen >= 2 && hi - lo > 8.0) return hi - lo;
  }
  return frameHeightPx / 3.0;
}

namespace {

Geometry geometryFor(double personPx, const TrackerOptions& o) {
  Geometry g;
  g.personPx = personPx;
  g.windowPx = oddClamp(personPx * o.windowShare, 9, 61);
  g.patchPx = oddClamp(personPx * o.patchShare, 9, 81);
  g.searchPx = std::clamp(static_cast<int>(std::lround(personPx * o.searchShare)), 6, 120);
  // Sub-pixel flow on textured clothing comes back within a pixel; a bigger forward–
  // backward disagreement means the window slid onto something else (the other leg).
  g.forwardBackwardLimitPx = std::max(1.0, 0.01 * personPx);
  return g;
}

// [SECTION] One joint's constant-velocity Kalman filter (state x, y, vx, vy; px, px/frame) ---

struct JointFilter {
  Eigen::Vector4d state = Eigen::Vector4d::Zero();
  Eigen::Matrix4d covariance = Eigen::Matrix4d::Identity();
  bool active = false;

  void start(double x, double y) {
    state << x, y, 0.0, 0.0;
    covariance = Eigen::Vector4d(1.0, 1.0, 100.0, 100.0).asDiagonal();
    active = true;
  }
  // Limbs accelerate hard (a foot leaving the ground): the process noise lets the velocity
  // change by about a hundredth of the body height per frame.
  void predict(double accelerationPx) {
    Eigen::Matrix4d f = Eigen::Matrix4d::Identity();
    f(0, 2) = f(1, 3) = 1.0;
    state = f * state;
    const double q = accelerationPx * accelerationPx;
    const Eigen::Vector4d noise(0.25 * q, 0.25 * q, q, q);
    covariance = f * covariance * f.transpose() + Eigen::Matrix4d(noise.asDiagonal());
  }
  void update(double x, double y, double sigmaPx) {
    Eigen::Matrix<double, 2, 4> h = Eigen::Matrix<double, 2, 4>::Zero();
    h(0, 0) = h(1, 1) = 1.0;
    const Eigen::Matrix2d s =
        h * covariance * h.transpose() + Eigen::Matrix2d::Identity() * sigmaPx * sigmaPx;
    const Eigen::Matrix<double, 4, 2> gain = covariance * h.transpose() * s.inverse();
    state += gain * (Eigen::Vector2d(x, y) - h * state);
    covariance = (Eigen::Matrix4d::Identity() - gain * h) * covariance;
  }
  cv::Point2f position() const {
    return {static_cast<float>(state(0)), static_cast<float>(state(1))};
  }
};

// [SECTION] Frames: sequential reads forward, buffered pieces backward ---------------------

class FrameSupply {
 public:
  // Grey frames for the flow, colour ones (BGR) for the appearance tracker.
  FrameSupply(VideoSource& video, std::size_t capacity, bool colour)
      : video_(video), capacity_(std::max<std::size_t>(capacity, 2)), colour_(colour) {}

  // Frame `f`, where `lowest` is the lowest frame the caller will ask for next (so a
  // backward pass decodes the piece [max(lowest, f − capacity + 1), f] at once).
  const cv::Mat& image(int f, int lowest) {
    if (auto it = frames_.find(f); it != frames_.end()) return it->second;
    // Forward, a frame is not asked for again once passed (a pass holds what it still needs):
    // one is kept. Backward, a piece is decoded at once and then handed out downwards.
    frames_.clear();
    const int from = f < newestRead_ ? std::max(lowest, f - static_cast<int>(capacity_) + 1) : f;
    for (int k = from; k <= f; ++k) frames_[k] = prepared(video_.frame(k));
    newestRead_ = f;
    return frames_.at(f);
  }

  void flatten(StaticBackground background) {
    frames_.clear();
    background_ = std::move(background);
  }

 private:
  VideoSource& video_;
  std::size_t capacity_;
  bool colour_;
  std::map<int, cv::Mat> frames_;
  int newestRead_ = -1;
  std::optional<StaticBackground> background_;

  cv::Mat prepared(const cv::Mat& bgr) const {
    if (colour_) return bgr;
    return background_ ? withoutBackground(toGrey(bgr), *background_) : toGrey(bgr);
  }
};

std::vector<cv::Mat> pyramidOf(const cv::Mat& grey, const Geometry& g, int levels) {
  std::vector<cv::Mat> pyramid;
  cv::buildOpticalFlowPyramid(grey, pyramid, cv::Size(g.windowPx, g.windowPx), levels);
  return pyramid;
}

// [SECTION] One pass from a keyframe ----------------------------------------------------

struct PassOutput {
  Eigen::MatrixXd jointsPx, confidence;  // rows: the whole tracked range
};

struct Step {
  std::vector<cv::Point2f> from, flow, back, guess;
  std::vector<unsigned char> status, backStatus;
  std::vector<float> error;
};

class FlowPass final : public TrackingPass {
 public:
  FlowPass(const Geometry& g, const TrackerOptions& o, const Keyframe& key, const cv::Mat& keyGrey)
      : g_(g), o_(o), fromPyramid_(pyramidOf(keyGrey, g, o.pyramidLevels)) {
    onKeyframe_.fill(cv::Point2f(std::numeric_limits<float>::quiet_NaN(),
                                 std::numeric_limits<float>::quiet_NaN()));
    for (int j = 0; j < kJointCount; ++j) {
      const double x = key.jointsPx(2 * j), y = key.jointsPx(2 * j + 1);
      if (std::isnan(x) || std::isnan(y)) continue;
      filters_[j].start(x, y);
      onKeyframe_[j] = cv::Point2f(static_cast<float>(x), static_cast<float>(y));
      templates_[j] =
          patchAround(keyGrey, cv::Point2f(static_cast<float>(x), static_cast<float>(y)));
    }
    for (std::size_t b = 0; b < kSearchTree.size(); ++b) {
      const int parent = index(kSearchTree[b].parent), child = index(kSearchTree[b].child);
      if (filters_[parent].active && filters_[child].active)
        strips_[b] = segmentStrip(keyGrey, filters_[parent].position(), filters_[child].position(),
                                  kSearchTree[b], g_.personPx);
    }
  }

  bool tracks(int j) const override { return filters_[j].active; }
  cv::Point2f position(int j) const override { return filters_[j].position(); }

  std::array<double, kJointCount> advance(const cv::Mat& toGrey, int frame) override {
    std::vector<cv::Mat> toPyramid = pyramidOf(toGrey, g_, o_.pyramidLevels);
    frame_ = frame;
    const auto confidence = advance(fromPyramid_, toPyramid, toGrey);
    fromPyramid_ = std::move(toPyramid);
    return confidence;
  }

 private:
  // Moves every joint from the from-frame to `toGrey`; confidence per joint out.
  std::array<double, kJointCount> advance(const std::vector<cv::Mat>& fromPyramid,
                                          const std::vector<cv::Mat>& toPyramid,
                                          const cv::Mat& toGrey) {
    std::array<double, kJointCount> confidence{};
    std::array<cv::Point2f, kJointCount> fromAll;
    fromAll.fill(cv::Point2f(std::numeric_limits<float>::quiet_NaN(),
                             std::numeric_limits<float>::quiet_NaN()));
    std::vector<int> joints;
    Step s;
    for (int j = 0; j < kJointCount; ++j) {
      if (!filters_[j].active) continue;
      joints.push_back(j);
      fromAll[j] = filters_[j].position();
      s.from.push_back(fromAll[j]);
      filters_[j].predict(0.01 * g_.personPx);
      s.guess.push_back(filters_[j].position());
    }
    if (joints.empty()) return confidence;
    const cv::Size window(g_.windowPx, g_.windowPx);
    const cv::TermCriteria stop(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 30, 0.01);
    s.flow = s.guess;
    cv::calcOpticalFlowPyrLK(fromPyramid, toPyramid, s.from, s.flow, s.status, s.error, window,
                             o_.pyramidLevels, stop, cv::OPTFLOW_USE_INITIAL_FLOW);
    s.back = s.from;
    cv::calcOpticalFlowPyrLK(toPyramid, fromPyramid, s.flow, s.back, s.backStatus, s.error, window,
                             o_.pyramidLevels, stop, cv::OPTFLOW_USE_INITIAL_FLOW);
    // The flow's answer where it holds (checked by flowing back), else the filter's guess.
    std::array<cv::Point2f, kJointCount> predicted = fromAll;
    std::array<bool, kJointCount> flowHolds{};
    for (std::size_t i = 0; i < joints.size(); ++i) {
      const cv::Point2f d = s.back[i] - s.from[i];
      flowHolds[joints[i]] =
          s.status[i] && s.backStatus[i] && std::hypot(d.x, d.y) <= g_.forwardBackwardLimitPx;
      predicted[joints[i]] = flowHolds[joints[i]] ? s.flow[i] : s.guess[i];
    }
    const SearchResult found =
        o_.searchSegments ? ew::searchSegments(toGrey, predicted, strips_,
                                               {g_.personPx, static_cast<double>(g_.searchPx)})
                          : SearchResult{};
    // Parents first: the trunk's hold needs the pelvis and the sternum of this frame.
    static const std::array<int, kJointCount> kParentsFirst = parentsFirst();
    std::array<int, kJointCount> slot;
    slot.fill(-1);
    for (std::size_t i = 0; i < joints.size(); ++i) slot[joints[i]] = static_cast<int>(i);
    for (const int j : kParentsFirst) {
      const int i = slot[j];
      if (i < 0) continue;
      confidence[j] = measure(j, s.guess[i], flowHolds[j] ? std::optional(s.flow[i]) : std::nullopt,
                              found.at[j], found.match[j], toGrey);
      // A joint that left the picture is lost for the rest of this pass, not extrapolated.
      const cv::Point2f p = filters_[j].position();
      if (!(p.x >= 0.0f && p.y >= 0.0f && p.x < static_cast<float>(toGrey.cols) &&
            p.y < static_cast<float>(toGrey.rows)))
        filters_[j].active = false;
    }
    return confidence;
  }

  cv::Mat patchAround(const cv::Mat& grey, cv::Point2f centre) const {
    cv::Mat patch;
    cv::getRectSubPix(grey, cv::Size(g_.patchPx, g_.patchPx), centre, patch);
    return patch;
  }

  // The keyframe patch sought in a square around `centre`: the best match and its score
  // (normalised cross-correlation, −1-1).
  struct Match {
    cv::Point2f best;
    double bestScore = -1.0;
  };
  // The keyframe patch's correlation at `centre` alone (one score, not a search).
  double scoreAt(int j, const cv::Mat& grey, cv::Point2f centre) const {
    cv::Mat region, score;
    cv::getRectSubPix(grey, templates_[j].size(), centre, region);
    cv::matchTemplate(region, templates_[j], score, cv::TM_CCOEFF_NORMED);
    return score.at<float>(0, 0);
  }

  Match matchAround(int j, const cv::Mat& grey, cv::Point2f centre) const {
    const int side = g_.patchPx + 2 * g_.searchPx;
    cv::Mat region, scores;
    cv::getRectSubPix(grey, cv::Size(side, side), centre, region);
    cv::matchTemplate(region, templates_[j], scores, cv::TM_CCOEFF_NORMED);
    double maxScore = 0.0;
    cv::Point maxAt;
    cv::minMaxLoc(scores, nullptr, &maxScore, nullptr, &maxAt);
    Match m;
    m.bestScore = maxScore;
    m.best = centre + cv::Point2f(static_cast<float>(maxAt.x - g_.searchPx),
                                  static_cast<float>(maxAt.y - g_.searchPx));
    return m;
  }

  // The model's place for joint j on this frame, when the options have one.
  std::optional<cv::Point2f> priorAt(int j) const {
    const Eigen::Index row = frame_ - o_.firstFrame;
    if (row < 0 || row >= o_.priorPx.rows() || o_.priorPx.cols() != kDims2) return std::nullopt;
    const double x = o_.priorPx(row, 2 * j), y = o_.priorPx(row, 2 * j + 1);
    if (!std::isfinite(x) || !std::isfinite(y)) return std::nullopt;
    return cv::Point2f(static_cast<float>(x), static_cast<float>(y));
  }

  // A joint the walk hides is where the walk puts it, at the fit's threshold (a detector's 0.3,
  // KeypointOptions): the next fit keeps it there rather than losing it, as it would a lost
  // joint at 0.2. (Dropping it lost the pelvis, hidden under the near thigh all through a side
  // view, and with it the walking check.)
  static constexpr double kHiddenConfidence = 0.3;

  bool hiddenByTheWalk(int j) const {
    const Eigen::Index row = frame_ - o_.firstFrame;
    return row >= 0 && row < o_.priorHidden.rows() && o_.priorHidden.cols() == kJointCount &&
           o_.priorHidden(row, j) > 0.5;
  }

  // The model loop: a flow that failed or strayed beyond the gate from the model's place is
  // replaced by the keyframe patch found near that place, else by the place itself (a joint
  // hidden behind the other leg is where the walk says it is). A flow within the gate stands,
  // but slides towards the place along an edge (slideAlongTheAperture). nullopt: the flow
  // stands as it is.
  std::optional<double> measureAgainstPrior(int j, std::optional<cv::Point2f> flow,
                                            const cv::Mat& toGrey) {
    const std::optional<cv::Point2f> prior = priorAt(j);
    if (!prior) return std::nullopt;
    const double gate = o_.priorGateShare * g_.personPx;
    if (hiddenByTheWalk(j)) {
      filters_[j].update(prior->x, prior->y, 0.5 * gate);
      return kHiddenConfidence;
    }
    const auto distance = [](cv::Point2f a, cv::Point2f b) {
      return std::hypot(a.x - b.x, a.y - b.y);
    };
    if (flow && distance(*flow, *prior) <= gate) {
      const std::optional<cv::Point2f> slid = slideAlongTheAperture(*flow, *prior, toGrey);
      if (!slid) return std::nullopt;
      return takeTheFlow(j, *slid, toGrey);
    }
    const Match m = matchAround(j, toGrey, *prior);
    if (m.bestScore > 0.7 && distance(m.best, *prior) <= gate) {
      filters_[j].update(m.best.x, m.best.y, 1.0 / m.bestScore);
      return 0.5 * m.bestScore;
    }
    filters_[j].update(prior->x, prior->y, 0.5 * gate);
    return 0.2;
  }

  // Where the flow's window shows one edge (a straight limb with little print on it: a leg seen
  // from behind), the flow knows the joint's place across the edge but hardly along it, and
  // drifts along it frame after frame. There the model's place says where along: the flow moves
  // towards it along the weak direction, by as much as that direction is weaker than the
  // other (the window's structure tensor). nullopt: the window is textured both ways.
  std::optional<cv::Point2f> slideAlongTheAperture(cv::Point2f flow, cv::Point2f prior,
                                                   const cv::Mat& toGrey) const {
    cv::Mat window, gx, gy;
    cv::getRectSubPix(toGrey, cv::Size(g_.windowPx + 2, g_.windowPx + 2), flow, window);
    window.convertTo(window, CV_32F);
    cv::Sobel(window, gx, CV_32F, 1, 0, 3);
    cv::Sobel(window, gy, CV_32F, 0, 1, 3);
    const cv::Rect inner(1, 1, g_.windowPx, g_.windowPx);
    const double xx = gx(inner).dot(gx(inner)), yy = gy(inner).dot(gy(inner)),
                 xy = gx(inner).dot(gy(inner));
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> tensor(
        (Eigen::Matrix2d() << xx, xy, xy, yy).finished());
    const double weak = tensor.eigenvalues()(0), strong = tensor.eigenvalues()(1);
    if (!(strong > 0.0) || weak >= kApertureRatio * strong) return std::nullopt;
    const double pull = 1.0 - weak / (kApertureRatio * strong);
    const Eigen::Vector2d along = tensor.eigenvectors().col(0);
    const Eigen::Vector2d towards(prior.x - flow.x, prior.y - flow.y);
    const Eigen::Vector2d moved = pull * along * along.dot(towards);
    return flow + cv::Point2f(static_cast<float>(moved.x()), static_cast<float>(moved.y()));
  }

  // With TrackerOptions::holdTheTrunk: where the trunk puts joint j on this frame — its place
  // on the pass's keyframe relative to the pelvis, turned, stretched and carried as the
  // pelvis→sternum line has been since. nullopt for the other joints, or without the line.
  std::optional<cv::Point2f> heldByTheTrunk(int j) const {
    const int pelvis = index(Joint::Pelvis), sternum = index(Joint::Sternum);
    if (!o_.holdTheTrunk || !heldWithTheTrunk(j) || !filters_[pelvis].active ||
        !filters_[sternum].active || std::isnan(onKeyframe_[j].x))
      return std::nullopt;
    const auto complexOf = [](cv::Point2f p) { return std::complex<double>(p.x, p.y); };
    const std::complex<double> lineThen =
        complexOf(onKeyframe_[sternum]) - complexOf(onKeyframe_[pelvis]);
    const std::complex<double> lineNow =
        complexOf(filters_[sternum].position()) - complexOf(filters_[pelvis].position());
    if (!(std::abs(lineThen) >= 1.0)) return std::nullopt;
    const std::complex<double> at =
        complexOf(filters_[pelvis].position()) +
        lineNow / lineThen * (complexOf(onKeyframe_[j]) - complexOf(onKeyframe_[pelvis]));
    return cv::Point2f(static_cast<float>(at.real()), static_cast<float>(at.imag()));
  }

  // A flow near where the trunk puts the joint stands; one that strayed (a shoulder sliding
  // along a bare arm) or failed is replaced by that place.
  double measureAgainstTheTrunk(int j, std::optional<cv::Point2f> flow, cv::Point2f held,
                                const cv::Mat& toGrey) {
    if (flow && std::hypot(flow->x - held.x, flow->y - held.y) <= kTrunkGateShare * g_.personPx)
      return takeTheFlow(j, *flow, toGrey);
    filters_[j].update(held.x, held.y, 0.5);
    return 0.5;
  }

  // The flow's answer `at` as the joint's measurement, trusted as far as the keyframe patch
  // still looks like the picture there; its confidence.
  double takeTheFlow(int j, cv::Point2f at, const cv::Mat& toGrey) {
    const double c = std::clamp(0.5 + 0.5 * scoreAt(j, toGrey, at), 0.05, 1.0) * 0.8;
    filters_[j].update(at.x, at.y, 0.5 / c);
    return c;
  }

  // The model's prior first, when it has one and the flow strayed from it (above). Then a
  // segment that looks as it did on the keyframe places its joint; else the joint's own flow;
  // else the keyframe patch, if it is clearly there; else the joint coasts on the filter.
  double measure(int j, cv::Point2f guess, std::optional<cv::Point2f> flow, cv::Point2f segmentAt,
                 double segmentMatch, const cv::Mat& toGrey) {
    if (const std::optional<double> c = measureAgainstPrior(j, flow, toGrey)) return *c;
    if (const std::optional<cv::Point2f> held = heldByTheTrunk(j))
      return measureAgainstTheTrunk(j, flow, *held, toGrey);
    if (segmentMatch >= kSegmentMatchHolds) {
      filters_[j].update(segmentAt.x, segmentAt.y, 0.5 / segmentMatch);
      return segmentMatch;
    }
    if (flow) return takeTheFlow(j, *flow, toGrey);
    const Match m = matchAround(j, toGrey, guess);
    if (m.bestScore > 0.7) {
      filters_[j].update(m.best.x, m.best.y, 1.0 / m.bestScore);
      return 0.5 * m.bestScore;
    }
    return 0.05;
  }

  // A strip correlation this high is the same segment (a limb's stripes or folds line up);
  // below it the segment turned out of view or something covers it.
  static constexpr double kSegmentMatchHolds = 0.6;
  // A window whose weaker direction has less than this share of the stronger's gradient energy
  // shows an edge. Measured on track-study from behind (five held-out walkers, one round): 0.15
  // left the knees drifting (0 of 5 within issue 14's bar), 0.2 brought 3 of 5 within it, 0.3
  // lost one walker's ankle (p95 22.8 px); from the front 5 of 5 with each.
  static constexpr double kApertureRatio = 0.2;
  // How far (a share of the person's height) a held joint's flow may stand from the trunk's
  // place. On cam01: 0.02 gave a median of 19.9 px, 0.03 19.3, 0.05 20.8 (docs/TRACKING_DESIGN.md).
  static constexpr double kTrunkGateShare = 0.03;

  Geometry g_;
  TrackerOptions o_;
  std::array<JointFilter, kJointCount> filters_{};
  std::array<cv::Mat, kJointCount> templates_{};
  std::array<SegmentStrip, kBones.size()> strips_{};
  std::vector<cv::Mat> fromPyramid_;
  std::array<cv::Point2f, kJointCount> onKeyframe_{};  // NaN: not marked there
  int frame_ = 0;  // the video frame being tracked onto
};

// [SECTION] Blending the passes -----------------------------------------------------------

// Forward and backward answers for one joint in one frame: near each other they are
// averaged by weight, else the heavier one is kept (an average of two different legs is
// neither).
void blend(const PassOutput& fwd, double wf, const PassOutput& bwd, double wb, Eigen::Index row,
           int j, double agreePx, JointTrack& out) {
  const double xf = fwd.jointsPx(row, 2 * j), yf = fwd.jointsPx(row, 2 * j + 1);
  const double xb = bwd.jointsPx(row, 2 * j), yb = bwd.jointsPx(row, 2 * j + 1);
  const bool hasF = !std::isnan(xf), hasB = !std::isnan(xb);
  if (!hasF && !hasB) return;
  wf = hasF ? wf * fwd.confidence(row, j) : 0.0;
  wb = hasB ? wb * bwd.confidence(row, j) : 0.0;
  const auto take = [&](double x, double y, double c) {
    out.jointsPx(row, 2 * j) = x;
    out.jointsPx(row, 2 * j + 1) = y;
    out.confidence(row, j) = c;
  };
  const bool apart = hasF && hasB && std::hypot(xf - xb, yf - yb) > agreePx;
  if (!hasB || (apart && wf >= wb)) {
    take(xf, yf, fwd.confidence(row, j));
  } else if (!hasF || apart) {
    take(xb, yb, bwd.confidence(row, j));
  } else {
    const double sum = std::max(wf + wb, 1e-12);
    take((wf * xf + wb * xb) / sum, (wf * yf + wb * yb) / sum,
         std::max(fwd.confidence(row, j), bwd.confidence(row, j)));
  }
}

// [SECTION] The whole range ---------------------------------------------------------------

struct Range {
  int first = 0, last = 0;
  Eigen::Index rows() const { return last - first + 1; }
};

std::size_t bytesPerPixel(const TrackerOptions& o) {
  return o.kind == TrackerKind::Appearance ? 3 : 1;
}

// A 1 × 1 video was "tracked" at confidence 0 (issue 53): no walker fits in a picture that small.
void checkTrackableSize(const VideoInfo& info) {
  if (info.widthPx < kMinTrackedSidePx || info.heightPx < kMinTrackedSidePx)
    throwBadData(info.file, "",
                 "frame size " + std::to_string(info.widthPx) + "x" + std::to_string(info.heightPx) +
                     " px is too small to track a walker in (each side at least " +
                     std::to_string(kMinTrackedSidePx) + " px)");
}

Range rangeFor(const VideoSource& video, const TrackerOptions& o) {
  checkTrackableSize(video.info());
  const int count = video.info().frameCount;
  Range r{o.firstFrame, o.lastFrame < 0 ? count - 1 : o.lastFrame};
  if (r.first < 0 || r.last >= count || r.first > r.last)
    throw Error(ErrorKind::BadArgument, video.info().file, "",
                "frames " + std::to_string(r.first) + "-" + std::to_string(r.last) +
                    " are not within the video's 0-" + std::to_string(count - 1));
  return r;
}

class RangeTracker {
 public:
  RangeTracker(VideoSource& video, const Keyframes& keys, const TrackerOptions& o,
               const TrackProgress& progress)
      : video_(video),
        o_(o),
        progress_(progress),
        range_(rangeFor(video, o)),
        supply_(video,
                std::max<std::size_t>(
                    2, o.frameBufferBytes /
                           std::max<std::size_t>(1, static_cast<std::size_t>(video.info().widthPx) *
                                                        video.info().heightPx * bytesPerPixel(o))),
                o.kind == TrackerKind::Appearance) {
    for (const Keyframe& k : keys.keyframes)
      if (k.frame >= range_.first && k.frame <= range_.last) keys_.push_back(k);
    if (keys_.empty())
      throw Error(ErrorKind::BadArgument, video.info().file, "",
                  "no keyframe within the tracked frames " + std::to_string(range_.first) + "-" +
                      std::to_string(range_.last));
    checkMarksWithin(keys, video.info().widthPx, video.info().heightPx, video.info().file);
    g_ = geometryFor(personHeightPx(keys, video.info().heightPx), o);
    if (o.kind == TrackerKind::OpticalFlow && o.flattenStaticBackground) {
      BackgroundCheck check = estimateStaticBackground(video, range_.first, range_.last,
                                                       keys_.front(), o.frameBufferBytes);
      background_ = check.background ? "flattened" : check.why;
      if (check.background) supply_.flatten(std::move(*check.background));
    }
    const PassOutput empty{Eigen::MatrixXd::Constant(range_.rows(), kDims2, kNaN),
                           Eigen::MatrixXd::Zero(range_.rows(), kJointCount)};
    forward_ = backward_ = empty;
    totalSteps_ = static_cast<double>(2 * range_.rows());
  }

  JointTrack run() {
    for (std::size_t i = 0; i < keys_.size(); ++i) {
      const int previous = i == 0 ? range_.first : keys_[i - 1].frame;
      const int next = i + 1 == keys_.size() ? range_.last : keys_[i + 1].frame;
      runPass(keys_[i], previous, backward_);
      runPass(keys_[i], next, forward_);
    }
    return blended();
  }

 private:
  // From the keyframe to `until` (either direction), writing rows of `out`.
  void runPass(const Keyframe& key, int until, PassOutput& out) {
    const int step = until >= key.frame ? 1 : -1;
    const int lowest = std::min(key.frame, until);
    // Headers, not copies: they keep the frame alive when the supply lets it go.
    const cv::Mat keyImage = supply_.image(key.frame, lowest);
    const std::unique_ptr<TrackingPass> pass = passFrom(key, keyImage);
    record(*pass, key.frame, std::array<double, kJointCount>{}, out, true);
    for (int j = 0; j < kJointCount; ++j)  // the marks themselves, not their float copies
      if (pass->tracks(j))
        out.jointsPx.block<1, 2>(key.frame - range_.first, 2 * j) = key.jointsPx.segment<2>(2 * j);
    for (int f = key.frame + step; f != until + step; f += step) {
      record(*pass, f, pass->advance(supply_.image(f, lowest), f), out, false);
      if (progress_ && !progress_(++stepsDone_ / totalSteps_))
        throw Error(ErrorKind::BadArgument, video_.info().file, "", "tracking cancelled");
    }
  }

  std::unique_ptr<TrackingPass> passFrom(const Keyframe& key, const cv::Mat& keyImage) const {
    if (o_.kind == TrackerKind::Appearance) {
      AppearanceOptions a;
      a.personPx = g_.personPx;
      return makeAppearancePass(key, keyImage, a);
    }
    return std::make_unique<FlowPass>(g_, o_, key, keyImage);
  }

  void record(const TrackingPass& pass, int frame,
              const std::array<double, kJointCount>& confidence, PassOutput& out, bool isKeyframe) {
    const Eigen::Index row = frame - range_.first;
    for (int j = 0; j < kJointCount; ++j) {
      if (!pass.tracks(j)) continue;
      const cv::Point2f p = pass.position(j);
      out.jointsPx(row, 2 * j) = p.x;
      out.jointsPx(row, 2 * j + 1) = p.y;
      out.confidence(row, j) = isKeyframe ? 1.0 : confidence[j];
    }
  }

  JointTrack blended() const {
    JointTrack t;
    t.firstFrame = range_.first;
    t.fps = video_.info().fps;
    t.imageSize = {video_.info().widthPx, video_.info().heightPx};
    t.background = background_;
    t.jointsPx = Eigen::MatrixXd::Constant(range_.rows(), kDims2, kNaN);
    t.confidence = Eigen::MatrixXd::Zero(range_.rows(), kJointCount);
    const double agreePx = 0.03 * g_.personPx;
    for (Eigen::Index row = 0; row < range_.rows(); ++row) {
      const int frame = range_.first + static_cast<int>(row);
      const auto [wf, wb] = passWeights(frame);
      for (int j = 0; j < kJointCount; ++j) blend(forward_, wf, backward_, wb, row, j, agreePx, t);
    }
    return t;
  }

  // Each pass counts more the nearer its keyframe: 1 at it, 0 at the other keyframe.
  std::pair<double, double> passWeights(int frame) const {
    const Keyframe* before = nullptr;
    const Keyframe* after = nullptr;
    for (const Keyframe& k : keys_) {
      if (k.frame <= frame) before = &k;
      if (k.frame >= frame && !after) after = &k;
    }
    if (!before) return {0.0, 1.0};
    if (!after) return {1.0, 0.0};
    if (before == after) return {1.0, 0.0};  // a keyframe: its forward pass starts at the marks
    const double s = static_cast<double>(frame - before->frame) / (after->frame - before->frame);
    return {1.0 - s, s};
  }

  VideoSource& video_;
  TrackerOptions o_;
  TrackProgress progress_;
  Range range_;
  FrameSupply supply_;
  std::vector<Keyframe> keys_;
  Geometry g_;
  PassOutput forward_, backward_;
  std::string background_ = "off";
  double stepsDone_ = 0.0, totalSteps_ = 1.0;
};

}  // namespace

const char* trackerName(TrackerKind kind) {
  return kind == TrackerKind::Appearance ? "appearance" : "flow";
}

TrackerKind trackerFromName(const std::string& name) {
  for (TrackerKind k : {TrackerKind::OpticalFlow, TrackerKind::Appearance})
    if (name == trackerName(k)) return k;
  throw Error(ErrorKind::BadArgument, "", "",
              "unknown tracker '" + name + "' (flow or appearance)");
}

JointTrack trackJoints(VideoSource& video, const Keyframes& keyframes,
                       const TrackerOptions& options, const TrackProgress& progress) {
  return RangeTracker(video, keyframes, options, progress).run();
}

KeypointTrial keypointTrialOf(const JointTrack& track, const std::string& file) {
  KeypointOptions k;
  k.fps = track.fps;
  if (track.imageSize.width > 0 && track.imageSize.height > 0) k.imageSize = track.imageSize;
  return trialFromJoints(track.jointsPx, track.confidence, file, "tracked video", k);
}

}  // namespace ew

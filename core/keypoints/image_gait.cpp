#include "core/keypoints/image_gait.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <Eigen/LU>
#include <Eigen/QR>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

#include "core/common/errors.h"
#include "core/gait/gait_cycles.h"
#include "core/gait/gaps.h"

namespace ew {
namespace {

[[noreturn]] void notWalking(const KeypointTrial& t, const std::string& why) {
  throw Error(ErrorKind::BadData, t.file, "", "not walking: " + why);
}

// Mean pelvis position over the first (or last) tenth of the frames where it is seen. A trial
// whose pelvis is never seen is not walking (its points all dropped by a lens undistortion that
// does not fit the camera, issue 53): there is no end to read.
Eigen::Vector2d pelvisAtEnd(const KeypointTrial& t, bool last) {
  std::vector<Eigen::Vector2d> seen;
  for (Eigen::Index f = 0; f < t.jointsPx.rows(); ++f) {
    const Eigen::Vector2d p = t.jointsPx.block<1, 2>(f, 2 * index(Joint::Pelvis)).transpose();
    if (p.allFinite()) seen.push_back(p);
  }
  if (seen.empty()) notWalking(t, "the pelvis is seen in none of the " + std::to_string(t.jointsPx.rows()) + " frames");
  const std::size_t n = std::max<std::size_t>(1, seen.size() / 10);
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (std::size_t i = 0; i < n; ++i) sum += seen[last ? seen.size() - 1 - i : i];
  return sum / static_cast<double>(n);
}

// The walker's size in one frame: the lower ankle below the head (else the sternum), px; NaN
// without both (a detector's frame missing the head and the neck, or both feet).
double frameSizePx(const KeypointTrial& t, Eigen::Index f) {
  const auto v = [&](Joint j) {
    const double u = t.jointsPx(f, 2 * index(j)), y = t.jointsPx(f, 2 * index(j) + 1);
    return std::isfinite(u) ? y : NAN;
  };
  const double top = std::isfinite(v(Joint::Head)) ? v(Joint::Head) : v(Joint::Sternum);
  const double r = v(Joint::RAnkle), l = v(Joint::LAnkle);
  const double bottom = std::isfinite(r) && std::isfinite(l) ? std::max(r, l) : std::isfinite(r) ? r : l;
  return bottom - top;
}

// The walker's mean size over the first (or last) tenth of the frames where it can be
// measured (frameSizePx); NaN when no frame can.
double extentAtEnd(const KeypointTrial& t, bool last) {
  std::vector<double> extents;
  for (Eigen::Index f = 0; f < t.jointsPx.rows(); ++f) {
    const double size = frameSizePx(t, f);
    if (std::isfinite(size)) extents.push_back(size);
  }
  if (extents.empty()) return NAN;
  const std::size_t n = std::max<std::size_t>(1, extents.size() / 10);
  double sum = 0.0;
  for (std::size_t i = 0; i < n; ++i) sum += extents[last ? extents.size() - 1 - i : i];
  return sum / static_cast<double>(n);
}

// A clip read as a stride and a bit (one strike a side, or the ankles' swing alone) must be
// short, and the walker must travel (across the picture, or towards or away from the camera):
// in a longer clip a walker strikes more often, and a person balancing or shifting their
// weight on the spot, whose feet move once or twice, is not walking.
constexpr double kMaxShortClipStrides = 2.5;
// A walker who does not cross the picture travels when a line in time explains this share of
// the variance of their size in it (steadySizeChange; a foot's lift makes the size bob with the
// steps): the widened camera experiment's walkers seen from within 20° of behind over 1.2
// strides 0.46-0.82, the Pose2Sim balancing trial's views whose size changes 0.11.
constexpr double kMinSteadySizeChange = 0.3;

// Stride frequency from same-side strike intervals (strides per second); a clip of a stride
// and a bit has one strike a side: then from the step between them, half a stride, when the
// clip (`durationS`) holds fewer than kMaxShortClipStrides of them.
double strideHz(const std::vector<double>& right, const std::vector<double>& left, double durationS) {
  double total = 0.0;
  int count = 0;
  for (const auto* side : {&right, &left}) {
    if (side->size() < 2) continue;
    total += side->back() - side->front();
    count += static_cast<int>(side->size()) - 1;
  }
  if (count > 0 && total > 0) return count / total;
  const double step = right.size() == 1 && left.size() == 1 ? std::abs(right.front() - left.front()) : 0.0;
  return step > 0 && durationS < kMaxShortClipStrides * 2.0 * step ? 0.5 / step : 0.0;
}

// The share of the variance of the walker's per-frame size (frameSizePx) a line in time
// explains: near 1 for a walker nearing or leaving the camera, low for one who stays and
// lifts a foot; 0 with fewer than 8 frames measured.
double steadySizeChange(const KeypointTrial& t) {
  std::vector<double> ts, sizes;
  for (Eigen::Index f = 0; f < t.jointsPx.rows(); ++f) {
    const double size = frameSizePx(t, f);
    if (std::isfinite(size)) ts.push_back(static_cast<double>(f)), sizes.push_back(size);
  }
  if (sizes.size() < 8) return 0.0;
  const auto n = static_cast<Eigen::Index>(sizes.size());
  Eigen::MatrixXd line(n, 2);
  line.col(0).setOnes();
  line.col(1) = Eigen::Map<const Eigen::VectorXd>(ts.data(), n);
  const Eigen::VectorXd y = Eigen::Map<const Eigen::VectorXd>(sizes.data(), n);
  const double total = (y.array() - y.mean()).square().sum();
  const double left = (y - line * line.colPivHouseholderQr().solve(y)).squaredNorm();
  return total > 0.0 ? 1.0 - left / total : 0.0;
}

// A clip too short for the strikes' frequency (defined with the trunk's bob, below).
std::optional<double> ankleLeadsStrideHz(const Eigen::VectorXd& rightMinusLeft, double rateHz);

// The ankles' offsets from the pelvis spread along their swing this many times more (in
// variance) than across it, or there is no swing to read a direction from.
constexpr double kMinSwingAnisotropy = 1.3;

// Each ankle's offset from the pelvis over the frames where both are seen, times the frame's
// `scale` (steadySizeScale).
std::vector<std::vector<Eigen::Vector2d>> ankleLeads(const KeypointTrial& t, const Eigen::VectorXd& scale) {
  std::vector<std::vector<Eigen::Vector2d>> leads(2);
  const Eigen::Index pelvis = 2 * index(Joint::Pelvis);
  for (Eigen::Index f = 0; f < t.jointsPx.rows(); ++f) {
    const Eigen::Vector2d p = t.jointsPx.block<1, 2>(f, pelvis).transpose();
    for (int side = 0; side < 2; ++side) {
      const Joint ankle = side == 0 ? Joint::RAnkle : Joint::LAnkle;
      const Eigen::Vector2d a = t.jointsPx.block<1, 2>(f, 2 * index(ankle)).transpose();
      leads[static_cast<std::size_t>(side)].push_back(a.allFinite() && p.allFinite() ? Eigen::Vector2d(scale[f] * (a - p))
                                                                                   : Eigen::Vector2d::Constant(NAN));
    }
  }
  return leads;
}

// The way the feet swing in the image, for a walker that does not cross it (in place, or
// towards or away from the camera): the main axis of the ankles' offsets from the pelvis,
// pointing the way they move for the shorter part of the time (a foot swings forward in about
// 40 % of a stride and is carried back in the rest). Unset when the ankles are seen too little
// or move no way more than another.
std::optional<Eigen::Vector2d> ankleSwingDirection(const KeypointTrial& t, const Eigen::VectorXd& scale) {
  const auto leads = ankleLeads(t, scale);
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  int samples = 0;
  for (const auto& side : leads) {
    Eigen::Vector2d mean = Eigen::Vector2d::Zero();
    int n = 0;
    for (const auto& l : side)
      if (l.allFinite()) mean += l, ++n;
    if (n == 0) continue;
    mean /= n;
    for (const auto& l : side)
      if (l.allFinite()) scatter += (l - mean) * (l - mean).transpose(), ++samples;
  }
  if (samples < 8) return std::nullopt;
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
  // A swing along one axis, not a scatter as wide every way (a person standing and shifting).
  if (!(eig.eigenvalues()[1] > kMinSwingAnisotropy * eig.eigenvalues()[0])) return std::nullopt;
  Eigen::Vector2d d = eig.eigenvectors().col(1);
  int forward = 0, back = 0;
  for (const auto& side : leads) {
    for (std::size_t f = 1; f + 1 < side.size(); ++f) {
      if (!side[f - 1].allFinite() || !side[f + 1].allFinite()) continue;
      const double v = (side[f + 1] - side[f - 1]).dot(d);
      if (v > 0) ++forward;
      if (v < 0) ++back;
    }
  }
  if (forward + back == 0) return std::nullopt;
  return forward > back ? Eigen::Vector2d(-d) : d;
}

std::string fixed(double v, int decimals) {
  std::ostringstream s;
  s.precision(decimals);
  s << std::fixed << v;
  return s.str();
}

std::string fixed1(double v) { return fixed(v, 1); }

// What a clip whose pelvis does not cross the picture shows instead.
std::string stillPelvis(double travelShare, double sizeChange) {
  return "the pelvis crosses " + fixed1(travelShare) + " of the walker's height in the image (walking across it: > " +
         fixed1(kMinImageTravelOfHeight) + ") and the walker's size in it changes " +
         (std::isfinite(sizeChange) ? fixed(100.0 * sizeChange, 0) + " %" : std::string("by an unknown share")) +
         " (walking towards or away from the camera: > " + fixed(100.0 * kMaxInPlaceSizeChange, 0) + " %)";
}

// Frames at the clip's ends where the pelvis or an ankle is unseen, over this long, are left
// out of the feet's reading: filled, each ankle would stand where it was first or last seen
// while the pelvis moves on (a walker whose feet enter the picture late read as no strikes at
// all). A shorter run (a point the detector missed now and then) is filled as gaps inside are:
// a strike at the clip's very end still counts.
constexpr double kMaxFilledEndS = 0.1;

// The frames the feet are read over: the whole clip less its ends' runs of unseen pelvis or
// ankles longer than kMaxFilledEndS (the whole clip when nothing would be left).
std::pair<Eigen::Index, Eigen::Index> feetSeenSpan(const KeypointTrial& t) {
  const auto seen = [&](Eigen::Index f) {
    for (Joint j : {Joint::Pelvis, Joint::RAnkle, Joint::LAnkle})
      if (!t.jointsPx.block<1, 2>(f, 2 * index(j)).allFinite()) return false;
    return true;
  };
  const Eigen::Index n = t.jointsPx.rows();
  Eigen::Index first = 0, last = n - 1;
  while (first < last && !seen(first)) ++first;
  while (last > first && !seen(last)) --last;
  if (first >= last) return {0, n - 1};
  const double maxFilled = kMaxFilledEndS * t.rateHz;
  if (static_cast<double>(first) <= maxFilled) first = 0;
  if (static_cast<double>(n - 1 - last) <= maxFilled) last = n - 1;
  return {first, last};
}

// A walker nearing or leaving the camera grows or shrinks in the image, and the feet's swing
// with it. Read raw, the strides near the camera dwarf the far ones and the strike finder,
// whose threshold is a share of the largest lead, finds only the near ones (a walker coming
// from 8 m to the camera, 216 px to 2168 px tall, read as 2 right and 1 left strike in 9 s).
// So each frame's positions are read scaled to the walker's size at `referencePx`: the inverse
// of its image height is a line in time for a walk at a steady speed (imageDepthLine), which
// leaves out the steps' bob of the height. All ones when there is no such line, or when it
// changes less than kMaxInPlaceSizeChange over the clip (a walker crossing the picture).
Eigen::VectorXd steadySizeScale(const KeypointTrial& t, double referencePx) {
  const Eigen::Index n = t.jointsPx.rows();
  const Eigen::VectorXd times = Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1) / t.rateHz);
  const std::optional<Eigen::Vector2d> inverseHeight = n >= 2 ? imageDepthLine(t.jointsPx, times) : std::nullopt;
  if (!inverseHeight) return Eigen::VectorXd::Ones(n);
  const Eigen::ArrayXd inverse = (*inverseHeight)[0] + (*inverseHeight)[1] * times.array();
  if (std::abs(inverse[n - 1] / inverse[0] - 1.0) < kMaxInPlaceSizeChange) return Eigen::VectorXd::Ones(n);
  return (referencePx * inverse).matrix();
}

// A walker whose size in the picture changes more than this many times over the clip walks
// mostly along the camera's line of sight. The pelvis then travels towards or away from the
// walk's vanishing point, and perspective moves it across the picture too (a walker seen from
// 5° off behind, crossing 2.5 of its heights as it comes up to the camera); the feet, below
// it, swing along their own lines to that point, steeper in the picture: their swing is read
// along its own axis, as when the pelvis does not cross the picture.
constexpr double kMaxSizeRatioOfACrossing = 2.0;

// Scaled to the walker's size (steadySizeScale), an ankle's offset from the pelvis keeps its
// height in the picture, but a step along the line of sight is foreshortened as well as shrunk
// with the distance: its image is as one over the distance squared. So each lead less its mean
// is scaled once more, leaving the pelvis at zero. `frames`: leads along the swing, scaled once.
void evenSightLineSwing(Eigen::MatrixXd& frames, const Eigen::VectorXd& scale) {
  const Eigen::Index pelvis = 3 * index(Joint::Pelvis) + 1;
  for (Joint ankle : {Joint::RAnkle, Joint::LAnkle}) {
    const Eigen::Index col = 3 * index(ankle) + 1;
    const Eigen::VectorXd lead = frames.col(col) - frames.col(pelvis);
    frames.col(col) = ((lead.array() - lead.mean()) * scale.array()).matrix();
  }
  frames.col(pelvis).setZero();
}

// The walk's direction in the picture for a walker crossing it: its pelvis's travel, or along
// the line of sight the feet's own swing (kMaxSizeRatioOfACrossing).
Eigen::Vector2d crossingDirection(const KeypointTrial& t, const Eigen::Vector2d& travel, bool alongTheSightLine,
                                  const Eigen::VectorXd& scale) {
  const std::optional<Eigen::Vector2d> swing = alongTheSightLine ? ankleSwingDirection(t, scale) : std::nullopt;
  return swing.value_or(travel.normalized());
}

// The walk's direction in the picture for a walker who does not cross it: the feet's swing.
// Too short a clip to read a swing from, but the walker grows or shrinks: towards the camera
// the feet come down the image, away from it they go up. Throws "not walking" without either,
// `prefix` saying first what the walker does instead.
Eigen::Vector2d swingDirectionInPlace(const KeypointTrial& t, double sizeChange, const Eigen::VectorXd& scale,
                                      const std::string& prefix) {
  std::optional<Eigen::Vector2d> swing = ankleSwingDirection(t, scale);
  if (!swing && sizeChange > kMaxInPlaceSizeChange)
    swing = Eigen::Vector2d(0.0, extentAtEnd(t, true) > extentAtEnd(t, false) ? 1.0 : -1.0);
  if (!swing) notWalking(t, prefix + "the ankles do not swing about the pelvis (as on a treadmill)");
  return *swing;
}

}  // namespace

ImageGait imageGaitCycles(const KeypointTrial& t, std::optional<double> heldStrideHz) {
  ImageGait g;
  const double height = std::max(t.people.at(static_cast<std::size_t>(t.chosen)).sizePx, 1.0);
  const Eigen::Vector2d travel = pelvisAtEnd(t, true) - pelvisAtEnd(t, false);
  g.travelPx = travel.norm();
  const bool crosses = g.travelPx >= kMinImageTravelOfHeight * height;
  const double sizeChange = std::abs(extentAtEnd(t, true) / extentAtEnd(t, false) - 1.0);
  // Not crossing the picture and keeping its size (a NaN size change is no evidence of depth).
  g.inPlace = !crosses && !(sizeChange > kMaxInPlaceSizeChange);
  // A walker not crossing the picture is first told what it does instead, then why that is
  // not walking either.
  const std::string prefix = crosses ? std::string() : stillPelvis(g.travelPx / height, sizeChange) + ", and ";
  const double sizeRatio = extentAtEnd(t, true) / extentAtEnd(t, false);
  const bool alongTheSightLine = std::max(sizeRatio, 1.0 / sizeRatio) > kMaxSizeRatioOfACrossing;
  const Eigen::VectorXd scale = steadySizeScale(t, height);
  g.direction = crosses ? crossingDirection(t, travel, alongTheSightLine, scale)
                        : swingDirectionInPlace(t, sizeChange, scale, prefix);
  // The leads as the forward coordinate of canonical frames, so the 3D strike finder applies,
  // over the frames where the feet are seen (strike times then counted from the clip's start).
  const auto [first, last] = feetSeenSpan(t);
  const Eigen::Index count = last - first + 1;
  Eigen::MatrixXd frames = Eigen::MatrixXd::Zero(count, 3 * kJointCount);
  for (Joint j : {Joint::Pelvis, Joint::RAnkle, Joint::LAnkle}) {
    frames.col(3 * index(j) + 1) = t.jointsPx.middleRows(first, count).middleCols<2>(2 * index(j)) * g.direction;
    // Every sample filled: one missed ankle must not hide a strike.
    fillAllGapsLinearly(frames.col(3 * index(j) + 1));
  }
  for (Joint ankle : {Joint::RAnkle, Joint::LAnkle}) {
    const Eigen::VectorXd lead =
        frames.col(3 * index(ankle) + 1) - frames.col(3 * index(Joint::Pelvis) + 1);
    double lo = INFINITY, hi = -INFINITY;
    for (double x : lead) {
      if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
    }
    const double minLead = crosses ? kMinImageAnkleLeadOfHeight : kMinImageAnkleLeadInPlaceOfHeight;
    if (!(hi - lo >= minLead * height))
      notWalking(t, prefix + "the " + (ankle == Joint::RAnkle ? "right" : "left") + " ankle swings " +
                        fixed(std::isfinite(hi - lo) ? (hi - lo) / height : 0.0, 2) +
                        " of the walker's height about the pelvis (walking: > " + fixed(minLead, 2) + ")");
  }
  for (Eigen::Index r = 0; r < count; ++r) frames.row(r) *= scale[first + r];
  if (alongTheSightLine) evenSightLineSwing(frames, scale.segment(first, count));
  const double firstS = static_cast<double>(first) / t.rateHz;
  for (const auto& [side, strikes] : {std::pair{Side::Right, &g.rightStrikesS}, std::pair{Side::Left, &g.leftStrikesS}}) {
    *strikes = footStrikesFromKinematics(frames, t.rateHz, side);
    for (double& s : *strikes) s += firstS;
  }
  const double durationS = static_cast<double>(t.frameCount) / t.rateHz;
  const double feetSeenS = static_cast<double>(count) / t.rateHz;
  // The readings of a stride and a bit, for a walker who travels: across the picture, or
  // nearing or leaving the camera at a steady rate.
  const bool travels = crosses || (!g.inPlace && steadySizeChange(t) >= kMinSteadySizeChange);
  g.strikesStrideHz = strideHz(g.rightStrikesS, g.leftStrikesS, travels ? feetSeenS : INFINITY);
  if (travels && (g.strikesStrideHz < kMinStrideHz || g.strikesStrideHz > kMaxStrideHz))
    g.strikesStrideHz = ankleLeadsStrideHz(frames.col(3 * index(Joint::RAnkle) + 1) - frames.col(3 * index(Joint::LAnkle) + 1),
                                           t.rateHz)
                            .value_or(g.strikesStrideHz);
  g.strideHz = heldStrideHz.value_or(g.strikesStrideHz);
  if (g.strideHz < kMinStrideHz || g.strideHz > kMaxStrideHz)
    notWalking(t, prefix + "no regular foot strikes (" + std::to_string(g.rightStrikesS.size()) +
                      " right, " + std::to_string(g.leftStrikesS.size()) + " left at " +
                      fixed1(t.rateHz) + " fps" +
                      // A video's own rate (a track) is no guess to correct.
                      (t.rateAssumed ? ", assumed: give the video's --fps if it is not that)" : ")"));
  g.cycles = durationS * g.strideHz;
  if (g.cycles < kMinImageCycles)
    throw Error(ErrorKind::BadData, t.file, "",
                "shorter than a gait cycle (" + fixed(g.cycles, 2) + " cycles): at least " +
                    fixed(kMinImageCycles, 2) + " of one is needed");
  return g;
}

namespace {

constexpr double kBobSeenShare = 0.6;
constexpr std::size_t kBobMinJoints = 2;
// Walking cadence, 60-190 steps a minute: below, the trunk's slow drifts (a walker nearing
// the camera sinks in the image) would pass for a bob.
constexpr double kBobMinStrideHz = 0.5, kBobMaxStrideHz = 1.6;
constexpr double kBobStepHz = 0.005;

// A joint's vertical path (v, px) where it is seen, detrended by a parabola in time.
struct BobSamples {
  Eigen::VectorXd t, v;
};

std::optional<BobSamples> bobSamples(const Eigen::MatrixXd& px, Joint joint, double rateHz) {
  const Eigen::Index col = 2 * index(joint) + 1;
  std::vector<double> ts, vs;
  for (Eigen::Index f = 0; f < px.rows(); ++f)
    if (std::isfinite(px(f, col)))
      ts.push_back(static_cast<double>(f) / rateHz), vs.push_back(px(f, col));
  if (static_cast<double>(ts.size()) < kBobSeenShare * static_cast<double>(px.rows()) ||
      ts.size() < 8)
    return std::nullopt;
  BobSamples b{Eigen::Map<Eigen::VectorXd>(ts.data(), static_cast<Eigen::Index>(ts.size())),
               Eigen::Map<Eigen::VectorXd>(vs.data(), static_cast<Eigen::Index>(vs.size()))};
  // A parabola, not a line: a walker nearing the camera grows in the image as one over its
  // distance, a curve a line leaves behind to pass for a slow bob (read at a near-front view).
  Eigen::MatrixXd trend(b.t.size(), 3);
  trend.col(0).setOnes();
  trend.col(1) = b.t;
  trend.col(2) = b.t.array().square();
  b.v -= trend * trend.colPivHouseholderQr().solve(b.v);
  return b;
}

// The variance a sinusoid of frequency f explains in the samples (least squares).
double explained(const BobSamples& b, double f) {
  Eigen::MatrixXd basis(b.t.size(), 2);
  basis.col(0) = (2 * std::numbers::pi * f * b.t).array().sin();
  basis.col(1) = (2 * std::numbers::pi * f * b.t).array().cos();
  const Eigen::Matrix2d gram = basis.transpose() * basis;
  const Eigen::Vector2d rhs = basis.transpose() * b.v;
  if (std::abs(gram.determinant()) < 1e-12) return 0.0;
  return rhs.dot(gram.ldlt().solve(rhs));
}

// The ankles' leads swing in opposition once a stride: their difference's detrended path
// (a line through it taken out: a walker nearing the camera grows), fitted by a sinusoid over
// the bob's stride band; the frequency explaining most of it, when that is at least half its
// variance and the clip holds kMinImageCycles to kMaxShortClipStrides cycles of it.
std::optional<double> ankleLeadsStrideHz(const Eigen::VectorXd& rightMinusLeft, double rateHz) {
  const Eigen::Index n = rightMinusLeft.size();
  if (n < 8 || !rightMinusLeft.allFinite()) return std::nullopt;
  BobSamples b{Eigen::VectorXd::LinSpaced(n, 0.0, static_cast<double>(n - 1) / rateHz), rightMinusLeft};
  Eigen::MatrixXd trend(n, 2);
  trend.col(0).setOnes();
  trend.col(1) = b.t;
  b.v -= trend * trend.colPivHouseholderQr().solve(b.v);
  const double variance = b.v.squaredNorm();
  if (!(variance > 0.0)) return std::nullopt;
  double bestHz = 0.0, bestShare = 0.0;
  for (double f = kBobMinStrideHz; f <= kBobMaxStrideHz; f += kBobStepHz) {
    const double share = explained(b, f) / variance;
    if (share > bestShare) bestShare = share, bestHz = f;
  }
  const double strides = static_cast<double>(n) / rateHz * bestHz;
  if (bestShare < 0.5 || strides < kMinImageCycles || strides > kMaxShortClipStrides) return std::nullopt;
  return bestHz;
}

}  // namespace

Eigen::VectorXd imageHeightsPx(const Eigen::MatrixXd& px) {
  Eigen::VectorXd h(px.rows());
  for (Eigen::Index f = 0; f < px.rows(); ++f) {
    const double ankles = 0.5 * (px(f, 2 * index(Joint::LAnkle) + 1) + px(f, 2 * index(Joint::RAnkle) + 1));
    const double head = px(f, 2 * index(Joint::Head) + 1), sternum = px(f, 2 * index(Joint::Sternum) + 1);
    const double top = std::isfinite(head) ? head : sternum - 0.17 * (ankles - sternum);
    h[f] = ankles - top;
  }
  return h;
}

Eigen::Vector2d lineThroughFinite(const Eigen::VectorXd& x, const Eigen::VectorXd& t) {
  Eigen::Matrix2d a = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (Eigen::Index i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) continue;
    const Eigen::Vector2d row(1.0, t[i]);
    a += row * row.transpose();
    b += row * x[i];
  }
  return a.ldlt().solve(b);
}

std::optional<Eigen::Vector2d> imageDepthLine(const Eigen::MatrixXd& px, const Eigen::VectorXd& times) {
  const Eigen::VectorXd inverse =
      imageHeightsPx(px).unaryExpr([](double h) { return h > 0.0 ? 1.0 / h : std::numeric_limits<double>::quiet_NaN(); });
  if (inverse.array().isFinite().count() < 8) return std::nullopt;
  const Eigen::Vector2d line = lineThroughFinite(inverse, times);
  const double first = line[0] + line[1] * times[0], last = line[0] + line[1] * times[times.size() - 1];
  if (!line.allFinite() || !(first > 0.0) || !(last > 0.0)) return std::nullopt;
  return line;
}

std::optional<double> trunkBobStrideHz(const KeypointTrial& trial, double minShare) {
  std::vector<BobSamples> paths;
  double variance = 0.0;
  // The upper trunk only: a tracker's pelvis and hips, hidden under the thigh tops in a side
  // view, are dragged down by the near thigh once a stride (docs/TRACKING_DESIGN.md); the head, the
  // sternum and the shoulders bob with them and stay in sight.
  for (Joint j : {Joint::Head, Joint::Sternum, Joint::RShoulder, Joint::LShoulder}) {
    const auto b = bobSamples(trial.jointsPx, j, trial.rateHz);
    if (!b) continue;
    variance += b->v.squaredNorm();
    paths.push_back(*b);
  }
  if (paths.size() < kBobMinJoints || !(variance > 0.0)) return std::nullopt;
  std::vector<double> hz, share;
  for (double f = 2 * kBobMinStrideHz; f <= 2 * kBobMaxStrideHz; f += kBobStepHz) {
    double sum = 0.0;
    for (const BobSamples& b : paths) sum += explained(b, f);
    hz.push_back(f);
    share.push_back(sum / variance);
  }
  // A peak inside the band, not its edge: a share still rising at the edge belongs to something
  // slower or faster than a step (a tracker's hips dragged down by the thigh once a stride read
  // as a bob at the band's lower edge, half the stride).
  double bestHz = 0.0, bestShare = 0.0;
  for (std::size_t i = 1; i + 1 < share.size(); ++i)
    if (share[i] >= share[i - 1] && share[i] >= share[i + 1] && share[i] > bestShare)
      bestShare = share[i], bestHz = hz[i];
  const double durationS = static_cast<double>(trial.frameCount) / trial.rateHz;
  if (bestShare < minShare || durationS * bestHz < 2.0) return std::nullopt;
  return 0.5 * bestHz;
}

}  // namespace ew

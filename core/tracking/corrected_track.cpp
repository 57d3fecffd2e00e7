#include "core/tracking/corrected_track.h"

#include <cmath>
#include <vector>

#include "core/common/errors.h"
#include "core/common/skeleton.h"

namespace ew {
namespace {

struct Offset {
  int frame;
  Eigen::Vector2d px;
};

// The corrections of joint j that the detection has on their frame, as offsets from it.
std::vector<Offset> offsetsOf(const Eigen::Ref<const Eigen::MatrixXd>& detected, const Keyframes& corrections, int j) {
  std::vector<Offset> out;
  for (const Keyframe& k : corrections.keyframes) {
    if (k.frame < 0 || k.frame >= detected.rows() || k.jointsPx.size() != kDims2) continue;
    const Eigen::Vector2d mark(k.jointsPx(2 * j), k.jointsPx(2 * j + 1));
    const Eigen::Vector2d seen(detected(k.frame, 2 * j), detected(k.frame, 2 * j + 1));
    if (mark.allFinite() && seen.allFinite()) out.push_back({k.frame, mark - seen});
  }
  return out;  // keyframes come sorted by frame
}

// The offset at frame f: interpolated between the two corrections around it when they are
// within 2 spans of each other, else the nearer one's, fading over the span.
Eigen::Vector2d offsetAt(const std::vector<Offset>& offsets, int f, int span) {
  const Offset* before = nullptr;
  const Offset* after = nullptr;
  for (const Offset& o : offsets) {
    if (o.frame <= f) before = &o;
    if (o.frame >= f && !after) after = &o;
  }
  const auto fading = [&](const Offset* o) {
    const double d = std::abs(f - o->frame);
    return d >= span + 1 ? Eigen::Vector2d::Zero().eval() : ((1.0 - d / (span + 1.0)) * o->px).eval();
  };
  if (before && after && before != after && after->frame - before->frame <= 2 * span) {
    const double t = static_cast<double>(f - before->frame) / (after->frame - before->frame);
    return (1.0 - t) * before->px + t * after->px;
  }
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  if (before) sum += fading(before);
  if (after && after != before) sum += fading(after);
  return sum;
}

}  // namespace

Eigen::MatrixXd correctTrack(const Eigen::Ref<const Eigen::MatrixXd>& detectedPx, const Keyframes& corrections,
                             int spanFrames) {
  if (detectedPx.cols() != kDims2)
    throw Error(ErrorKind::BadArgument, corrections.video, "", "a track to correct needs frames × 30 pixels");
  if (spanFrames < 0) throw Error(ErrorKind::BadArgument, corrections.video, "", "a correction's span cannot be negative");
  Eigen::MatrixXd out = detectedPx;
  for (int j = 0; j < kJointCount; ++j) {
    const std::vector<Offset> offsets = offsetsOf(detectedPx, corrections, j);
    for (const Offset& o : offsets) {
      const int from = std::max(0, o.frame - spanFrames);
      const int to = std::min(static_cast<int>(out.rows()) - 1, o.frame + spanFrames);
      for (int f = from; f <= to; ++f) {
        if (!std::isfinite(detectedPx(f, 2 * j)) || !std::isfinite(detectedPx(f, 2 * j + 1))) continue;
        out.row(f).segment<2>(2 * j) = detectedPx.row(f).segment<2>(2 * j) + offsetAt(offsets, f, spanFrames).transpose();
      }
    }
    // A joint the detection lacks on a corrected frame: the mark there.
    for (const Keyframe& k : corrections.keyframes)
      if (k.frame >= 0 && k.frame < out.rows() && k.jointsPx.size() == kDims2 && std::isfinite(k.jointsPx(2 * j)) &&
          std::isfinite(k.jointsPx(2 * j + 1)) && !std::isfinite(detectedPx(k.frame, 2 * j)))
        out.row(k.frame).segment<2>(2 * j) = k.jointsPx.segment<2>(2 * j);
  }
  return out;
}

int correctTrial(KeypointTrial& trial, const Keyframes& corrections) {
  const int span = static_cast<int>(std::lround(kCorrectionSpanS * trial.rateHz));
  trial.jointsPx = correctTrack(trial.jointsPx, corrections, span);
  if (trial.jointConfidence.rows() == trial.jointsPx.rows())
    for (const Keyframe& key : corrections.keyframes)
      for (int j = 0; j < kJointCount && key.jointsPx.size() == kDims2 && key.frame >= 0 && key.frame < trial.jointConfidence.rows(); ++j)
        if (std::isfinite(key.jointsPx(2 * j))) trial.jointConfidence(key.frame, j) = 1.0;
  return span;
}

}  // namespace ew

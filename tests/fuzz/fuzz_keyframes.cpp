// libFuzzer harness: keyframe file text -> ew::parseKeyframes (core/tracking/keyframes.h), what
// `track --keyframes`, `reconstruct --corrections` and the viewer's Load keyframes read. Every
// file that parses is written back (formatKeyframes) and must read back to the same marks; it
// is checked against a 640 × 480 picture and a 90-frame video as a track checks it, and applied
// as corrections to a small detected track (core/tracking/corrected_track.h), as the viewer and
// `reconstruct --corrections` apply them. A typed ew::Error is the correct outcome; anything
// else is a finding (fuzz_common.h).

#include <cmath>
#include <cstdlib>
#include <limits>
#include <optional>
#include <string>

#include "core/tracking/corrected_track.h"
#include "core/tracking/keyframes.h"
#include "tests/fuzz/fuzz_common.h"

namespace {

// 90 frames × 15 joints of a detection drifting right, its left wrist lost on every tenth frame.
const Eigen::MatrixXd& smallTrack() {
  static const Eigen::MatrixXd track = [] {
    Eigen::MatrixXd px(90, 30);
    for (Eigen::Index f = 0; f < px.rows(); ++f)
      for (Eigen::Index c = 0; c < px.cols(); ++c) {
        const double frame = static_cast<double>(f), column = static_cast<double>(c);
        px(f, c) = c % 2 == 0 ? 100.0 + 3.0 * frame + column : 50.0 + 10.0 * column;
      }
    for (Eigen::Index f = 0; f < px.rows(); f += 10) px.block(f, 14, 1, 2).setConstant(std::numeric_limits<double>::quiet_NaN());
    return px;
  }();
  return track;
}

// The same marks, NaN where the other is NaN (a mark written and read back is the same double).
bool sameMarks(const ew::Keyframes& a, const ew::Keyframes& b) {
  if (a.video != b.video || a.keyframes.size() != b.keyframes.size()) return false;
  for (std::size_t k = 0; k < a.keyframes.size(); ++k) {
    const auto& x = a.keyframes[k];
    const auto& y = b.keyframes[k];
    if (x.frame != y.frame || x.jointsPx.size() != y.jointsPx.size()) return false;
    for (Eigen::Index i = 0; i < x.jointsPx.size(); ++i)
      if (!(x.jointsPx(i) == y.jointsPx(i) || (std::isnan(x.jointsPx(i)) && std::isnan(y.jointsPx(i))))) return false;
  }
  return true;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(ew::fuzz::asText(data, size));
  std::optional<ew::Keyframes> parsed;
  ew::fuzz::acceptTypedErrors([&] {
    parsed = ew::parseKeyframes(text, "fuzz.json");
    if (!sameMarks(*parsed, ew::parseKeyframes(ew::formatKeyframes(*parsed), "back.json"))) std::abort();
  });
  if (!parsed) return 0;
  ew::fuzz::acceptTypedErrors([&] { ew::checkMarksWithin(*parsed, 640, 480, "fuzz.json"); });
  ew::fuzz::acceptTypedErrors([&] { ew::checkKeyframesWithin(*parsed, 90, "fuzz.json"); });
  ew::fuzz::acceptTypedErrors([&] {
    const Eigen::MatrixXd corrected = ew::correctTrack(smallTrack(), *parsed, 7);
    if (corrected.rows() != smallTrack().rows() || corrected.cols() != smallTrack().cols()) std::abort();
  });
  return 0;
}

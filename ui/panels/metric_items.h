#pragma once
// The metrics strip's values (METHOD §7: E_a, E_r, MPJPE, the 2D residual, α or est. α; a
// keypoint clip's walk in metres and its reprojection error) as text, for the strip and for
// the captions of an exported video.

#include <string>
#include <vector>

namespace ew::ui {

struct AppState;

// Normal text, a good value, a bad one (an angle more than 10° off), or coefficients edited by hand.
enum class MetricTone { Normal, Good, Bad, Edited };

struct MetricItem {
  std::string label, value, note;
  MetricTone tone = MetricTone::Normal;
  // The value with its SD ("1.42 ± 0.06 m"), shown where the strip has room; "" if it has none.
  std::string withSd = {};
};

// Empty when the mode has none to show (explore mode, nothing reconstructed or fitted yet).
std::vector<MetricItem> metricItems(const AppState& s);

}  // namespace ew::ui

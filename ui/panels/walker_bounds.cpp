#include "ui/panels/walker_bounds.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/glm.hpp>

#include "ui/app/derived.h"
#include "ui/convert.h"

namespace ew::ui {

namespace {

// Grows a rectangle to points, through a camera into a view's pixels.
struct Bounds {
  const CameraMatrices& camera;
  ImVec2 p0, size;
  float lo[2]{std::numeric_limits<float>::max(), std::numeric_limits<float>::max()};
  float hi[2]{std::numeric_limits<float>::lowest(), std::numeric_limits<float>::lowest()};

  void add(const glm::vec3& p) {
    const glm::vec4 clip = camera.projection * camera.view * glm::vec4(p, 1.0f);
    if (clip.w <= 1e-6f || !std::isfinite(clip.x) || !std::isfinite(clip.y)) return;  // behind the eye
    const float x = p0.x + (0.5f + 0.5f * clip.x / clip.w) * size.x;
    const float y = p0.y + (0.5f - 0.5f * clip.y / clip.w) * size.y;
    lo[0] = std::min(lo[0], x), hi[0] = std::max(hi[0], x);
    lo[1] = std::min(lo[1], y), hi[1] = std::max(hi[1], y);
  }

  ImRect rect(float margin) const {
    if (lo[0] > hi[0]) return {p0, p0};
    return {ImVec2(lo[0] - margin, lo[1] - margin), ImVec2(hi[0] + margin, hi[1] + margin)};
  }
};

constexpr int kPhases = 24;

}  // namespace

ImRect walkerBounds3(std::initializer_list<const Eigen::VectorXd*> w, const CameraMatrices& camera, ImVec2 p0,
                     ImVec2 size, float marginPx) {
  Bounds b{camera, p0, size};
  for (const Eigen::VectorXd* walker : w) {
    if (!walker || walker->size() == 0) continue;
    for (int i = 0; i < kPhases; ++i)
      for (const glm::vec3& joint : toPose3(frameAtPhase(*walker, static_cast<double>(i) / kPhases))) b.add(joint);
  }
  return b.rect(marginPx);
}

ImRect trailBounds2(const Eigen::MatrixXd& trail, const CameraMatrices& camera, ImVec2 p0, ImVec2 size, float marginPx) {
  Bounds b{camera, p0, size};
  for (Eigen::Index i = 0; i < trail.rows(); ++i)
    for (Eigen::Index j = 0; j + 1 < trail.cols(); j += 2)
      b.add(glm::vec3(static_cast<float>(trail(i, j)), static_cast<float>(trail(i, j + 1)), 0.0f));
  return b.rect(marginPx);
}

}  // namespace ew::ui

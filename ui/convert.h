#pragma once
// The one seam between the three vector types of the viewer: Eigen (core's numbers),
// GLM (rendering) and ImVec2 (ImGui layout). core never sees GLM or ImGui.

#include <imgui.h>

#include <Eigen/Core>
#include <array>
#include <glm/glm.hpp>

#include "core/common/skeleton.h"

namespace ew::ui {

inline glm::vec3 toGlm(const Eigen::Vector3d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y()), static_cast<float>(v.z())};
}
inline glm::vec2 toGlm(const Eigen::Vector2d& v) {
  return {static_cast<float>(v.x()), static_cast<float>(v.y())};
}
inline Eigen::Vector3d toEigen(const glm::vec3& v) { return {v.x, v.y, v.z}; }
inline ImVec2 toImVec2(const glm::vec2& v) { return {v.x, v.y}; }
inline glm::vec2 toGlm(const ImVec2& v) { return {v.x, v.y}; }
inline ImVec4 toImVec4(const glm::vec4& v) { return {v.x, v.y, v.z, v.w}; }
inline ImU32 toImU32(const glm::vec4& v) { return ImGui::ColorConvertFloat4ToU32(toImVec4(v)); }

// One 3D pose: 15 joints (x, y, z, mm) from a joint-major 45-vector.
using Pose3 = std::array<glm::vec3, kJointCount>;
// One 2D pose: 15 joints (u, v, mm) from a joint-major 30-vector.
using Pose2 = std::array<glm::vec2, kJointCount>;

template <class Derived>
Pose3 toPose3(const Eigen::DenseBase<Derived>& frame45) {
  Pose3 pose{};
  for (int j = 0; j < kJointCount; ++j) {
    pose[static_cast<std::size_t>(j)] = {static_cast<float>(frame45(3 * j)),
                                         static_cast<float>(frame45(3 * j + 1)),
                                         static_cast<float>(frame45(3 * j + 2))};
  }
  return pose;
}

template <class Derived>
Pose2 toPose2(const Eigen::DenseBase<Derived>& frame30) {
  Pose2 pose{};
  for (int j = 0; j < kJointCount; ++j) {
    pose[static_cast<std::size_t>(j)] = {static_cast<float>(frame30(2 * j)),
                                         static_cast<float>(frame30(2 * j + 1))};
  }
  return pose;
}

}  // namespace ew::ui

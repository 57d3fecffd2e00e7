#include "ui/render/camera.h"

#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

namespace ew::ui {

OrbitCamera OrbitCamera::preset(CameraPreset preset) {
  OrbitCamera c;
  switch (preset) {
    case CameraPreset::ThreeQuarter:
      break;
    case CameraPreset::Front:
      c.yawDeg = 0.0f;
      c.pitchDeg = 4.0f;
      break;
    case CameraPreset::Side:
      c.yawDeg = 90.0f;
      c.pitchDeg = 4.0f;
      break;
    case CameraPreset::Top:
      c.yawDeg = 0.0f;
      c.pitchDeg = 89.0f;
      c.distanceMm = 5600.0f;
      c.target = {0.0f, 0.0f, 400.0f};
      break;
  }
  return c;
}

glm::vec3 OrbitCamera::eye() const {
  const float yaw = glm::radians(yawDeg);
  const float pitch = glm::radians(pitchDeg);
  const glm::vec3 dir{std::cos(pitch) * std::sin(yaw), std::cos(pitch) * std::cos(yaw),
                      std::sin(pitch)};
  return target + distanceMm * dir;
}

CameraMatrices OrbitCamera::matrices(float aspect) const {
  CameraMatrices m;
  const glm::vec3 e = eye();
  // Looking straight down, "up" on screen is the walking direction.
  const glm::vec3 up = pitchDeg > 88.0f ? glm::vec3(0.0f, 1.0f, 0.0f) : glm::vec3(0.0f, 0.0f, 1.0f);
  m.view = glm::lookAt(e, target, up);
  m.projection = glm::perspective(glm::radians(fovDeg), std::max(aspect, 0.01f),
                                  std::max(50.0f, distanceMm * 0.05f), distanceMm * 4.0f + 8000.0f);
  m.orthographic = false;
  return m;
}

void OrbitCamera::orbit(float dxPx, float dyPx) {
  yawDeg = std::fmod(yawDeg + 0.35f * dxPx + 540.0f, 360.0f) - 180.0f;
  pitchDeg = std::clamp(pitchDeg + 0.3f * dyPx, -10.0f, 89.0f);
}

void OrbitCamera::pan(float dxPx, float dyPx, float viewHeightPx) {
  const CameraMatrices m = matrices(1.0f);
  const glm::vec3 right{m.view[0][0], m.view[1][0], m.view[2][0]};
  const glm::vec3 up{m.view[0][1], m.view[1][1], m.view[2][1]};
  const float mmPerPx =
      2.0f * distanceMm * std::tan(glm::radians(fovDeg) * 0.5f) / std::max(viewHeightPx, 1.0f);
  target += (-dxPx * right + dyPx * up) * mmPerPx;
}

void OrbitCamera::zoom(float wheelSteps) {
  distanceMm = std::clamp(distanceMm * std::pow(0.88f, wheelSteps), 800.0f, 20000.0f);
}

CameraMatrices imageCamera(float aspect, glm::vec2 centreMm, float heightMm) {
  CameraMatrices m;
  const float h = 0.5f * heightMm;
  const float w = h * std::max(aspect, 0.01f);
  m.view = glm::mat4(1.0f);
  m.projection = glm::ortho(centreMm.x - w, centreMm.x + w, centreMm.y - h, centreMm.y + h,
                            -5000.0f, 5000.0f);
  m.orthographic = true;
  return m;
}

}  // namespace ew::ui

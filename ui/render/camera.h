#pragma once
// Cameras of the two views. The 3D view orbits a target (yaw about the vertical axis,
// pitch above the floor, distance); the 2D view is an orthographic image-plane camera
// (u to the right, v up, both mm) — exactly the coordinates of METHOD §5.

#include <glm/glm.hpp>

#include "ui/render/scene.h"

namespace ew::ui {

enum class CameraPreset { ThreeQuarter, Front, Side, Top };

struct OrbitCamera {
  // yaw 0: the camera stands in front of the walker (+y) looking back at it; 90: on the
  // walker's right (+x).
  float yawDeg = 52.0f;
  float pitchDeg = 14.0f;
  float distanceMm = 5300.0f;
  float fovDeg = 32.0f;
  glm::vec3 target{0.0f, 0.0f, 820.0f};

  bool operator==(const OrbitCamera&) const = default;

  static OrbitCamera preset(CameraPreset preset);
  glm::vec3 eye() const;
  CameraMatrices matrices(float aspect) const;
  // Mouse interaction, in pixels of the view.
  void orbit(float dxPx, float dyPx);
  void pan(float dxPx, float dyPx, float viewHeightPx);
  void zoom(float wheelSteps);
};

// Orthographic camera for the image plane: centre (u, v) and the visible height, mm.
CameraMatrices imageCamera(float aspect, glm::vec2 centreMm, float heightMm);

}  // namespace ew::ui

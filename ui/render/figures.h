#pragma once
// Scene builders: a walker's pose as joints and bones, the 2D input as point-lights,
// error lines, the camera glyph. Pure functions that append instances to a Scene.

#include <optional>
#include <span>

#include "ui/convert.h"
#include "ui/render/scene.h"

namespace ew::ui {

enum class FigureLayer { Opaque, Ghost };

struct FigureStyle {
  glm::vec4 right, left, mid;    // colours of right-side, left-side and midline parts
  float boneRadiusMm = 17.0f;
  float jointRadiusMm = 27.0f;
  float headRadiusMm = 95.0f;
  FigureLayer layer = FigureLayer::Opaque;
};

FigureStyle reconstructionStyle();
FigureStyle ghostStyle();

// Joints and bones of a 3D pose. jointColours (15), when given, colour the joints.
void addFigure(Scene& scene, const Pose3& pose, const FigureStyle& style,
               std::optional<std::span<const glm::vec4, kJointCount>> jointColours = std::nullopt);

// A 2D pose (u, v in mm) drawn in the image plane (z = 0): point-lights and, optionally,
// thin bones. pointRadiusMm is the glow's radius.
void addPointLights(Scene& scene, const Pose2& pose, float pointRadiusMm, bool bones,
                    float boneWidthPx);

// 2D polyline of a joint's path (trail) through the image plane.
void addPolyline2(Scene& scene, std::span<const glm::vec2> points, const glm::vec4& colour,
                  float widthPx, bool closed);

// Lines joining each joint of `from` to the same joint of `to` (3D), on top.
void addErrorLines(Scene& scene, const Pose3& from, const Pose3& to, const glm::vec4& colour,
                   float widthPx);

// A camera on the floor at `radiusMm`, looking at the walker from view angle α (SPEC §5:
// it sees u = x cos α + y sin α to the right), with a dashed sight line.
void addCameraGlyph(Scene& scene, double alphaDeg, float radiusMm, const glm::vec4& colour,
                    bool dashed);

}  // namespace ew::ui

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
// Compare mode: engine `index` of kEngineKinds in its own colour, a little thinner.
FigureStyle engineStyle(int index);
FigureStyle ghostStyle();

// Joints and bones of a 3D pose. jointColours (15), when given, colour the joints.
void addFigure(Scene& scene, const Pose3& pose, const FigureStyle& style,
               std::optional<std::span<const glm::vec4, kJointCount>> jointColours = std::nullopt);

// A foot's heel and toe beside a pose (FootPoint order; nullopt where unknown): ankle → heel →
// toe → ankle, a little thinner than the bones, in the side's colour.
using FootPoints3 = std::array<std::optional<glm::vec3>, 4>;
void addFeet(Scene& scene, const Pose3& pose, const FootPoints3& feet, const FigureStyle& style);

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

// A camera on the floor at `radiusMm`, looking at the walker from view angle α (METHOD §5:
// it sees u = x cos α + y sin α to the right), with a dashed sight line.
void addCameraGlyph(Scene& scene, double alphaDeg, float radiusMm, const glm::vec4& colour,
                    bool dashed);

// A real camera standing at `eye` (mm), its axes right / down / forward (unit, the image's
// u, v and optical axis), drawn as a body with a lens; `rays` (direction vectors, each
// reaching as far as it should) are drawn from the eye as its field of view, and a dashed
// line drops from the eye to the floor to show its height.
struct CameraPose {
  glm::vec3 eye{0.0f}, right{1.0f, 0.0f, 0.0f}, down{0.0f, 0.0f, -1.0f}, forward{0.0f, 1.0f, 0.0f};
};
void addRealCameraGlyph(Scene& scene, const CameraPose& pose, std::span<const glm::vec3> rays,
                        const glm::vec4& colour, float lineScale);

}  // namespace ew::ui

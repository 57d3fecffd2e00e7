#include "ui/render/figures.h"

#include <algorithm>

#include <array>
#include <cmath>

#include "ui/render/palette.h"

namespace ew::ui {

namespace {

enum class Side { Right, Left, Mid };

Side sideOf(Joint j) {
  switch (j) {
    case Joint::RShoulder:
    case Joint::RElbow:
    case Joint::RWrist:
    case Joint::RHip:
    case Joint::RKnee:
    case Joint::RAnkle:
      return Side::Right;
    case Joint::LShoulder:
    case Joint::LElbow:
    case Joint::LWrist:
    case Joint::LHip:
    case Joint::LKnee:
    case Joint::LAnkle:
      return Side::Left;
    default:
      return Side::Mid;
  }
}

const glm::vec4& colourFor(const FigureStyle& s, Side side) {
  return side == Side::Right ? s.right : side == Side::Left ? s.left : s.mid;
}

// A bone takes the side of its distal joint (the pelvis → hip bones are the hip's side).
Side boneSide(Joint a, Joint b) {
  const Side sb = sideOf(b);
  return sb != Side::Mid ? sb : sideOf(a);
}

}  // namespace

FigureStyle reconstructionStyle() {
  return {palette::kReconRight, palette::kReconLeft, palette::kReconMid};
}

FigureStyle engineStyle(int index) {
  const glm::vec4 right = palette::kEngineRight[static_cast<std::size_t>(std::clamp(index, 0, 2))];
  FigureStyle s{right, palette::engineLighter(right, 0.45f), palette::engineLighter(right, 0.22f)};
  s.boneRadiusMm = 14.0f;
  s.jointRadiusMm = 22.0f;
  s.headRadiusMm = 85.0f;
  return s;
}

FigureStyle ghostStyle() {
  FigureStyle s{palette::kGhostRight, palette::kGhostLeft, palette::kGhostMid};
  s.boneRadiusMm = 26.0f;
  s.jointRadiusMm = 34.0f;
  s.headRadiusMm = 104.0f;
  s.layer = FigureLayer::Ghost;
  return s;
}

void addFigure(Scene& scene, const Pose3& pose, const FigureStyle& style,
               std::optional<std::span<const glm::vec4, kJointCount>> jointColours) {
  auto& tubes = style.layer == FigureLayer::Ghost ? scene.ghostTubes : scene.tubes;
  auto& spheres = style.layer == FigureLayer::Ghost ? scene.ghostSpheres : scene.spheres;
  for (const auto& [ja, jb] : kBones) {
    const auto a = static_cast<std::size_t>(index(ja));
    const auto b = static_cast<std::size_t>(index(jb));
    tubes.push_back({pose[a], style.boneRadiusMm, pose[b], 0.0f, colourFor(style, boneSide(ja, jb))});
  }
  for (int j = 0; j < kJointCount; ++j) {
    const auto ju = static_cast<std::size_t>(j);
    const Joint joint = static_cast<Joint>(j);
    glm::vec4 colour = colourFor(style, sideOf(joint));
    if (jointColours) {
      const glm::vec3 c((*jointColours)[ju]);
      // The head is large: tint it rather than paint it.
      colour = glm::vec4(joint == Joint::Head ? glm::mix(glm::vec3(colour), c, 0.55f) : c, colour.a);
    }
    float radius = style.jointRadiusMm;
    if (joint == Joint::Head) radius = style.headRadiusMm;
    if (joint == Joint::Pelvis || joint == Joint::Sternum) radius *= 1.15f;
    spheres.push_back({pose[ju], radius, colour});
  }
}

void addFeet(Scene& scene, const Pose3& pose, const FootPoints3& feet, const FigureStyle& style) {
  auto& tubes = style.layer == FigureLayer::Ghost ? scene.ghostTubes : scene.tubes;
  auto& spheres = style.layer == FigureLayer::Ghost ? scene.ghostSpheres : scene.spheres;
  const float radius = 0.7f * style.boneRadiusMm;
  for (const bool right : {true, false}) {
    const auto& heel = feet[right ? 0 : 2];
    const auto& toe = feet[right ? 1 : 3];
    const glm::vec3 ankle = pose[static_cast<std::size_t>(index(right ? Joint::RAnkle : Joint::LAnkle))];
    const glm::vec4 colour = right ? style.right : style.left;
    if (heel) tubes.push_back({ankle, radius, *heel, 0.0f, colour});
    if (toe) tubes.push_back({ankle, radius, *toe, 0.0f, colour});
    if (heel && toe) tubes.push_back({*heel, radius, *toe, 0.0f, colour});
    for (const auto& p : {heel, toe})
      if (p) spheres.push_back({*p, radius * 1.3f, colour});
  }
}

void addPointLights(Scene& scene, const Pose2& pose, float pointRadiusMm, bool bones,
                    float boneWidthPx) {
  if (bones) {
    for (const auto& [ja, jb] : kBones) {
      const auto a = static_cast<std::size_t>(index(ja));
      const auto b = static_cast<std::size_t>(index(jb));
      const glm::vec4 colour = boneSide(ja, jb) == Side::Left ? palette::kInputBoneLeft
                                                              : palette::kInputBoneRight;
      scene.lines.push_back({glm::vec3(pose[a], 0.0f), boneWidthPx, glm::vec3(pose[b], 0.0f), 0.0f,
                             colour});
    }
  }
  for (const auto& p : pose) scene.glows.push_back({glm::vec3(p, 0.0f), pointRadiusMm, palette::kInputPoint});
}

void addPolyline2(Scene& scene, std::span<const glm::vec2> points, const glm::vec4& colour,
                  float widthPx, bool closed) {
  if (points.size() < 2) return;
  const std::size_t n = points.size();
  const std::size_t segments = closed ? n : n - 1;
  for (std::size_t i = 0; i < segments; ++i) {
    scene.lines.push_back({glm::vec3(points[i], -1.0f), widthPx,
                           glm::vec3(points[(i + 1) % n], -1.0f), 0.0f, colour});
  }
}

void addErrorLines(Scene& scene, const Pose3& from, const Pose3& to, const glm::vec4& colour,
                   float widthPx) {
  for (std::size_t j = 0; j < from.size(); ++j)
    scene.overlayLines.push_back({from[j], widthPx, to[j], 0.0f, colour});
}

void addCameraGlyph(Scene& scene, double alphaDeg, float radiusMm, const glm::vec4& colour,
                    bool dashed) {
  const float a = glm::radians(static_cast<float>(alphaDeg));
  // Depth direction d = (−sin α, cos α, 0); the camera looks along +d from −d · R.
  const glm::vec3 look{-std::sin(a), std::cos(a), 0.0f};
  const glm::vec3 right{std::cos(a), std::sin(a), 0.0f};  // image u
  const glm::vec3 up{0.0f, 0.0f, 1.0f};
  const glm::vec3 pos = -look * radiusMm + up * 10.0f;
  const float w = 1.0f * 160.0f, h = 1.0f * 110.0f, len = 220.0f;
  auto line = [&](glm::vec3 p, glm::vec3 q, float width, float dash) {
    scene.lines.push_back({p, width, q, dash, colour});
  };
  // Body: a box behind the lens, frustum towards the walker.
  const glm::vec3 c = pos + up * 140.0f;
  const glm::vec3 back = c - look * len;
  std::array<glm::vec3, 4> front{c + right * w * 0.5f + up * h * 0.5f, c - right * w * 0.5f + up * h * 0.5f,
                                 c - right * w * 0.5f - up * h * 0.5f, c + right * w * 0.5f - up * h * 0.5f};
  std::array<glm::vec3, 4> rear{};
  for (std::size_t i = 0; i < 4; ++i) rear[i] = back + (front[i] - c) * 0.75f;
  for (std::size_t i = 0; i < 4; ++i) {
    line(front[i], front[(i + 1) % 4], 2.0f, 0.0f);
    line(rear[i], rear[(i + 1) % 4], 2.0f, 0.0f);
    line(front[i], rear[i], 2.0f, 0.0f);
  }
  // Lens frustum opening towards the walker.
  const glm::vec3 apex = c + look * 20.0f;
  for (std::size_t i = 0; i < 4; ++i) {
    const glm::vec3 tip = apex + look * 180.0f + (front[i] - c) * 1.7f;
    line(apex + (front[i] - c) * 0.4f, tip, 2.0f, 0.0f);
  }
  // "Up" tick on the image's right edge, so a mirrored image would be visible.
  line(front[0], front[0] + right * 50.0f, 3.0f, 0.0f);
  // Sight line along the floor to the walker.
  line(pos + look * 80.0f, glm::vec3(0.0f, 0.0f, 5.0f), 1.5f, dashed ? 6.0f : 10.0f);
}

void addRealCameraGlyph(Scene& scene, const CameraPose& pose, std::span<const glm::vec3> rays,
                        const glm::vec4& colour, float lineScale) {
  auto line = [&](glm::vec3 p, glm::vec3 q, float width, float dash, glm::vec4 c) {
    scene.lines.push_back({p, width * lineScale, q, dash, c});
  };
  const glm::vec3 up = -pose.down;
  const float w = 190.0f, h = 130.0f, len = 260.0f;
  // Body behind the eye, lens in front of it.
  const glm::vec3 c = pose.eye - pose.forward * 40.0f;
  const glm::vec3 back = c - pose.forward * len;
  const std::array<glm::vec3, 4> corner{pose.right * w * 0.5f + up * h * 0.5f, -pose.right * w * 0.5f + up * h * 0.5f,
                                        -pose.right * w * 0.5f - up * h * 0.5f, pose.right * w * 0.5f - up * h * 0.5f};
  for (std::size_t i = 0; i < 4; ++i) {
    line(c + corner[i], c + corner[(i + 1) % 4], 2.0f, 0.0f, colour);
    line(back + corner[i], back + corner[(i + 1) % 4], 2.0f, 0.0f, colour);
    line(c + corner[i], back + corner[i], 2.0f, 0.0f, colour);
    line(c + corner[i] * 0.45f, pose.eye + pose.forward * 120.0f + corner[i] * 0.8f, 2.0f, 0.0f, colour);
  }
  // "Up" tick on the image's top edge, so that a mirrored or rolled image would show.
  line(c + corner[0], c + corner[0] + up * 60.0f, 3.0f, 0.0f, colour);
  const glm::vec4 faint(glm::vec3(colour), 0.45f);
  for (const glm::vec3& r : rays) line(pose.eye, pose.eye + r, 1.5f, 0.0f, faint);
  // Height above the floor.
  line(pose.eye, glm::vec3(pose.eye.x, pose.eye.y, 0.0f), 1.5f, 8.0f, faint);
}

}  // namespace ew::ui

#include "ui/panels/clip_view.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include "core/eigenwalker/projection.h"
#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/render/figures.h"
#include "ui/render/palette.h"

namespace ew::ui {

namespace {

// A pixel (u, v) as a scene point of the 2D view (y up on screen: −v).
glm::vec2 scenePoint(double u, double v) { return {static_cast<float>(u), static_cast<float>(-v)}; }

bool seen(const Eigen::MatrixXd& px, int frame, int joint) {
  return std::isfinite(px(frame, 2 * joint)) && std::isfinite(px(frame, 2 * joint + 1));
}

glm::vec2 pointAt(const Eigen::MatrixXd& px, int frame, int joint) {
  return scenePoint(px(frame, 2 * joint), px(frame, 2 * joint + 1));
}

// Each seen joint's path over the last stride before `frame`, fading with age (the whole
// clip's paths would bury the walker of a long clip), broken where it is not seen.
void addInputTrails(Scene& scene, const Eigen::MatrixXd& px, int frame, int span, float width) {
  const int first = std::max(1, frame - span);
  for (int j = 0; j < kJointCount; ++j) {
    for (int b = first; b <= frame; ++b) {
      const int a = b - 1;
      if (!seen(px, a, j) || !seen(px, b, j)) continue;
      const float age = static_cast<float>(frame - b) / static_cast<float>(std::max(span, 1));
      glm::vec4 colour = palette::kTrail;
      colour.a *= 1.6f * (1.0f - age);
      scene.lines.push_back({glm::vec3(pointAt(px, a, j), -1.0f), width, glm::vec3(pointAt(px, b, j), -1.0f), 0.0f,
                             colour});
    }
  }
}

// The input joints at `frame` (bones between seen joints), as point-lights.
void addInputPose(Scene& scene, const Eigen::MatrixXd& px, int frame, float radiusPx, bool bones, float width) {
  if (bones) {
    for (const auto& [ja, jb] : kBones) {
      if (!seen(px, frame, index(ja)) || !seen(px, frame, index(jb))) continue;
      const bool left = ja == Joint::LShoulder || ja == Joint::LElbow || ja == Joint::LHip || ja == Joint::LKnee ||
                        jb == Joint::LShoulder || jb == Joint::LElbow || jb == Joint::LWrist || jb == Joint::LHip ||
                        jb == Joint::LKnee || jb == Joint::LAnkle;
      scene.lines.push_back({glm::vec3(pointAt(px, frame, index(ja)), 0.0f), width,
                             glm::vec3(pointAt(px, frame, index(jb)), 0.0f), 0.0f,
                             left ? palette::kInputBoneLeft : palette::kInputBoneRight});
    }
  }
  for (int j = 0; j < kJointCount; ++j)
    if (seen(px, frame, j)) scene.glows.push_back({glm::vec3(pointAt(px, frame, j), 0.0f), radiusPx, palette::kInputPoint});
}

// The people not fitted, as thin bones between their seen joints: so the user sees whom the
// person picker offers.
void addOtherPeople(Scene& scene, const KeypointTrial& trial, int frame, float radiusPx, float width) {
  for (const OtherPerson& o : otherPeopleAt(trial, frame)) {
    const PersonTrack& person = trial.people[static_cast<std::size_t>(o.track - 1)];
    const int row = personRowAt(person, frame);
    const Eigen::MatrixXd& px = person.jointsPx;
    for (const auto& [ja, jb] : kBones) {
      if (!seen(px, row, index(ja)) || !seen(px, row, index(jb))) continue;
      scene.lines.push_back({glm::vec3(pointAt(px, row, index(ja)), -0.5f), width,
                             glm::vec3(pointAt(px, row, index(jb)), -0.5f), 0.0f, palette::kOtherPerson});
    }
    for (int j = 0; j < kJointCount; ++j)
      if (seen(px, row, j)) scene.glows.push_back({glm::vec3(pointAt(px, row, j), -0.5f), radiusPx, palette::kOtherPerson});
  }
}

// The reprojected walker's bones and, for each seen joint, the residual to the input.
void addReprojection(Scene& scene, const ClipReconstruction& rec, int frame, float lineScale) {
  const Eigen::MatrixXd& re = rec.reprojectedPx;
  for (const auto& [ja, jb] : kBones) {
    if (!seen(re, frame, index(ja)) || !seen(re, frame, index(jb))) continue;
    scene.overlayLines.push_back({glm::vec3(pointAt(re, frame, index(ja)), 1.0f), 2.0f * lineScale,
                                  glm::vec3(pointAt(re, frame, index(jb)), 1.0f), 0.0f,
                                  glm::vec4(glm::vec3(palette::kReconRight), 0.9f)});
  }
  for (int j = 0; j < kJointCount; ++j) {
    if (!seen(rec.trial.jointsPx, frame, j) || !seen(re, frame, j)) continue;
    scene.overlayLines.push_back({glm::vec3(pointAt(rec.trial.jointsPx, frame, j), 1.0f), 2.0f * lineScale,
                                  glm::vec3(pointAt(re, frame, j), 1.0f), 0.0f, palette::kError});
  }
}

// Rays from the camera through the corners of the image region the walker crosses, reaching
// the look-at point's depth: the part of the field of view the clip uses.
std::vector<glm::vec3> viewRays(const ClipResult& clip, const ClipWorld& w) {
  const WalkCamera& c = clip.rec.fit.camera;
  const PixelBounds& b = clip.keypointBounds;
  if (b.empty) return {};
  const double u0 = b.low.x(), u1 = b.high.x(), v0 = b.low.y(), v1 = b.high.y();
  const float depth = static_cast<float>(c.distanceMm);
  std::vector<glm::vec3> rays;
  for (const double u : {u0, u1}) {
    for (const double v : {v0, v1}) {
      const float x = static_cast<float>((u - c.cxPx) / c.focalPx), y = static_cast<float>((v - c.cyPx) / c.focalPx);
      rays.push_back(depth * (w.forward + x * w.right + y * w.down));
    }
  }
  return rays;
}

// The heels and toes lifted from the image (core/camera/lifted_feet.h) at a frame, where the
// walker stands in the clip's world; none where a point was not lifted.
FootPoints3 liftedFeetAt(const ClipReconstruction& rec, int frame, const glm::vec3& walkerOffset) {
  FootPoints3 feet{};
  const Eigen::MatrixXd& m = rec.feet.feetMm;
  if (frame < 0 || frame >= m.rows()) return feet;
  for (int p = 0; p < kFootPointCount; ++p) {
    const Eigen::Vector3d v = m.row(frame).segment<3>(3 * p).transpose();
    if (v.allFinite()) feet[static_cast<std::size_t>(p)] = toGlm(v) + walkerOffset;
  }
  return feet;
}

}  // namespace

std::vector<OtherPerson> otherPeopleAt(const KeypointTrial& trial, int frame) {
  std::vector<OtherPerson> out;
  for (std::size_t i = 0; i < trial.people.size(); ++i) {
    if (static_cast<int>(i) == trial.chosen) continue;
    const PersonTrack& person = trial.people[i];
    const int row = personRowAt(person, frame);
    if (row < 0 || person.jointsPx.rows() <= row) continue;
    OtherPerson o{static_cast<int>(i) + 1, {}};
    bool any = false;
    for (int j = 0; j < kJointCount; ++j) {
      if (!seen(person.jointsPx, row, j)) continue;
      const glm::vec2 p = pointAt(person.jointsPx, row, j);
      if (!any || p.y > o.top.y) o.top = p;  // scene y runs up: the highest point
      any = true;
    }
    if (any) out.push_back(o);
  }
  return out;
}

ClipWorld clipWorld(const ClipResult& clip, int frame) {
  const WalkCamera& c = clip.rec.fit.camera;
  const double mid = 0.5 * clip.durationS();
  const double t = clip.rec.timesS.size() > frame ? clip.rec.timesS[frame] : 0.0;
  // Origin: where the walker's canonical origin stands mid-clip.
  const Eigen::Vector3d lookAt = -walkerOriginFromLookAt(c, mid);
  ClipWorld w;
  w.pinhole = c.model == CameraModel::Pinhole;
  w.lookAt = toGlm(lookAt);
  w.eye = toGlm(Eigen::Vector3d(lookAt + cameraFromLookAt(c)));
  w.walkerOffset = toGlm(Eigen::Vector3d(walkerOriginFromLookAt(c, t) - walkerOriginFromLookAt(c, mid)));
  const double a = degToRad(c.alphaDeg), e = degToRad(c.elevationDeg);
  const glm::vec3 depth(static_cast<float>(-std::sin(a)), static_cast<float>(std::cos(a)), 0.0f);
  const glm::vec3 up(0.0f, 0.0f, 1.0f);
  const float se = static_cast<float>(std::sin(e)), ce = static_cast<float>(std::cos(e));
  w.right = {static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0.0f};
  w.down = -(se * depth + ce * up);   // Y_c (docs/CAMERA.md)
  w.forward = ce * depth - se * up;   // Z_c
  return w;
}

OrbitCamera clipViewCamera(const OrbitCamera& camera, const ClipResult& clip, int frame) {
  OrbitCamera c = camera;
  const glm::vec3 walker = clipWorld(clip, frame).walkerOffset;
  c.target += glm::vec3(walker.x, walker.y, 0.0f);
  return c;
}

ClipImageFrame clipImageFrame(const ClipResult& clip, float aspect) {
  const PixelBounds& b = clip.shownBounds;
  if (b.empty) return {};
  // Scene coordinates run up the screen: v is negated.
  const glm::vec2 lo = scenePoint(b.low.x(), b.high.y()), hi = scenePoint(b.high.x(), b.low.y());
  ClipImageFrame frame;
  frame.centre = 0.5f * (lo + hi);
  const glm::vec2 size = hi - lo;
  // Room for the caption above and the legend below.
  frame.heightPx = std::max({size.y * 1.45f, size.x * 1.12f / std::max(aspect, 0.1f), 50.0f});
  frame.centre.y -= 0.04f * frame.heightPx;
  return frame;
}

CameraMatrices clipInputCamera(const ClipImageFrame& frame, float aspect) {
  return imageCamera(aspect, frame.centre, frame.heightPx);
}

bool buildClipInputScene(const AppState& s, Scene& scene, float lineScale, int frame, const ClipImageFrame& view) {
  scene.clearItems();
  scene.floor.visible = false;
  scene.backgroundTop = {0.085f, 0.09f, 0.105f, 1.0f};
  scene.backgroundBottom = {0.04f, 0.045f, 0.055f, 1.0f};
  if (!s.clip.fit()) return false;
  const ClipReconstruction& rec = s.clip.fit()->rec;
  const auto& o = s.view.overlays;
  // Point-lights a fixed share of the view, whatever the image's resolution.
  const float glow = 0.012f * view.heightPx;
  if (o.trails && !o.pointLights) {
    const int stride = static_cast<int>(rec.trial.rateHz / std::max(rec.fit.strideHz, 0.1));
    addInputTrails(scene, rec.trial.jointsPx, frame, stride, 1.5f * lineScale);
  }
  if (!o.pointLights) addOtherPeople(scene, rec.trial, frame, 0.6f * glow, 1.5f * lineScale);
  addInputPose(scene, rec.trial.jointsPx, frame, glow, o.stickFigure && !o.pointLights, 2.5f * lineScale);
  if (o.reprojection && !o.pointLights) addReprojection(scene, rec, frame, lineScale);
  // The estimated principal point (where the optical axis meets the image).
  const glm::vec2 c = scenePoint(rec.fit.camera.cxPx, rec.fit.camera.cyPx);
  const float arm = 2.0f * glow;
  const glm::vec4 cross(glm::vec3(palette::kCamera), 0.7f);
  scene.lines.push_back({glm::vec3(c - glm::vec2(arm, 0.0f), -1.5f), 1.5f * lineScale,
                         glm::vec3(c + glm::vec2(arm, 0.0f), -1.5f), 0.0f, cross});
  scene.lines.push_back({glm::vec3(c - glm::vec2(0.0f, arm), -1.5f), 1.5f * lineScale,
                         glm::vec3(c + glm::vec2(0.0f, arm), -1.5f), 0.0f, cross});
  return true;
}

bool buildClipReconstructionScene(const AppState& s, Scene& scene, float lineScale, int frame) {
  scene.clearItems();
  if (!s.clip.fit()) return false;
  const ClipResult& clip = *s.clip.fit();
  const ClipReconstruction& rec = clip.rec;
  const auto& o = s.view.overlays;
  const ClipWorld w = clipWorld(clip, frame);
  Pose3 pose = toPose3(rec.framesMm.row(frame));
  for (auto& p : pose) p += w.walkerOffset;
  const glm::vec3 pelvis = pose[static_cast<std::size_t>(index(Joint::Pelvis))];
  scene.floor.visible = o.grid;
  scene.floor.scrollMm = 0.0f;  // the walker crosses a fixed floor
  scene.floor.shadowCentre = {pelvis.x, pelvis.y};
  scene.floor.extentMm = std::clamp(std::max(std::abs(w.eye.x), std::abs(w.eye.y)) + 1000.0f, 3200.0f, 12000.0f);
  std::array<glm::vec4, kJointCount> colours{};
  for (int j = 0; j < kJointCount; ++j) {
    const bool unseen = std::find(rec.fit.unseenJoints.begin(), rec.fit.unseenJoints.end(), j) != rec.fit.unseenJoints.end();
    colours[static_cast<std::size_t>(j)] = unseen ? palette::kModelEstimated : palette::kReconMid;
  }
  if (o.pointLights) {
    for (const auto& p : pose) scene.glows.push_back({p, 34.0f, palette::kInputPoint});
  } else if (rec.fit.unseenJoints.empty()) {
    addFigure(scene, pose, reconstructionStyle());
  } else {
    addFigure(scene, pose, reconstructionStyle(), std::span<const glm::vec4, kJointCount>(colours));
  }
  if (!o.pointLights) addFeet(scene, pose, liftedFeetAt(rec, frame, w.walkerOffset), reconstructionStyle());
  // The walker's path over the clip, on the floor.
  const ClipWorld first = clipWorld(clip, 0), last = clipWorld(clip, rec.trial.frameCount - 1);
  scene.lines.push_back({glm::vec3(first.walkerOffset.x, first.walkerOffset.y, 3.0f), 2.0f * lineScale,
                         glm::vec3(last.walkerOffset.x, last.walkerOffset.y, 3.0f), 10.0f * lineScale,
                         glm::vec4(glm::vec3(palette::kReconMid), 0.6f)});
  if (o.cameraGlyph) {
    const std::vector<glm::vec3> rays = w.pinhole ? viewRays(clip, w) : std::vector<glm::vec3>{};
    addRealCameraGlyph(scene, {w.eye, w.right, w.down, w.forward}, rays, palette::kCamera, lineScale);
    // Sight line to the look-at point.
    scene.lines.push_back({w.eye, 1.5f * lineScale, w.lookAt, 6.0f * lineScale,
                           glm::vec4(glm::vec3(palette::kCamera), 0.6f)});
  }
  return true;
}

}  // namespace ew::ui

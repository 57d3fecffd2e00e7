#include "ui/panels/stage_scenes.h"

#include <cmath>
#include <numbers>

#include "ui/app/app_state.h"
#include "ui/app/stage_actions.h"
#include "ui/convert.h"
#include "ui/render/figures.h"
#include "ui/render/palette.h"

namespace ew::ui {

namespace {

constexpr float kDotRadiusMm = 34.0f;  // as the 2D view's point-lights

glm::vec3 at(const Eigen::Matrix3Xd& p, Eigen::Index i) {
  return {static_cast<float>(p(0, i)), static_cast<float>(p(1, i)), static_cast<float>(p(2, i))};
}

// A ring round a point of the image plane, on top of the dots: the depth-reversed walker's
// joints stay visible where they fall on the true walker's.
void addRing(Scene& scene, glm::vec2 centre, float radiusMm, const glm::vec4& colour, float widthPx) {
  constexpr int kSegments = 16;
  for (int k = 0; k < kSegments; ++k) {
    const float a0 = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k) / kSegments;
    const float a1 = 2.0f * std::numbers::pi_v<float> * static_cast<float>(k + 1) / kSegments;
    scene.overlayLines.push_back({glm::vec3(centre + radiusMm * glm::vec2(std::cos(a0), std::sin(a0)), 1.0f), widthPx,
                                  glm::vec3(centre + radiusMm * glm::vec2(std::cos(a1), std::sin(a1)), 1.0f), 0.0f,
                                  colour});
  }
}

Pose2 pose2Of(const Eigen::Matrix2Xd& uv) {
  Pose2 pose{};
  for (int j = 0; j < kJointCount; ++j)
    pose[static_cast<std::size_t>(j)] = {static_cast<float>(uv(0, j)), static_cast<float>(uv(1, j))};
  return pose;
}

Pose3 pose3Of(const Eigen::Matrix3Xd& p, const Eigen::Vector3d& offset) {
  Pose3 pose{};
  for (int j = 0; j < kJointCount; ++j) pose[static_cast<std::size_t>(j)] = at(p, j) + toGlm(offset);
  return pose;
}

}  // namespace

bool buildStageInputScene(const AppState& s, Scene& scene, float lineScale, double cycles) {
  const std::optional<StageWalker> walker = stageWalker2d(s);
  if (!walker) return false;
  const StageFeature stage = effectiveStage(s);
  const StageDots dots = stageDots(stage, *walker->w, walker->strideHz, cycles, walker->speedMmS, walker->alphaDeg);
  const double azimuth = stageAzimuthDeg(s, walker->alphaDeg);
  const auto& o = s.view.overlays;
  const Eigen::Matrix2Xd uv = stageProjection(dots.walker, azimuth, stage.elevationDeg);
  const bool bones = dots.keepsForm && o.stickFigure && !o.pointLights && uv.cols() == kJointCount;
  if (dots.walker.cols() == kJointCount) {
    addPointLights(scene, pose2Of(uv), kDotRadiusMm, bones, 2.5f * lineScale);
  } else {
    for (Eigen::Index i = 0; i < uv.cols(); ++i)
      scene.glows.push_back({glm::vec3(toGlm(Eigen::Vector2d(uv.col(i))), 0.0f), kDotRadiusMm, palette::kInputPoint});
  }
  // The noise dots look like the walker's own: that is the mask.
  const Eigen::Matrix2Xd noise = stageProjection(dots.noise, azimuth, stage.elevationDeg);
  for (Eigen::Index i = 0; i < noise.cols(); ++i)
    scene.glows.push_back({glm::vec3(toGlm(Eigen::Vector2d(noise.col(i))), 0.0f), kDotRadiusMm, palette::kInputPoint});
  if (dots.reversed) {
    const Eigen::Matrix2Xd mirrored = stageProjection(*dots.reversed, azimuth, stage.elevationDeg);
    if (bones) {  // dashed, so that the true walker's bones stay the solid ones
      const Pose2 pose = pose2Of(mirrored);
      for (const auto& [ja, jb] : kBones)
        scene.overlayLines.push_back({glm::vec3(pose[static_cast<std::size_t>(index(ja))], 1.0f), 1.5f * lineScale,
                                      glm::vec3(pose[static_cast<std::size_t>(index(jb))], 1.0f), 6.0f * lineScale,
                                      glm::vec4(glm::vec3(palette::kOtherMinimum), 0.7f)});
    }
    for (Eigen::Index i = 0; i < mirrored.cols(); ++i)
      addRing(scene, toGlm(Eigen::Vector2d(mirrored.col(i))), 1.5f * kDotRadiusMm, palette::kOtherMinimum,
              2.0f * lineScale);
  }
  return true;
}

bool buildStageReconstructionScene(const AppState& s, Scene& scene, float lineScale, double cycles) {
  const std::optional<StageWalker> walker = stageWalker3d(s);
  if (!walker) return false;
  const StageFeature stage = effectiveStage(s);
  const StageDots dots = stageDots(stage, *walker->w, walker->strideHz, cycles, walker->speedMmS, walker->alphaDeg);
  const auto& o = s.view.overlays;
  const bool figure = dots.keepsForm && !o.pointLights && dots.walker.cols() == kJointCount;
  if (stage.display.translating) scene.floor.scrollMm = 0.0f;  // the walker moves, not the floor
  if (dots.walker.cols() == kJointCount) {
    const glm::vec3 pelvis = at(dots.walker, index(Joint::Pelvis));
    scene.floor.shadowCentre = {pelvis.x, pelvis.y};
  }
  if (figure) {
    addFigure(scene, pose3Of(dots.walker, Eigen::Vector3d::Zero()), reconstructionStyle());
  } else {
    for (Eigen::Index i = 0; i < dots.walker.cols(); ++i)
      scene.glows.push_back({at(dots.walker, i), kDotRadiusMm, palette::kInputPoint});
  }
  for (Eigen::Index i = 0; i < dots.noise.cols(); ++i)
    scene.glows.push_back({at(dots.noise, i), kDotRadiusMm, palette::kInputPoint});
  if (dots.reversed) {
    // Beside the true walker along the 2D view's depth axis: both still project to one image.
    const Eigen::Vector3d aside = depthReversedOffset(walker->alphaDeg);
    if (figure) {
      addFigure(scene, pose3Of(*dots.reversed, aside), engineStyle(1));
    } else {
      for (Eigen::Index i = 0; i < dots.reversed->cols(); ++i)
        scene.glows.push_back({at(*dots.reversed, i) + toGlm(aside), kDotRadiusMm, palette::kOtherMinimum});
    }
  }
  if (o.cameraGlyph) addCameraGlyph(scene, stageAzimuthDeg(s, walker->alphaDeg), 1150.0f, palette::kCamera, false);
  (void)lineScale;
  return true;
}

Eigen::MatrixXd stageTrail2d(const AppState& s) {
  const std::optional<StageWalker> walker = stageWalker2d(s);
  if (!walker) return {};
  StageFeature stage = effectiveStage(s);
  stage.display.maskDots = 0;  // the noise fills twice the walker's extent on purpose
  const double azimuth = stageAzimuthDeg(s, walker->alphaDeg);
  constexpr int kSamples = 24;
  Eigen::MatrixXd trail;
  for (int i = 0; i < kSamples; ++i) {
    const StageDots dots =
        stageDots(stage, *walker->w, walker->strideHz, static_cast<double>(i) / kSamples, 0.0, walker->alphaDeg);
    const Eigen::Matrix2Xd uv = stageProjection(dots.walker, azimuth, stage.elevationDeg);
    if (trail.size() == 0) trail.resize(kSamples, 2 * uv.cols());
    trail.row(i) = Eigen::Map<const Eigen::RowVectorXd>(uv.data(), uv.size());
  }
  return trail;
}

}  // namespace ew::ui

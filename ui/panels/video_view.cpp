#include "ui/panels/video_view.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>
#include <imgui.h>
#include <opencv2/core.hpp>

#include "core/camera/walk_camera.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/panels/clip_view.h"
#include "ui/render/palette.h"

namespace ew::ui {

namespace {

glm::vec2 scenePoint(double u, double v) { return {static_cast<float>(u), static_cast<float>(-v)}; }

bool finitePair(const Eigen::Ref<const Eigen::RowVectorXd>& px, int joint) {
  return std::isfinite(px(2 * joint)) && std::isfinite(px(2 * joint + 1));
}

void addBones(Scene& scene, const Eigen::Ref<const Eigen::RowVectorXd>& px, float width,
              glm::vec4 colour) {
  for (const auto& [a, b] : kBones) {
    if (!finitePair(px, index(a)) || !finitePair(px, index(b))) continue;
    scene.overlayLines.push_back(
        {glm::vec3(scenePoint(px(2 * index(a)), px(2 * index(a) + 1)), 1.0f), width,
         glm::vec3(scenePoint(px(2 * index(b)), px(2 * index(b) + 1)), 1.0f), 0.0f, colour});
  }
}

// The tracked joints of a frame the fit does not show (before the fit, or outside it).
void addTrackedPose(Scene& scene, const TrackedVideo& t, int frame, float radius, float lineScale) {
  const int row = frame - t.track.firstFrame;
  if (row < 0 || row >= t.frames()) return;
  const Eigen::RowVectorXd px = t.track.jointsPx.row(row);
  addBones(scene, px, 2.0f * lineScale, glm::vec4(0.85f, 0.88f, 0.95f, 0.55f));
  for (int j = 0; j < kJointCount; ++j) {
    if (!finitePair(px, j)) continue;
    scene.glows.push_back({glm::vec3(scenePoint(px(2 * j), px(2 * j + 1)), 0.5f), radius,
                           palette::confidenceColour(static_cast<float>(t.track.confidence(row, j)))});
  }
}

// The joints marked on this frame: teal rings (a dark disc under a bright one) and bones.
void addKeyframeMarks(Scene& scene, const Keyframe& k, float radius, float lineScale) {
  addBones(scene, k.jointsPx, 2.5f * lineScale, glm::vec4(glm::vec3(palette::kCamera), 0.9f));
  for (int j = 0; j < kJointCount; ++j) {
    if (!finitePair(k.jointsPx, j)) continue;
    const glm::vec3 p(scenePoint(k.jointsPx(2 * j), k.jointsPx(2 * j + 1)), 2.0f);
    scene.glows.push_back({p, 1.5f * radius, glm::vec4(0.02f, 0.05f, 0.05f, 0.85f)});
    scene.glows.push_back({p, radius, palette::kCamera});
  }
}

// The MediaPipe-33 body's lines (the face's points are drawn, not joined): trunk, arms, legs
// and feet.
constexpr std::pair<int, int> kDetectedBones[] = {
    {11, 12}, {11, 23}, {12, 24}, {23, 24}, {11, 13}, {13, 15}, {12, 14}, {14, 16}, {23, 25}, {25, 27},
    {27, 29}, {29, 31}, {27, 31}, {24, 26}, {26, 28}, {28, 30}, {30, 32}, {28, 32}};

// The people the detector found on a frame: each point coloured by its visibility (sure blue,
// unsure red, as the tracked joints are), the body's lines faint under them.
void addDetectedPeople(Scene& scene, const std::vector<KeypointDetection>& people, float radius, float lineScale) {
  for (const KeypointDetection& d : people) {
    const Eigen::MatrixX3d& p = d.points;
    const auto finite = [&](int i) { return i < p.rows() && std::isfinite(p(i, 0)) && std::isfinite(p(i, 1)); };
    for (const auto& [a, b] : kDetectedBones) {
      if (!finite(a) || !finite(b)) continue;
      const float sure = static_cast<float>(std::min(p(a, 2), p(b, 2)));
      scene.overlayLines.push_back({glm::vec3(scenePoint(p(a, 0), p(a, 1)), 1.0f), 2.0f * lineScale,
                                    glm::vec3(scenePoint(p(b, 0), p(b, 1)), 1.0f), 0.0f,
                                    glm::vec4(0.85f, 0.88f, 0.95f, 0.25f + 0.4f * std::clamp(sure, 0.0f, 1.0f))});
    }
    for (int i = 0; i < p.rows(); ++i) {
      if (!finite(i)) continue;
      // The face's eleven points smaller: the body's joints are what the fit reads.
      const float r = i <= 10 ? 0.55f * radius : radius;
      scene.glows.push_back({glm::vec3(scenePoint(p(i, 0), p(i, 1)), 0.5f), r,
                             palette::confidenceColour(static_cast<float>(std::clamp(p(i, 2), 0.0, 1.0)))});
    }
  }
}

// A horizon across the picture at `rowPx`: dashed (the scene's, read off its lines) or whole
// (the fitted camera's).
void addHorizon(Scene& scene, double rowPx, int widthPx, float width, glm::vec4 colour, bool dashed) {
  if (!std::isfinite(rowPx)) return;
  const float y = -static_cast<float>(rowPx), w = static_cast<float>(widthPx);
  const float dash = dashed ? w / 48.0f : w;
  for (float x = 0.0f; x < w; x += dashed ? 2.0f * dash : dash)
    scene.overlayLines.push_back({glm::vec3(x, y, 0.8f), width, glm::vec3(std::min(x + dash, w), y, 0.8f), 0.0f, colour});
}

// The scene's horizon and the fitted camera's (docs/CAMERA.md, "The scene's horizon"): where
// the two part, the camera's height over the walker is unsure.
void addHorizons(const AppState& s, Scene& scene, float lineScale, bool fitted) {
  const VideoSession& v = *s.video.session;
  const VideoHorizon* horizon = v.horizon();
  if (!horizon || !horizon->scene || v.marking) return;
  const int widthPx = v.frames->info().widthPx;
  addHorizon(scene, horizon->scene->rowPx, widthPx, 2.0f * lineScale, palette::kSceneHorizon, true);
  if (fitted && actions::showsVideoFit(s))
    addHorizon(scene, horizonRowPx(s.clip.fit()->rec.fit.camera), widthPx, 1.5f * lineScale, palette::kCamera, false);
}

}  // namespace

glm::vec2 VideoViewFrame::toVideoPx(glm::vec2 share, float aspect) const {
  const float h = 0.5f * heightPx, w = h * aspect;
  const glm::vec2 scene{centre.x - w + 2.0f * w * share.x, centre.y + h - 2.0f * h * share.y};
  return {scene.x, -scene.y};
}

glm::vec2 VideoViewFrame::toViewShare(glm::vec2 px, float aspect) const {
  const float h = 0.5f * heightPx, w = h * aspect;
  return {(px.x - (centre.x - w)) / (2.0f * w), ((centre.y + h) + px.y) / (2.0f * h)};
}

VideoViewFrame videoViewFrame(int widthPx, int heightPx, float aspect, float topShare, float bottomShare,
                              float leftShare) {
  VideoViewFrame f;
  const float w = static_cast<float>(widthPx), h = static_cast<float>(heightPx);
  const float band = std::max(1.0f - topShare - bottomShare, 0.2f);
  const float across = std::max(1.0f - leftShare, 0.2f);
  f.heightPx = std::max({h / band, w * 1.02f / (std::max(aspect, 0.1f) * across), 16.0f});
  // The box's middle (scene x right, y up) on the video's middle.
  const float viewWidth = f.heightPx * aspect;
  f.centre = {0.5f * w - 0.5f * leftShare * viewWidth,
              -0.5f * h + 0.5f * (topShare - bottomShare) * f.heightPx};
  return f;
}

glm::vec2 videoViewMiddle(const VideoViewFrame& view) { return {view.centre.x, -view.centre.y}; }

glm::vec2 zoomMiddleKeeping(glm::vec2 middlePx, glm::vec2 cursorPx, double zoomBefore, double zoomAfter) {
  return cursorPx + (middlePx - cursorPx) * static_cast<float>(zoomBefore / zoomAfter);
}

std::optional<Magnification> magnifierInput(double zoom, glm::vec2 middlePx, glm::vec2 cursorPx,
                                            float pxPerScreenPx) {
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Right))
    return Magnification{1.0, middlePx};
  if (ImGui::IsItemHovered() && io.MouseWheel != 0.0f) {
    const double next = std::clamp(zoom * std::pow(1.25, static_cast<double>(io.MouseWheel)), 1.0, kMaxVideoZoom);
    return Magnification{next, zoomMiddleKeeping(middlePx, cursorPx, zoom, next)};
  }
  if (ImGui::IsItemActive() && ImGui::IsMouseDragging(ImGuiMouseButton_Right, 0.0f) && zoom > 1.0)
    return Magnification{zoom, middlePx - glm::vec2(io.MouseDelta.x, io.MouseDelta.y) * pxPerScreenPx};
  return std::nullopt;
}

bool buildVideoInputScene(const AppState& s, Scene& scene, float lineScale,
                          float videoPxPerScreenPx, int frame, const void* bgrMat) {
  scene.clearItems();
  scene.floor.visible = false;
  scene.backgroundTop = {0.085f, 0.09f, 0.105f, 1.0f};
  scene.backgroundBottom = {0.04f, 0.045f, 0.055f, 1.0f};
  if (!s.video.session) return false;
  const VideoSession& v = *s.video.session;
  const float radius = 5.0f * lineScale * videoPxPerScreenPx;
  const auto fit = v.marking ? std::nullopt : actions::videoFitFrames(s);
  const int clipFrame = fit ? frame - fit->first : -1;
  const bool fitted = fit.has_value();
  // A detection under way, or done and not fitted: the people found on the frame.
  const bool detections = v.detecting || (v.detected && !v.tracked && !fitted);
  if (fitted && clipFrame >= 0 && clipFrame < s.clip.fit()->rec.trial.frameCount) {
    buildClipInputScene(s, scene, lineScale, clipFrame, clipImageFrame(*s.clip.fit(), 1.0f));
  } else if (detections) {
    addDetectedPeople(scene, actions::detectionsOn(s, frame), radius, lineScale);
  } else if (v.tracked) {
    addTrackedPose(scene, *v.tracked, frame, radius, lineScale);
  }
  if (const Keyframe* k = v.keyframeAt(frame)) addKeyframeMarks(scene, *k, radius, lineScale);
  addHorizons(s, scene, lineScale, fitted);
  if (const auto* mat = static_cast<const cv::Mat*>(bgrMat); mat && !mat->empty()) {
    scene.image.bgr = mat->data;
    scene.image.width = mat->cols;
    scene.image.height = mat->rows;
    scene.image.strideBytes = mat->step[0];
    scene.image.key =
        reinterpret_cast<std::uintptr_t>(mat->data) ^ (static_cast<std::uint64_t>(frame) << 40);
    scene.image.low = {0.0f, -static_cast<float>(mat->rows)};
    scene.image.high = {static_cast<float>(mat->cols), 0.0f};
    // Dimmed under a fit or while marking, so the marks read on any footage.
    scene.image.brightness = fitted || v.marking || v.tracked || detections ? 0.72f : 1.0f;
  }
  return true;
}

}  // namespace ew::ui

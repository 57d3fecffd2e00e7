#pragma once
// Left view: the 2D input — the held-out walker's orthographic projection at α, exactly
// what the reconstruction sees — as point-lights (optionally a stick figure and each
// point's path over the cycle), with the reconstruction projected back and the 2D residual.

#include "ui/gl/gl.h"
#include "ui/panels/clip_view.h"
#include "ui/panels/panel_window.h"
#include "ui/panels/video_view.h"
#include "ui/render/camera.h"
#include "ui/render/scene.h"

namespace ew::ui {

struct AppState;
struct FrameContext;

// The view's scene at a gait phase (0 … 1): the panel draws it each frame, the video
// export at exact phases. lineScale multiplies line widths (the UI scale). Returns false
// when there is nothing to show yet.
bool buildInputScene(const AppState& s, Scene& scene, float lineScale, double phase);
// The fixed image-plane camera of the 2D view for a width / height aspect.
CameraMatrices inputViewCamera(float aspect);

struct InputViewPanel {
  gl::RenderTarget target;
  Scene scene;  // rebuilt every frame; kept to reuse its allocations
  PanelRect lastImage;  // where the view was drawn last frame (screen pixels), for PNG export

  void draw(AppState& s, const FrameContext& ctx, const PanelRect& rect);

 private:
  // The walker's orthographic view at α (reconstruct and explore modes), at p0, size.
  void drawWalkerView(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size);
  // Mode::Clip: the keypoint clip in image pixels (ui/panels/clip_view.h).
  void drawClipView(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size);
  // Mode::Clip with a video open: the footage, marks and track (ui/panels/video_view.h).
  void drawVideoView(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size);
  void handleVideoMouse(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size, int frame);

  int dragJoint_ = -1;  // the keyframe joint being dragged (-1: none)
  void zoomAndPanVideo(AppState& s, ImVec2 size, glm::vec2 cursorPx);
  void zoomAndPanClip(AppState& s, ImVec2 p0, ImVec2 size, const ClipImageFrame& image);
  VideoViewFrame videoFrame_;  // the video view's framing, as drawn (clicks map through it)
};

}  // namespace ew::ui

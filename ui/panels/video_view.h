#pragma once
// The 2D view of a video (Mode::Clip with a video open, docs/VIEWER.md "Video"): the frame at
// the video's aspect, the joints marked on it (keyframes), the tracked joints coloured by
// confidence, and once the track is fitted the 3D walker drawn back through the estimated
// camera over the footage. Clicks place the joint the guided marking asks for; a mark can
// be dragged to correct it.

#include <glm/vec2.hpp>
#include <optional>

#include "ui/render/scene.h"

namespace ew::ui {

struct AppState;

// The image-plane view that holds the whole picture with room for the captions.
struct VideoViewFrame {
  glm::vec2 centre{0.0f};  // scene units: image pixels, y up (−v)
  float heightPx = 1.0f;
  // A screen point of the view (0-1 across, 0-1 down) as video pixels (x right, y down).
  glm::vec2 toVideoPx(glm::vec2 viewShare, float aspect) const;
  // A video pixel as a view share (the inverse).
  glm::vec2 toViewShare(glm::vec2 videoPx, float aspect) const;
};
// The video as large as fits in the view right of `leftShare` of its width and in the band
// between `topShare` and `bottomShare` of its height (the caption above, the legend below, or
// both in a column on the left), centred in that box.
VideoViewFrame videoViewFrame(int widthPx, int heightPx, float aspect, float topShare = 0.11f,
                              float bottomShare = 0.07f, float leftShare = 0.0f);

// `whole` magnified `zoom` times (≥ 1) with the image pixel `centrePx` (x right, y down) at
// the view's middle; `whole` itself at zoom 1. For any image-plane framing with a `centre`
// (scene units, y up) and a `heightPx`: the video's, a keypoint clip's.
template <class Frame>
Frame zoomedFrame(const Frame& whole, double zoom, glm::vec2 centrePx) {
  if (!(zoom > 1.0)) return whole;
  Frame f;
  f.heightPx = whole.heightPx / static_cast<float>(zoom);
  f.centre = {centrePx.x, -centrePx.y};
  return f;
}
// The video pixel (x right, y down) at the middle of `view`.
glm::vec2 videoViewMiddle(const VideoViewFrame& view);
// The middle a view magnified from `zoomBefore` to `zoomAfter` needs for the video pixel
// `cursorPx` to stay where it was on screen (the wheel zooms about the cursor).
glm::vec2 zoomMiddleKeeping(glm::vec2 middlePx, glm::vec2 cursorPx, double zoomBefore, double zoomAfter);

// The mouse over a 2D view of pictures as a magnifier (ImGui's last item, which takes the right
// button too): the wheel zooms about the cursor, a right-drag moves a magnified view, a right
// double-click shows it whole. The new zoom and middle pixel, when the mouse asks for one.
struct Magnification {
  double zoom = 1.0;
  glm::vec2 middlePx{0.0f};
};
std::optional<Magnification> magnifierInput(double zoom, glm::vec2 middlePx, glm::vec2 cursorPx,
                                            float pxPerScreenPx);

// Builds the scene for video frame `frame` whose pixels are `bgrMat` (a cv::Mat; null: no
// picture yet); `videoPxPerScreenPx` sizes the marks on screen. Returns false when no video
// is open.
bool buildVideoInputScene(const AppState& s, Scene& scene, float lineScale,
                          float videoPxPerScreenPx, int frame, const void* bgrMat);

}  // namespace ew::ui

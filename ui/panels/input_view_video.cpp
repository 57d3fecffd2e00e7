// InputViewPanel's video view (ui/panels/video_view.h): the frame, marks and track, the
// guided marking's prompt, and the clicks that place and drag joints.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/panels/input_view_panel.h"
#include "ui/panels/video_view.h"
#include "ui/panels/view_captions.h"
#include "ui/panels/view_overlay.h"
#include "ui/render/palette.h"
#include "ui/render/renderer.h"

namespace ew::ui {

namespace {

// "the walker's right knee", as the guided marking asks for it.
std::string spokenJoint(Joint j) {
  std::string name(jointName(j));
  std::replace(name.begin(), name.end(), '_', ' ');
  if (name.starts_with("r ")) return "the walker's RIGHT " + name.substr(2);
  if (name.starts_with("l ")) return "the walker's LEFT " + name.substr(2);
  return "the " + name;
}

void drawPrompt(ImDrawList* dl, ImFont* font, ImVec2 p0, ImVec2 size, const std::string& text,
                float scale) {
  const float fontSize = font ? font->FontSize * ImGui::GetIO().FontGlobalScale : ImGui::GetFontSize();
  const ImVec2 ts = font ? font->CalcTextSizeA(fontSize, size.x, 0.0f, text.c_str())
                         : ImGui::CalcTextSize(text.c_str());
  const float pad = 8.0f * scale;
  const ImVec2 at(p0.x + std::max(pad, 0.5f * (size.x - ts.x)), p0.y + 64.0f * scale);
  dl->AddRectFilled(ImVec2(at.x - pad, at.y - 0.5f * pad),
                    ImVec2(at.x + ts.x + pad, at.y + ts.y + 0.5f * pad), IM_COL32(10, 40, 36, 225),
                    6.0f * scale);
  dl->AddText(font, fontSize, at, IM_COL32(120, 240, 215, 255), text.c_str());
}

// The joint nearest to `px` within `reach` (video pixels) among the marks on `frame`, else
// among the tracked joints there; -1 when none.
int nearestJoint(const VideoSession& v, int frame, glm::vec2 px, float reach) {
  Eigen::RowVectorXd points;
  if (const Keyframe* k = v.keyframeAt(frame)) {
    points = k->jointsPx;
  } else if (v.tracked && frame >= v.tracked->track.firstFrame && frame <= v.tracked->lastFrame()) {
    points = v.tracked->track.jointsPx.row(frame - v.tracked->track.firstFrame);
  } else {
    return -1;
  }
  int nearest = -1;
  double best = reach;
  for (int j = 0; j < kJointCount; ++j) {
    const double d = std::hypot(points(2 * j) - px.x, points(2 * j + 1) - px.y);
    if (std::isfinite(d) && d < best) best = d, nearest = j;
  }
  return nearest;
}

}  // namespace

void InputViewPanel::drawVideoView(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size) {
  VideoSession& v = *s.video;
  const int frame = actions::shownVideoFrame(s);
  if (auto f = v.frames->frame(frame)) {
    v.shown = std::move(f);
    v.shownIndex = frame;
  }
  const float aspect = size.x / size.y;
  const VideoInfo& info = v.frames->info();
  const VideoViewFrame view = videoViewFrame(info.widthPx, info.heightPx, aspect);
  handleVideoMouse(s, ctx, p0, size, frame);
  buildVideoInputScene(s, scene, ctx.scale, view.heightPx / size.y, frame, v.shown.get());
  ctx.renderer.render(target, scene, imageCamera(aspect, view.centre, view.heightPx));
  ctx.backdrop.image(target, {p0.x, p0.y});

  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float pad = 10.0f * ctx.scale;
  const ViewCaption caption = videoInputCaption(s, frame, v.shownIndex != frame, true);
  drawCaption(dl, ImVec2(p0.x + pad, p0.y + pad), caption.title, caption.subtitle, s.fonts.large, ctx.scale,
              ImVec2(size.x - 2.0f * pad, size.y));
  if (v.marking) {
    const auto& order = markingOrder();
    const std::string prompt =
        v.markStep < static_cast<int>(order.size())
            ? "Click " + spokenJoint(order[static_cast<std::size_t>(v.markStep)]) +
                  " (Skip if hidden)"
            : "All joints marked on this frame: drag one to correct it, or Done";
    drawPrompt(dl, s.fonts.large, p0, size, prompt, ctx.scale);
  }
  drawLegend(dl, ImVec2(p0.x + pad, p0.y + size.y - pad), caption.legend, ctx.scale, size.x);
}

void InputViewPanel::handleVideoMouse(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size,
                                      int frame) {
  VideoSession& v = *s.video;
  const VideoInfo& info = v.frames->info();
  const float aspect = size.x / size.y;
  const VideoViewFrame view = videoViewFrame(info.widthPx, info.heightPx, aspect);
  ImGui::SetCursorScreenPos(p0);
  ImGui::InvisibleButton("##video", size);
  const ImVec2 m = ImGui::GetIO().MousePos;
  const glm::vec2 px = view.toVideoPx({(m.x - p0.x) / size.x, (m.y - p0.y) / size.y}, aspect);
  const auto place = [&](Joint j, bool newEdit) {
    try {
      const double x =
          std::clamp(static_cast<double>(px.x), 0.0, static_cast<double>(info.widthPx));
      const double y =
          std::clamp(static_cast<double>(px.y), 0.0, static_cast<double>(info.heightPx));
      actions::markJoint(s, j, x, y, newEdit);
    } catch (const std::exception& e) {
      s.log.error(e.what());
    }
  };
  if (dragJoint_ >= 0) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      place(static_cast<Joint>(dragJoint_), false);
    } else {
      dragJoint_ = -1;
    }
    return;
  }
  if (!ImGui::IsItemClicked(ImGuiMouseButton_Left)) return;
  // A mark (or a tracked joint) within reach of the click is dragged: the frame becomes a
  // keyframe; else the joint the marking asks for is placed.
  const float reach = 12.0f * ctx.scale * view.heightPx / size.y;
  dragJoint_ = nearestJoint(v, frame, px, reach);
  if (dragJoint_ >= 0) {
    v.frame = frame;
    place(static_cast<Joint>(dragJoint_), true);
    return;
  }
  const auto& order = markingOrder();
  if (v.marking && v.markStep < static_cast<int>(order.size()))
    place(order[static_cast<std::size_t>(v.markStep)], true);
}

}  // namespace ew::ui

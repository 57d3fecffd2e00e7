// InputViewPanel's video view (ui/panels/video_view.h): the frame, marks and track, the
// guided marking's prompt, and the clicks that place and drag joints.
#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>
#include <utility>
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

// Beside footage narrower than the view, the caption and the legend may take this share of its
// width, on the left.
constexpr float kVideoCaptionColumnShare = 0.4f;

// "the walker's right knee", as the guided marking asks for it.
std::string spokenJoint(Joint j) {
  std::string name(jointName(j));
  std::replace(name.begin(), name.end(), '_', ' ');
  if (name.starts_with("r ")) return "the walker's RIGHT " + name.substr(2);
  if (name.starts_with("l ")) return "the walker's LEFT " + name.substr(2);
  return "the " + name;
}

// The guided marking's prompt, centred across the view, its top at `top` (below the caption).
void drawPrompt(ImDrawList* dl, ImFont* font, ImVec2 p0, ImVec2 size, float top, const std::string& text,
                float scale) {
  const float fontSize = font ? font->FontSize * ImGui::GetIO().FontGlobalScale : ImGui::GetFontSize();
  const ImVec2 ts = font ? font->CalcTextSizeA(fontSize, size.x, 0.0f, text.c_str())
                         : ImGui::CalcTextSize(text.c_str());
  const float pad = 8.0f * scale;
  const ImVec2 at(p0.x + std::max(pad, 0.5f * (size.x - ts.x)), std::max(top + pad, p0.y + 64.0f * scale));
  dl->AddRectFilled(ImVec2(at.x - pad, at.y - 0.5f * pad),
                    ImVec2(at.x + ts.x + pad, at.y + ts.y + 0.5f * pad), IM_COL32(10, 40, 36, 225),
                    6.0f * scale);
  dl->AddText(font, fontSize, at, IM_COL32(120, 240, 215, 255), text.c_str());
}

// The joint nearest to `px` within `reach` (video pixels) among the marks on `frame`, else
// among the tracked joints there; on a detected video, among the fitted walker's joints there
// with the marks in their place. -1 when none.
int nearestJoint(const AppState& s, int frame, glm::vec2 px, float reach) {
  const VideoSession& v = *s.video.session;
  const Keyframe* k = v.keyframeAt(frame);
  Eigen::RowVectorXd points;
  const auto fit = actions::correctsDetections(s) ? actions::videoFitFrames(s) : std::nullopt;
  if (fit && frame >= fit->first && frame <= fit->second) {
    points = s.clip.fit()->rec.trial.jointsPx.row(frame - fit->first);
    for (int j = 0; k && j < kJointCount; ++j)
      if (std::isfinite(k->jointsPx(2 * j))) points.segment<2>(2 * j) = k->jointsPx.segment<2>(2 * j);
  } else if (k) {
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

// The footage framed clear of the whole caption and the whole legend when that keeps it at
// 0.8 of its size at least; else of the caption's title alone and the legend; else of the
// title and the legend's folded tab (the view's other framings choose so too). Footage
// narrower than the view (a phone held upright) is rather framed right of a column that holds
// the whole caption, wrapped to the column, and the legend, when that makes it larger.
struct VideoFraming {
  VideoViewFrame view;
  float captionWidth = 0.0f;  // the caption's lines wrap within this (screen px)
  float narrowBelowPx = kNarrowViewPx;  // drawCaption's: 0 in the column, which is sized for it
};

VideoFraming videoFraming(const ViewCaption& caption, const VideoInfo& info, ImVec2 size, float scale,
                          ImFont* titleFont) {
  const float pad = 10.0f * scale, aspect = size.x / size.y;
  const auto framed = [&](ImVec2 top, ImVec2 bottom) {
    return videoViewFrame(info.widthPx, info.heightPx, aspect, (1.5f * pad + top.y) / size.y,
                          (1.5f * pad + bottom.y) / size.y);
  };
  const auto captionSize = [&](float width, float narrowBelowPx) {
    return drawCaption(nullptr, ImVec2(0.0f, 0.0f), caption.title, caption.subtitle, titleFont, scale,
                       ImVec2(width, size.y), kNothing, narrowBelowPx)
        .GetSize();
  };
  const float largest = framed({0.0f, 0.0f}, {0.0f, 0.0f}).heightPx;  // smaller heightPx: larger footage
  const ImVec2 full = captionSize(size.x - 2.0f * pad, kNarrowViewPx);
  const ImVec2 title = smallCaptionPlate(caption.title, scale, size.x - 2.0f * pad);
  const ImVec2 legend = legendSize(caption.legend, scale, size.x);
  const auto stackedView = [&] {
    for (const auto& [top, bottom] : {std::pair{full, legend}, std::pair{title, legend}}) {
      const VideoViewFrame f = framed(top, bottom);
      if (f.heightPx <= largest / 0.8f) return f;
    }
    return framed(title, legendTabSize(scale));
  };
  const VideoFraming stacked{stackedView(), size.x - 2.0f * pad};
  const float columnWidth = kVideoCaptionColumnShare * size.x - 2.5f * pad;
  const ImVec2 wrapped = captionSize(columnWidth, 0.0f);
  if (legend.x > columnWidth || wrapped.y + legend.y + 3.0f * pad > size.y) return stacked;
  const float column = (std::max(wrapped.x, legend.x) + 2.5f * pad) / size.x;
  const VideoFraming beside{
      videoViewFrame(info.widthPx, info.heightPx, aspect, pad / size.y, pad / size.y, column), columnWidth, 0.0f};
  // A few per cent are not worth the caption's move.
  return beside.view.heightPx < 0.95f * stacked.view.heightPx ? beside : stacked;
}

// Video pixels [low, high] (x right, y down) on the screen.
ImRect screenRect(const VideoViewFrame& view, float aspect, ImVec2 p0, ImVec2 size, glm::vec2 low, glm::vec2 high) {
  const glm::vec2 a = view.toViewShare(low, aspect), b = view.toViewShare(high, aspect);
  return ImRect(ImVec2(p0.x + a.x * size.x, p0.y + a.y * size.y), ImVec2(p0.x + b.x * size.x, p0.y + b.y * size.y));
}

// Where the walker shown on `frame` is, in video pixels: its marks, else the detector's fitted
// joints, else its tracked joints.
std::optional<std::pair<glm::vec2, glm::vec2>> walkerExtentPx(const AppState& s, int frame) {
  const VideoSession& v = *s.video.session;
  Eigen::RowVectorXd points;
  if (const Keyframe* k = v.keyframeAt(frame)) {
    points = k->jointsPx;
  } else if (actions::showsDetectionFit(s) && frame >= 0 && frame < s.clip.fit()->rec.trial.jointsPx.rows()) {
    points = s.clip.fit()->rec.trial.jointsPx.row(frame);  // the detector's clip counts the video's frames
  } else if (v.tracked && frame >= v.tracked->track.firstFrame && frame <= v.tracked->lastFrame()) {
    points = v.tracked->track.jointsPx.row(frame - v.tracked->track.firstFrame);
  }
  std::optional<std::pair<glm::vec2, glm::vec2>> box;
  for (Eigen::Index j = 0; j + 1 < points.size(); j += 2) {
    const glm::vec2 p(static_cast<float>(points(j)), static_cast<float>(points(j + 1)));
    if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
    box = box ? std::pair{glm::min(box->first, p), glm::max(box->second, p)} : std::pair{p, p};
  }
  return box;
}

}  // namespace

void InputViewPanel::drawVideoView(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size) {
  VideoSession& v = *s.video.session;
  const int frame = actions::shownVideoFrame(s);
  if (auto f = v.frames->frame(frame)) {
    v.shown = std::move(f);
    v.shownIndex = frame;
  }
  const float aspect = size.x / size.y;
  const VideoInfo& info = v.frames->info();
  const ViewCaption caption = videoInputCaption(s, frame, v.shownIndex != frame, true);
  const VideoFraming framing = videoFraming(caption, info, size, ctx.scale, s.fonts.large);
  videoFrame_ = zoomedFrame(framing.view, v.zoom,
                                 {static_cast<float>(v.zoomCentrePx.x()), static_cast<float>(v.zoomCentrePx.y())});
  const VideoViewFrame& view = videoFrame_;
  handleVideoMouse(s, ctx, p0, size, frame);
  buildVideoInputScene(s, scene, ctx.scale, view.heightPx / size.y, frame, v.shown.get());
  ctx.renderer.render(target, scene, imageCamera(aspect, view.centre, view.heightPx));
  ctx.backdrop.image(target, {p0.x, p0.y});

  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float pad = 10.0f * ctx.scale;
  // The caption and the legend keep clear of the footage: they lose the subtitle, or fold,
  // when the view has no room for them above and below it. Magnified, the picture fills the
  // view by the user's choice and they lie over it whole.
  const ImRect footage = screenRect(view, aspect, p0, size, {0.0f, 0.0f},
                                    {static_cast<float>(info.widthPx), static_cast<float>(info.heightPx)});
  const ImRect clearOf = v.zoom > 1.0 ? kNothing : footage;
  const ImRect captionRect = drawCaption(dl, ImVec2(p0.x + pad, p0.y + pad), caption.title, caption.subtitle,
                                         s.fonts.large, ctx.scale, ImVec2(framing.captionWidth, size.y), clearOf,
                                         framing.narrowBelowPx);
  if (v.marking) {
    const auto& order = markingOrder();
    const std::string prompt =
        v.markStep < static_cast<int>(order.size())
            ? "Click " + spokenJoint(order[static_cast<std::size_t>(v.markStep)]) +
                  " (Skip if hidden)"
            : "All joints marked on this frame: drag one to correct it, or Done";
    drawPrompt(dl, s.fonts.large, p0, size, captionRect.Max.y, prompt, ctx.scale);
  }
  const ImRect legendRect =
      drawLegend(dl, ImVec2(p0.x + pad, p0.y + size.y - pad), caption.legend, ctx.scale, size.x, clearOf);
  if (const auto walker = walkerExtentPx(s, frame))
    s.lastFrame.overlay("input.walker", toPanelRect(screenRect(view, aspect, p0, size, walker->first, walker->second)));
  s.lastFrame.overlay("input.caption", toPanelRect(captionRect));
  s.lastFrame.overlay("input.legend", toPanelRect(legendRect));
  s.lastFrame.overlay("input.footage", toPanelRect(footage));
}

// The magnifier (magnifierInput) over the video.
void InputViewPanel::zoomAndPanVideo(AppState& s, ImVec2 size, glm::vec2 cursorPx) {
  const auto change = magnifierInput(s.video.session->zoom, videoViewMiddle(videoFrame_), cursorPx,
                                     videoFrame_.heightPx / size.y);
  if (!change) return;
  try {
    actions::setVideoZoom(s, change->zoom, Eigen::Vector2d(change->middlePx.x, change->middlePx.y));
  } catch (const std::exception& e) {
    s.log.error(e.what());
  }
}

void InputViewPanel::handleVideoMouse(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size,
                                      int frame) {
  VideoSession& v = *s.video.session;
  const VideoInfo& info = v.frames->info();
  const float aspect = size.x / size.y;
  const VideoViewFrame& view = videoFrame_;
  ImGui::SetCursorScreenPos(p0);
  ImGui::InvisibleButton("##video", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  const ImVec2 m = ImGui::GetIO().MousePos;
  const glm::vec2 px = view.toVideoPx({(m.x - p0.x) / size.x, (m.y - p0.y) / size.y}, aspect);
  zoomAndPanVideo(s, size, px);
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
      try {
        actions::letGoOfJoint(s);
      } catch (const std::exception& e) {
        s.log.error(e.what());
      }
    }
    return;
  }
  if (!ImGui::IsItemClicked(ImGuiMouseButton_Left)) return;
  // A mark (or a tracked joint) within reach of the click is dragged: the frame becomes a
  // keyframe; else the joint the marking asks for is placed.
  const float reach = 12.0f * ctx.scale * view.heightPx / size.y;
  dragJoint_ = nearestJoint(s, frame, px, reach);
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

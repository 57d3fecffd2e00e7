#include "ui/panels/input_view_panel.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <vector>

#include "core/teaching/html_walker.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/panels/clip_view.h"
#include "ui/panels/stage_scenes.h"
#include "ui/convert.h"
#include "ui/panels/view_captions.h"
#include "ui/panels/view_overlay.h"
#include "ui/panels/walker_bounds.h"
#include "ui/render/camera.h"
#include "ui/render/figures.h"
#include "ui/render/palette.h"
#include "ui/render/renderer.h"
#include "ui/widgets/centred_message.h"

namespace ew::ui {

namespace {

// The standard 2D view's framing, the one the HTML walker's "viewer" framing copies.
constexpr float kViewHeightMm = static_cast<float>(kViewerViewHeightMm);
constexpr float kViewCentreVMm = static_cast<float>(kViewerViewCentreVMm);

}  // namespace

bool buildInputScene(const AppState& s, Scene& scene, float lineScale, double phase) {
  scene.clearItems();
  scene.floor.visible = false;
  scene.backgroundTop = {0.085f, 0.09f, 0.105f, 1.0f};
  scene.backgroundBottom = {0.04f, 0.045f, 0.055f, 1.0f};
  const auto& o = s.view.overlays;
  const bool reconstruct = s.doc.mode == Mode::Reconstruct;
  const ReconBase* r = s.derived.recon();
  const ReconDisplay* d = s.derived.display();
  const ExploreResult* e = s.derived.explore();
  const Eigen::VectorXd* input = nullptr;
  const Eigen::MatrixXd* trail = nullptr;
  if (reconstruct && r) {
    input = &r->observed;
    trail = &r->observedTrail;
  } else if (!reconstruct && e) {
    input = &e->projected;
    trail = &e->projectedTrail;
  }

  // Ground line (v = 0) and the image's vertical axis through u = 0. A stage seen from above
  // (elevation) has no ground line: the floor under the walker spans a band of v.
  const bool tilted = stageDrawsViews(s) && s.stage.elevationDeg != 0.0;
  if (!tilted)
    scene.lines.push_back({{-4000.0f, 0.0f, -2.0f}, 1.5f, {4000.0f, 0.0f, -2.0f}, 0.0f, palette::kAxis});
  scene.lines.push_back({{0.0f, -60.0f, -2.0f}, 1.0f, {0.0f, 2000.0f, -2.0f}, 8.0f,
                         glm::vec4(glm::vec3(palette::kAxis), 0.35f)});
  if (stageDrawsViews(s))
    return buildStageInputScene(s, scene, lineScale, std::floor(s.view.playback.cycles) + phase);
  if (input) {
    if (o.trails && !o.pointLights && trail) {
      std::vector<glm::vec2> points(static_cast<std::size_t>(trail->rows()));
      for (int j = 0; j < kJointCount; ++j) {
        for (Eigen::Index i = 0; i < trail->rows(); ++i)
          points[static_cast<std::size_t>(i)] = {static_cast<float>((*trail)(i, 2 * j)),
                                                 static_cast<float>((*trail)(i, 2 * j + 1))};
        addPolyline2(scene, points, palette::kTrail, 1.5f * lineScale, true);
      }
    }
    const Pose2 pose = toPose2(frameAtPhase(*input, phase));
    addPointLights(scene, pose, 34.0f, o.stickFigure && !o.pointLights, 2.5f * lineScale);
    // Joints estimated from a model (the marker set lacked them) are no measured point-lights.
    if (reconstruct && r && scene.glows.size() >= pose.size()) {
      const std::size_t first = scene.glows.size() - pose.size();
      for (std::size_t j = 0; j < pose.size(); ++j) {
        if (!r->modelEstimated[j]) continue;
        scene.glows[first + j].colour = palette::kModelEstimated;
        scene.glows[first + j].radius *= 0.8f;
      }
    }
    if (reconstruct && d && o.reprojection && !o.pointLights) {
      const Pose2 rec = toPose2(frameAtPhase(d->reprojected, phase));
      for (const auto& [ja, jb] : kBones) {
        scene.overlayLines.push_back({glm::vec3(rec[static_cast<std::size_t>(index(ja))], 1.0f),
                                      2.0f * lineScale,
                                      glm::vec3(rec[static_cast<std::size_t>(index(jb))], 1.0f),
                                      0.0f, glm::vec4(glm::vec3(palette::kReconRight), 0.9f)});
      }
      for (std::size_t j = 0; j < pose.size(); ++j)
        scene.overlayLines.push_back({glm::vec3(pose[j], 1.0f), 2.0f * lineScale,
                                      glm::vec3(rec[j], 1.0f), 0.0f, palette::kError});
    }
  }
  return input != nullptr;
}

CameraMatrices inputViewCamera(float aspect) {
  return imageCamera(aspect, {0.0f, kViewCentreVMm}, kViewHeightMm);
}

namespace {

// The 2D view's framing: the standard one (2.35 m high, the same for every walker, so that
// walkers compare by size), unless the caption's title or the legend would then cover the
// walker's trail (a small view, a large UI scale): then the trail is framed clear of them.
// `top` and `bottom` are the plates (width, height) at the view's top-left and bottom-left
// (the legend, or its folded tab); `margin` the pixels kept around the trail (trailBounds2's).
// Nothing when the plates leave too little room between them.
std::optional<CameraMatrices> inputFraming(const Eigen::MatrixXd& trail, ImVec2 size, float pad, ImVec2 top,
                                           ImVec2 bottom, float margin) {
  const float aspect = size.x / size.y;
  double uLo = 1e9, uHi = -1e9, vLo = 1e9, vHi = -1e9;
  for (Eigen::Index i = 0; i < trail.rows(); ++i)
    for (Eigen::Index j = 0; j + 1 < trail.cols(); j += 2) {
      uLo = std::min(uLo, trail(i, j)), uHi = std::max(uHi, trail(i, j));
      vLo = std::min(vLo, trail(i, j + 1)), vHi = std::max(vHi, trail(i, j + 1));
    }
  if (!(uLo < uHi && vLo < vHi)) return inputViewCamera(aspect);
  // In pixels from the view's top-left corner, in the standard framing.
  const float pxPerMm = size.y / kViewHeightMm;
  const float left = 0.5f * size.x + static_cast<float>(uLo) * pxPerMm - margin;
  const float head = 0.5f * size.y - static_cast<float>(vHi - kViewCentreVMm) * pxPerMm - margin;
  const float feet = 0.5f * size.y - static_cast<float>(vLo - kViewCentreVMm) * pxPerMm + margin;
  const bool underTitle = left < pad + top.x && head < pad + top.y;
  const bool overLegend = left < pad + bottom.x && feet > size.y - pad - bottom.y;
  if (!underTitle && !overLegend) return inputViewCamera(aspect);
  // Where the trail's top and bottom go (the margin inside): room is kept only for the plate the
  // walker would meet (the ground then comes nearer the view's bottom; the head nearer the top
  // when the walker stands clear of the caption, else where it was).
  const bool besideTitle = left >= pad + top.x;  // (and stays so: the framing only shrinks the trail)
  const float topPx = underTitle ? pad + top.y + margin + 1.0f : besideTitle ? margin + pad : std::max(margin, head + margin);
  const float bottomPx = overLegend ? size.y - pad - bottom.y - margin - 1.0f : size.y - margin - 4.0f * pad / 10.0f;
  if (bottomPx - topPx < 0.4f * size.y) return std::nullopt;  // no room to frame it
  const float heightMm = std::max(kViewHeightMm, static_cast<float>(vHi - vLo) * size.y / (bottomPx - topPx));
  const float mmPerPx = heightMm / size.y;
  const float centre = static_cast<float>(vHi) - (0.5f * size.y - topPx) * mmPerPx;
  return imageCamera(aspect, {0.0f, centre}, heightMm);
}

}  // namespace

namespace {

// A round number of pixels about a fifth of the view's width, for the scale bar.
float roundPixels(float px) {
  for (float step : {10.0f, 20.0f, 50.0f, 100.0f, 200.0f, 500.0f, 1000.0f})
    if (step >= px) return step;
  return 2000.0f;
}

// The clip's view: its input in image pixels, the reprojection, the residuals named.
// The clip's walker on the screen at `shown`: its keypoints and its reprojection.
ImRect clipWalkerRect(const ClipResult& clip, int shown, ImVec2 p0, ImVec2 size, const ClipImageFrame& frame) {
  const float screenPerPx = size.y / frame.heightPx;
  ImRect box = kNothing;
  bool any = false;
  for (const Eigen::MatrixXd* px : {&clip.rec.trial.jointsPx, &clip.rec.reprojectedPx}) {
    if (shown < 0 || shown >= px->rows()) continue;
    for (int j = 0; j < kJointCount; ++j) {
      const double u = (*px)(shown, 2 * j), v = (*px)(shown, 2 * j + 1);
      if (!std::isfinite(u) || !std::isfinite(v)) continue;
      const ImVec2 p(p0.x + 0.5f * size.x + (static_cast<float>(u) - frame.centre.x) * screenPerPx,
                     p0.y + 0.5f * size.y + (static_cast<float>(v) + frame.centre.y) * screenPerPx);
      if (!any) box = ImRect(p, p);
      box.Add(p);
      any = true;
    }
  }
  return box;
}

// "track N" above each person the clip has besides the one fitted, as the picker names them.
void drawOtherPeopleLabels(ImDrawList* dl, const KeypointTrial& trial, int shown, ImVec2 p0, ImVec2 size,
                           const ClipImageFrame& frame) {
  const float screenPerPx = size.y / frame.heightPx;
  const ImU32 colour = toImU32(glm::vec4(glm::vec3(palette::kOtherPerson), 1.0f));
  for (const OtherPerson& o : otherPeopleAt(trial, shown)) {
    char label[32];
    std::snprintf(label, sizeof label, "track %d", o.track);
    const ImVec2 ts = ImGui::CalcTextSize(label);
    const ImVec2 at(p0.x + 0.5f * size.x + (o.top.x - frame.centre.x) * screenPerPx - 0.5f * ts.x,
                    p0.y + 0.5f * size.y - (o.top.y - frame.centre.y) * screenPerPx - 1.6f * ts.y);
    dl->AddText(at, colour, label);
  }
}

void drawClipAnnotations(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size, const ClipImageFrame& frame,
                         int shown) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p1{p0.x + size.x, p0.y + size.y};
  const float pad = 10.0f * ctx.scale;
  const ViewCaption caption = clipInputCaption(s, shown, true);
  const ImRect walker = clipWalkerRect(*s.clip.fit(), shown, p0, size, frame);
  const ImRect captionRect = drawCaption(dl, ImVec2(p0.x + pad, p0.y + pad), caption.title, caption.subtitle,
                                         s.fonts.large, ctx.scale, ImVec2(size.x - 2.0f * pad, size.y), walker);
  const float screenPerPx = size.y / frame.heightPx;
  const float bar = roundPixels(0.18f * size.x / screenPerPx);
  char label[32];
  std::snprintf(label, sizeof label, "%.0f px", static_cast<double>(bar));
  const float len = bar * screenPerPx;
  const ImRect legendRect = drawLegend(dl, ImVec2(p0.x + pad, p1.y - pad), caption.legend, ctx.scale, size.x, walker);
  // The scale bar at the bottom right, when the legend and the walker leave it room.
  const ImVec2 barLeft(p1.x - pad - len - 4.0f * ctx.scale, p1.y - pad - 4.0f * ctx.scale);
  const ImRect barRect(ImVec2(barLeft.x, barLeft.y - ImGui::GetTextLineHeight() - 6.0f * ctx.scale),
                       ImVec2(barLeft.x + len, barLeft.y + 5.0f * ctx.scale));
  if (!overlaps(barRect, legendRect) && !overlaps(barRect, walker)) drawScaleBar(dl, barLeft, len, label, ctx.scale);
  drawOtherPeopleLabels(dl, s.clip.fit()->rec.trial, shown, p0, size, frame);
  if (walker.GetWidth() > 0.0f) {
    s.lastFrame.overlay("input.walker", toPanelRect(walker));
    s.lastFrame.overlay("input.caption", toPanelRect(captionRect));
    s.lastFrame.overlay("input.legend", toPanelRect(legendRect));
  }
}

}  // namespace

void InputViewPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  if (beginPanel(ctx.backdrop, "2D input", rect, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoTitleBar |
                                        ImGuiWindowFlags_NoBackground)) {
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    const ImVec2 fbScale = ImGui::GetIO().DisplayFramebufferScale;
    if (size.x > 4.0f && size.y > 4.0f) {
      target.ensure(static_cast<int>(size.x * fbScale.x), static_cast<int>(size.y * fbScale.y),
                    ctx.renderer.samples());
      lastImage = {p0, size};
      if (s.doc.mode == Mode::Clip && s.video.session) {
        drawVideoView(s, ctx, p0, size);
      } else if (s.doc.mode == Mode::Clip) {
        drawClipView(s, ctx, p0, size);
      } else {
        drawWalkerView(s, ctx, p0, size);
      }
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

void InputViewPanel::drawWalkerView(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size) {
  const bool reconstruct = s.doc.mode == Mode::Reconstruct;
  const bool drawn = buildInputScene(s, scene, ctx.scale, s.view.playback.phase());
  const auto& o = s.view.overlays;
  const float aspect = size.x / size.y;
  const float pad = 10.0f * ctx.scale;
  const ReconBase* r = s.derived.recon();
  const ReconDisplay* d = s.derived.display();
  const ExploreResult* e = s.derived.explore();
  // Where the walker is drawn over its cycle: the input's trail and the reconstruction over it.
  Eigen::MatrixXd extent;
  if (stageDrawsViews(s)) {
    extent = stageTrail2d(s);
  } else if (reconstruct && r) {
    extent = r->observedTrail;
    if (d && o.reprojection && !o.pointLights) {
      const Eigen::MatrixXd reprojected = trailOverCycle(d->reprojected, 24);
      extent.conservativeResize(extent.rows() + reprojected.rows(), Eigen::NoChange);
      extent.bottomRows(reprojected.rows()) = reprojected;
    }
  } else if (!reconstruct && e) {
    extent = e->projectedTrail;
  }
  const ViewCaption text = walkerInputCaption(s);
  const std::vector<LegendItem>& legend = text.legend;
  const std::string& sub = text.subtitle;
  // The walker framed clear of the whole caption and the whole legend when that shrinks it by a
  // fifth at most; else of the caption's title alone (its subtitle then goes) and the legend;
  // else of the title and the legend folded into its tab.
  const float margin = 8.0f * ctx.scale;  // around the walker, for its joints' discs
  const ImVec2 captionPlate =
      drawCaption(nullptr, ImVec2(0.0f, 0.0f), "2D input", sub, s.fonts.large, ctx.scale, ImVec2(size.x - 2.0f * pad, size.y))
          .GetSize();
  const ImVec2 titlePlate = smallCaptionPlate("2D input", ctx.scale, size.x - 2.0f * pad);
  const ImVec2 legendPlate = legendSize(legend, ctx.scale, size.x);
  CameraMatrices camera = inputViewCamera(aspect);
  if (extent.size() > 0) {
    const auto framed = [&](ImVec2 top, ImVec2 bottom, float leastScale) -> std::optional<CameraMatrices> {
      auto c = inputFraming(extent, size, pad, top, bottom, margin);
      if (c && c->projection[1][1] < leastScale * 2.0f / kViewHeightMm) return std::nullopt;
      return c;
    };
    auto chosen = framed(captionPlate, legendPlate, 0.8f);
    if (!chosen) chosen = framed(titlePlate, legendPlate, 0.8f);
    if (!chosen) chosen = framed(titlePlate, legendTabSize(ctx.scale), 0.0f);
    camera = chosen.value_or(camera);
  }
  ctx.renderer.render(target, scene, camera);

  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p1{p0.x + size.x, p0.y + size.y};
  ctx.backdrop.image(target, {p0.x, p0.y});
  // What the caption, the legend and the scale bar keep clear of: the input over its cycle and
  // the reconstruction drawn over it.
  const ImRect walker = extent.size() > 0 ? trailBounds2(extent, camera, p0, size, margin) : ImRect(p0, p0);
  const ImRect caption = drawCaption(dl, ImVec2(p0.x + pad, p0.y + pad), "2D input", sub, s.fonts.large, ctx.scale,
                                     ImVec2(size.x - 2.0f * pad, size.y), walker);
  const ImRect legendRect = drawLegend(dl, ImVec2(p0.x + pad, p1.y - pad), legend, ctx.scale, size.x, walker);
  // The scale bar at the bottom right, when it has room there beside the legend and the walker.
  const float halfMetre = 500.0f * camera.projection[1][1] * 0.5f * size.y;  // 500 mm in the framing's pixels
  const ImVec2 barLeft(p1.x - pad - halfMetre - 4.0f * ctx.scale, p1.y - pad - 4.0f * ctx.scale);
  const ImRect bar(ImVec2(barLeft.x, barLeft.y - ImGui::GetTextLineHeight() - 6.0f * ctx.scale),
                   ImVec2(barLeft.x + halfMetre, barLeft.y + 5.0f * ctx.scale));
  if (!overlaps(bar, legendRect) && !overlaps(bar, walker)) drawScaleBar(dl, barLeft, halfMetre, "50 cm", ctx.scale);
  if (drawn) {
    s.lastFrame.overlay("input.walker", toPanelRect(walker));
    s.lastFrame.overlay("input.caption", toPanelRect(caption));
    s.lastFrame.overlay("input.legend", toPanelRect(legendRect));
  }
  if (!drawn) drawCentredMessage(dl, p0, size, s.jobsBusy() ? "loading…" : "nothing loaded");
}

void InputViewPanel::drawClipView(AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size) {
  const float aspect = size.x / size.y;
  const int frame = s.clip.fit() ? clipFrameAt(*s.clip.fit(), s.view.playback.cycles) : 0;
  const ClipImageFrame whole = s.clip.fit() ? clipImageFrame(*s.clip.fit(), aspect) : ClipImageFrame{};
  const ClipImageFrame image = zoomedFrame(
      whole, s.clip.zoom,
      {static_cast<float>(s.clip.zoomCentreX), static_cast<float>(s.clip.zoomCentreY)});
  if (s.clip.fit()) zoomAndPanClip(s, p0, size, image);
  const bool drawn = buildClipInputScene(s, scene, ctx.scale, frame, image);
  ctx.renderer.render(target, scene, clipInputCamera(image, aspect));
  ctx.backdrop.image(target, {p0.x, p0.y});
  if (drawn) {
    drawClipAnnotations(s, ctx, p0, size, image, frame);
  } else {
    drawCentredMessage(ImGui::GetWindowDrawList(), p0, size,
                       s.clip.fits.running() ? "reading the keypoints and fitting the camera…"
                                             : unfittedClipMessage(s.clip.fits.error()));
  }
}

// The magnifier (magnifierInput) over the clip, as over a video.
void InputViewPanel::zoomAndPanClip(AppState& s, ImVec2 p0, ImVec2 size, const ClipImageFrame& image) {
  ImGui::SetCursorScreenPos(p0);
  ImGui::InvisibleButton("##clip", size, ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight);
  // The clip's framing is an image-plane frame as the video's is: the same mapping.
  const VideoViewFrame view{image.centre, image.heightPx};
  const ImVec2 m = ImGui::GetIO().MousePos;
  const glm::vec2 cursorPx = view.toVideoPx({(m.x - p0.x) / size.x, (m.y - p0.y) / size.y}, size.x / size.y);
  const auto change = magnifierInput(s.clip.zoom, videoViewMiddle(view), cursorPx, image.heightPx / size.y);
  if (!change) return;
  try {
    actions::setClipZoom(s, change->zoom, Eigen::Vector2d(change->middlePx.x, change->middlePx.y));
  } catch (const std::exception& e) {
    s.log.error(e.what());
  }
}

}  // namespace ew::ui

#include "ui/panels/reconstruction_view_panel.h"

#include <algorithm>
#include <deque>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

#include "core/eigenwalker/reconstruction.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/panels/clip_view.h"
#include "ui/panels/stage_scenes.h"
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

// Under "no walk fits this track": why, without the video's path (the fit's message, wrapped to
// the view).
// A message in the middle of the view, wrapped at 0.8 of its width; returns its height.
void drawWhyNoWalkFits(ImDrawList* dl, const AppState& s, ImVec2 p0, ImVec2 size, float messageHeight) {
  std::string why = s.clip.fits.error();
  const std::string file = s.video.session->path.string() + ": ";
  if (why.rfind(file, 0) == 0) why.erase(0, file.size());
  if (why.empty()) return;
  const float wrap = 0.8f * size.x;
  const ImVec2 ws = ImGui::CalcTextSize(why.c_str(), nullptr, false, wrap);
  dl->AddText(ImGui::GetFont(), ImGui::GetFontSize(),
              ImVec2(p0.x + 0.5f * (size.x - ws.x), p0.y + 0.5f * size.y + messageHeight + 0.5f * ImGui::GetFontSize()),
              IM_COL32(130, 138, 150, 255), why.c_str(), nullptr, wrap);
}

void handleMouse(OrbitCamera& camera, const ImVec2& size) {
  const ImGuiIO& io = ImGui::GetIO();
  if (ImGui::IsItemActive()) {
    if (ImGui::IsMouseDown(ImGuiMouseButton_Left)) {
      camera.orbit(-io.MouseDelta.x, io.MouseDelta.y);
    } else if (ImGui::IsMouseDown(ImGuiMouseButton_Right) || ImGui::IsMouseDown(ImGuiMouseButton_Middle)) {
      camera.pan(io.MouseDelta.x, io.MouseDelta.y, size.y);
    }
  }
  if (ImGui::IsItemHovered()) {
    if (io.MouseWheel != 0.0f) camera.zoom(io.MouseWheel);
    if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) camera = OrbitCamera::preset(CameraPreset::ThreeQuarter);
  }
}

float strideLengthMm(const AppState& s) {
  const WalkerFacts* f = s.doc.selectedFacts();
  if (s.doc.mode == Mode::Reconstruct && f && f->speedMps && f->strideHz > 0.0)
    return static_cast<float>(*f->speedMps * 1000.0 / f->strideHz);
  return 1400.0f;
}

// The depth-error colour bar at the top right (or left), under the caption, kept clear of the
// legend and the walker: in a small view it is shortened to end above the legend, or left out
// when too little is left (the metrics strip and the joint-error panel still give the errors);
// in a narrow one its title shortens so that the plate stays at the view's edge.
ImRect drawColourBarClearOf(ImDrawList* dl, const ImRect& caption, const ImRect& legend, const ImRect& walker, ImVec2 p0,
                            ImVec2 p1, ImVec2 size, float errorScale, float scale, bool presentation) {
  const float pad = 10.0f * scale;
  const float barW = 14.0f * scale + ImGui::CalcTextSize("000 mm").x + 24.0f * scale;
  // A narrow view (1024×768's drawer layout) gets a plate as narrow as its scale, titled
  // "RMS", which keeps clear of the walker in the middle of the view; so does a view where the
  // wider plate would touch the walker.
  const bool longFits = ImGui::CalcTextSize("depth error (RMS)").x + 16.0f * scale <= 0.3f * size.x;
  const float chrome = ImGui::GetTextLineHeight() + 24.0f * scale;  // title and padding around the bar
  // At the right edge, else at the left (the walker stands off-centre or swings an arm out),
  // each under the caption and above the legend where they reach over; left out where neither
  // keeps clear of the walker.
  for (const bool right : {true, false}) {
    for (const char* title : {longFits ? "depth error (RMS)" : "RMS", "RMS"}) {
      const float plateW = std::max(barW, ImGui::CalcTextSize(title).x + 16.0f * scale);
      // Presentation mode has no metrics strip to point at instead: there a plate that would
      // cover 0.4 of a narrow view is left out rather than hide the walker.
      if (presentation && plateW > 0.4f * size.x) continue;
      const float x0 = right ? p1.x - pad - plateW : p0.x + pad, x1 = x0 + plateW;
      float top = p0.y + 78.0f * scale;
      if (caption.Max.x > x0 && caption.Min.x < x1) top = std::max(top, caption.Max.y + pad);
      float height = std::min(200.0f * scale, size.y * 0.35f);
      if (legend.Max.x > x0 && legend.Min.x < x1) height = std::min(height, legend.Min.y - pad - top - chrome);
      if (height < 50.0f * scale) continue;
      const ImRect plate(ImVec2(x0, top), ImVec2(x1, top + height + chrome));
      if (overlaps(plate, walker)) continue;
      drawErrorColourBar(dl, ImVec2(x1, top), height, errorScale, title, scale);
      return plate;
    }
  }
  return kNothing;
}

// The walkers of the 3D view over their cycle on screen: the reconstruction and its ghost, every
// engine's in compare mode, or the explorer's.
ImRect walkerOnScreen(const AppState& s, const CameraMatrices& camera, ImVec2 p0, ImVec2 size, float scale) {
  const float margin = 6.0f * scale;  // the joints' spheres (35 mm) at a walker 1.7 m tall in ~300 px
  const ReconBase* r = s.derived.recon();
  const ReconDisplay* d = s.derived.display();
  const bool ghost = s.view.overlays.ghost;
  if (s.doc.mode == Mode::Explore) {
    const ExploreResult* e = s.derived.explore();
    return e ? walkerBounds3({&e->w}, camera, p0, size, margin) : ImRect(p0, p0);
  }
  if (!r) return {p0, p0};
  ImRect bounds = walkerBounds3({ghost ? &r->wTrue : nullptr}, camera, p0, size, margin);
  if (s.doc.compareEngines && s.derived.compare()) {
    for (const auto& e : s.derived.compare()->engines)
      if (e.display) bounds = unite(bounds, walkerBounds3({&e.display->w}, camera, p0, size, margin));
  } else if (d) {
    bounds = unite(bounds, walkerBounds3({&d->w}, camera, p0, size, margin));
  }
  return bounds;
}

// The camera with its picture moved (a lens shift: the orbit stays as the user left it) down
// when the caption's title would cover the walker's head, or up when the legend would cover its
// feet, where there is room (a small view, a large UI scale). Else as it is: the legend then
// folds into its tab.
// `walker` is where the walker is through `camera`; it is moved with the picture.
CameraMatrices clearOfOverlays(CameraMatrices camera, ImRect& walker, const char* title, ImVec2 legendPlate, ImVec2 p0,
                               ImVec2 size, float scale) {
  const float pad = 10.0f * scale;
  const ImVec2 plate = smallCaptionPlate(title, scale, size.x - 2.0f * pad);
  const ImRect caption(ImVec2(p0.x + pad, p0.y + pad), ImVec2(p0.x + pad + plate.x, p0.y + pad + plate.y));
  const float bottom = p0.y + size.y - pad;
  const ImRect legend(ImVec2(p0.x + pad, bottom - legendPlate.y), ImVec2(p0.x + pad + legendPlate.x, bottom));
  const auto shifted = [&](float down) {
    return ImRect(ImVec2(walker.Min.x, walker.Min.y + down), ImVec2(walker.Max.x, walker.Max.y + down));
  };
  float down = 0.0f;
  if (overlaps(caption, walker)) {
    down = caption.Max.y + 1.0f - walker.Min.y;
    const ImVec2 tab = legendTabSize(scale);
    const ImRect tabRect(ImVec2(p0.x + pad, bottom - tab.y), ImVec2(p0.x + pad + tab.x, bottom));
    if (shifted(down).Max.y > bottom || overlaps(shifted(down), tabRect)) return camera;  // no room below
  } else if (overlaps(legend, walker)) {
    down = legend.Min.y - 1.0f - walker.Max.y;
    const bool underCaption = walker.Min.x < caption.Max.x && walker.Max.x > caption.Min.x;
    const float top = underCaption ? caption.Max.y + 1.0f : p0.y + pad;
    if (shifted(down).Min.y < top) return camera;  // no room above
  } else {
    return camera;
  }
  camera.projection = glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, -2.0f * down / size.y, 0.0f)) * camera.projection;
  walker = shifted(down);
  return camera;
}

// The clip's 3D view: where the estimated camera stands, and what is estimated.
void drawClipAnnotations(const AppState& s, const FrameContext& ctx, ImVec2 p0, ImVec2 size) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float pad = 10.0f * ctx.scale;
  const ViewCaption c = clipReconstructionCaption(s);
  drawCaption(dl, ImVec2(p0.x + pad, p0.y + pad), c.title, c.subtitle, s.fonts.large, ctx.scale,
              ImVec2(size.x - 2.0f * pad, size.y));
  drawLegend(dl, ImVec2(p0.x + pad, p0.y + size.y - pad), c.legend, ctx.scale, size.x);
}

}  // namespace

// Compare mode: the ground truth as the ghost and each shown engine's walker in its colour.
bool buildCompareScene(const AppState& s, Scene& scene, double phase) {
  const ReconBase* r = s.derived.recon();
  const CompareResult* c = s.derived.compare();
  if (!r || !c) return false;
  const auto& o = s.view.overlays;
  const Pose3 truth = toPose3(frameAtPhase(r->wTrue, phase));
  scene.floor.shadowCentre = {truth[static_cast<std::size_t>(index(Joint::Pelvis))].x,
                              truth[static_cast<std::size_t>(index(Joint::Pelvis))].y};
  for (std::size_t k = 0; k < c->engines.size(); ++k) {
    const CompareEntry& e = c->engines[k];
    if (!e.display || !s.doc.compareShown[k]) continue;
    addFigure(scene, toPose3(frameAtPhase(e.display->w, phase)), engineStyle(static_cast<int>(k)));
  }
  if (o.ghost) addFigure(scene, truth, ghostStyle());
  if (o.cameraGlyph) addCameraGlyph(scene, r->alphaTrueDeg, 1150.0f, palette::kCamera, false);
  return true;
}

bool buildReconstructionScene(const AppState& s, Scene& scene, float lineScale, double cycles, float* errorScale) {
  scene.clearItems();
  const auto& o = s.view.overlays;
  const double phase = cycles - std::floor(cycles);
  const bool reconstruct = s.doc.mode == Mode::Reconstruct;
  const ReconBase* r = s.derived.recon();
  const ReconDisplay* d = s.derived.display();
  const ExploreResult* e = s.derived.explore();
  scene.floor.visible = o.grid;
  scene.floor.scrollMm = static_cast<float>(std::fmod(cycles * strideLengthMm(s), 1000.0));
  bool drawn = false;
  if (stageDrawsViews(s)) {
    // A quiz's 3D view stays empty: the room answers from the 2D view alone.
    drawn = !s.quiz.running() && buildStageReconstructionScene(s, scene, lineScale, cycles);
  } else if (reconstruct && s.doc.compareEngines) {
    drawn = buildCompareScene(s, scene, phase);
  } else if (reconstruct && r && d) {
    const Pose3 truth = toPose3(frameAtPhase(r->wTrue, phase));
    const Pose3 rec = toPose3(frameAtPhase(d->w, phase));
    scene.floor.shadowCentre = {rec[static_cast<std::size_t>(index(Joint::Pelvis))].x,
                                rec[static_cast<std::size_t>(index(Joint::Pelvis))].y};
    std::array<glm::vec4, kJointCount> colours{};
    *errorScale = palette::errorScaleMm(static_cast<float>(d->depthRmsMm.maxCoeff()));
    for (int j = 0; j < kJointCount; ++j)
      colours[static_cast<std::size_t>(j)] =
          palette::errorColour(static_cast<float>(d->depthRmsMm(j)) / *errorScale);
    // Joints the marker set lacked: their ground truth is the model's own estimate, so they
    // get the model-estimated colour and no error line (their errors are reported apart).
    Pose3 lineTruth = truth;
    for (std::size_t j = 0; j < colours.size(); ++j) {
      if (!r->modelEstimated[j]) continue;
      colours[j] = palette::kModelEstimated;
      lineTruth[j] = rec[j];
    }
    if (o.pointLights) {
      for (const auto& p : rec) scene.glows.push_back({p, 34.0f, palette::kInputPoint});
    } else if (o.depthErrorColour) {
      addFigure(scene, rec, reconstructionStyle(), std::span<const glm::vec4, kJointCount>(colours));
    } else {
      addFigure(scene, rec, reconstructionStyle());
    }
    if (o.ghost && !o.pointLights) addFigure(scene, truth, ghostStyle());
    if (o.errorLines && !o.pointLights)
      addErrorLines(scene, lineTruth, rec, palette::kError, 2.5f * lineScale);
    if (o.cameraGlyph) {
      addCameraGlyph(scene, r->alphaTrueDeg, 1150.0f, palette::kCamera, false);
      if (s.doc.recon.unknownAngle)
        addCameraGlyph(scene, r->alphaUsedDeg, 1000.0f, palette::kCameraEstimate, true);
    }
    drawn = true;
  } else if (!reconstruct && e) {
    const Pose3 pose = toPose3(frameAtPhase(e->w, phase));
    scene.floor.shadowCentre = {pose[static_cast<std::size_t>(index(Joint::Pelvis))].x,
                                pose[static_cast<std::size_t>(index(Joint::Pelvis))].y};
    if (o.pointLights) {
      for (const auto& p : pose) scene.glows.push_back({p, 34.0f, palette::kInputPoint});
    } else {
      addFigure(scene, pose, reconstructionStyle());
    }
    if (o.cameraGlyph) addCameraGlyph(scene, s.doc.recon.alphaDeg, 1150.0f, palette::kCamera, false);
    drawn = true;
  }
  return drawn;
}

void ReconstructionViewPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0, 0));
  if (beginPanel(ctx.backdrop, "3D reconstruction", rect, ImGuiWindowFlags_NoScrollbar | ImGuiWindowFlags_NoTitleBar |
                                        ImGuiWindowFlags_NoBackground)) {
    const ImVec2 p0 = ImGui::GetCursorScreenPos();
    const ImVec2 size = ImGui::GetContentRegionAvail();
    const ImVec2 fbScale = ImGui::GetIO().DisplayFramebufferScale;
    if (size.x > 4.0f && size.y > 4.0f) {
      ImGui::InvisibleButton("##orbit", size,
                             ImGuiButtonFlags_MouseButtonLeft | ImGuiButtonFlags_MouseButtonRight |
                                 ImGuiButtonFlags_MouseButtonMiddle);
      handleMouse(s.view.camera, size);

      target.ensure(static_cast<int>(size.x * fbScale.x), static_cast<int>(size.y * fbScale.y),
                    ctx.renderer.samples());
      const auto& o = s.view.overlays;
      const bool reconstruct = s.doc.mode == Mode::Reconstruct;
      const ReconDisplay* d = s.derived.display();
      float errorScale = 1.0f;
      const bool clipMode = s.doc.mode == Mode::Clip;
      const ClipResult* fit = s.clip.fit().get();
      const int clipFrame = fit ? clipFrameAt(*fit, s.view.playback.cycles) : 0;
      const bool drawn =
          clipMode ? buildClipReconstructionScene(s, scene, ctx.scale, clipFrame)
                   : buildReconstructionScene(s, scene, ctx.scale, s.view.playback.cycles, &errorScale);
      const float aspect = size.x / size.y;
      const OrbitCamera view = clipMode && fit ? clipViewCamera(s.view.camera, *fit, clipFrame) : s.view.camera;
      const ViewCaption caption = walkerReconstructionCaption(s);
      const char* title = caption.title.c_str();
      const std::vector<LegendItem>& legend = caption.legend;
      const std::string& sub = caption.subtitle;
      const float pad = 10.0f * ctx.scale;
      // Where the walker is over its cycle (what the annotations keep clear of), once a frame.
      ImRect walker(p0, p0);
      CameraMatrices camera = view.matrices(aspect);
      if (!clipMode && drawn) {
        walker = walkerOnScreen(s, camera, p0, size, ctx.scale);
        camera = clearOfOverlays(camera, walker, title, legendSize(legend, ctx.scale, size.x), p0, size, ctx.scale);
      }
      ctx.renderer.render(target, scene, camera);
      lastImage = {p0, size};

      ImDrawList* dl = ImGui::GetWindowDrawList();
      const ImVec2 p1{p0.x + size.x, p0.y + size.y};
      ctx.backdrop.image(target, {p0.x, p0.y});
      if (clipMode) {
        if (drawn) drawClipAnnotations(s, ctx, p0, size);
      } else {
      const ImRect captionRect =
          drawCaption(dl, ImVec2(p0.x + pad, p0.y + pad), title, sub,
                      s.fonts.large, ctx.scale, ImVec2(size.x - 2.0f * pad, size.y), walker);
      const ImRect legendRect = drawLegend(dl, ImVec2(p0.x + pad, p1.y - pad), legend, ctx.scale, size.x, walker);
      ImRect bar = kNothing;
      if (reconstruct && d && o.depthErrorColour && !o.pointLights && !s.doc.compareEngines && !stageDrawsViews(s))
        bar = drawColourBarClearOf(dl, captionRect, legendRect, walker, p0, p1, size, errorScale, ctx.scale,
                                   s.view.presentation);
      if (drawn) {
        s.lastFrame.overlay("reconstruction.walker", toPanelRect(walker));
        s.lastFrame.overlay("reconstruction.caption", toPanelRect(captionRect));
        s.lastFrame.overlay("reconstruction.legend", toPanelRect(legendRect));
        if (bar.GetWidth() > 0.0f) s.lastFrame.overlay("reconstruction.colour_bar", toPanelRect(bar));
      }
      }
      // A quiz leaves the view empty but for its caption (the quiz window floats over it).
      if (!drawn && !(s.quiz.running() && !clipMode)) {
        const std::optional<VideoSession>& video = s.video.session;
        const bool tracked = video && video->tracked;
        const bool detected = video && video->detected && video->detected->people > 0;
        const bool unfitted = clipMode && video && !s.clip.settings && (tracked || detected) &&
                              !s.video.track.running() && !s.video.detect.running();
        const char* msg = clipMode && video && !s.clip.settings
                              ? (s.video.track.running()    ? "tracking…"
                                 : s.video.detect.running() ? "detecting people… the walker appears when they are found"
                                 : tracked                  ? "no walk fits this track"
                                 : detected                 ? "no walk fits the people detected"
                                 : video->detected          ? "nobody detected: mark the joints on one frame, then Track"
                                                            : "detect the walker, or mark the joints on one frame, then Track")
                          : clipMode ? (s.clip.fits.running() ? "fitting the camera…" : unfittedClipMessage(s.clip.fits.error()))
                          : s.jobsBusy() ? "building models…" : "nothing to show";
        const float height = drawCentredMessage(dl, p0, size, msg);
        if (unfitted) drawWhyNoWalkFits(dl, s, p0, size, height);
      }
    }
  }
  ImGui::End();
  ImGui::PopStyleVar();
}

}  // namespace ew::ui

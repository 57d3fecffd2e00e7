#include "ui/panels/header_panel.h"

#include <algorithm>
#include <cstdio>
#include <exception>
#include <functional>
#include <string>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/held_model.h"
#include "ui/app/undo.h"
#include "ui/panels/camera_text.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/text_fit.h"

namespace ew::ui {

namespace {

std::string componentsText(int n, bool automatic, double explained) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "N = %d%s (%.1f %% of variance)", n, automatic ? " auto" : "",
                100.0 * explained);
  return buf;
}

// Progress of the background work, right-aligned (returns the x where it starts).
float drawProgress(AppState& s, const FrameContext& ctx, float right) {
  const float w = std::min(420.0f * ctx.scale, 0.3f * right);
  if (s.exports.video) {
    const auto& v = *s.exports.video;
    const std::string what =
        "Video: frame " + std::to_string(v.framesDone()) + " of " + std::to_string(v.frameCount());
    const float cancelW = ImGui::CalcTextSize("Cancel").x + 2.0f * ImGui::GetStyle().FramePadding.x;
    const float x = right - w - cancelW - ImGui::GetStyle().ItemSpacing.x;
    ImGui::SameLine(x);
    ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.32f, 0.88f, 0.76f, 0.9f));
    ImGui::ProgressBar(v.fraction(), ImVec2(w, 0.0f), what.c_str());
    ImGui::PopStyleColor();
    ImGui::SameLine();
    if (ImGui::SmallButton("Cancel")) actions::cancelVideoExport(s);
    return x;
  }
  if (s.video.track.running()) {
    const std::string what = s.video.track.title() + ": " + s.video.track.what();
    const float cancelW = ImGui::CalcTextSize("Cancel").x + 2.0f * ImGui::GetStyle().FramePadding.x;
    const float x = right - w - cancelW - ImGui::GetStyle().ItemSpacing.x;
    ImGui::SameLine(x);
    ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.32f, 0.88f, 0.76f, 0.9f));
    ImGui::ProgressBar(s.video.track.fraction(), ImVec2(w, 0.0f), fitText(what, w).c_str());
    ImGui::PopStyleColor();
    ImGui::SameLine();
    if (ImGui::SmallButton("Cancel")) actions::cancelTracking(s);
    return x;
  }
  if (!s.jobsBusy()) return right;
  const bool loading = s.loading.population.running();
  const bool clipping = !loading && !s.loading.models.running() && s.clip.fits.running();
  const bool analysing = !loading && !clipping && !s.loading.models.running() && s.jobs.analysis.running();
  // The camera fit reports no steps: the bar runs empty with its title.
  const float fraction = loading     ? s.loading.population.fraction()
                         : clipping  ? 0.0f
                         : analysing ? s.jobs.analysis.fraction()
                                     : s.loading.models.fraction();
  const std::string what = loading     ? s.loading.population.title() + ": " + s.loading.population.what()
                           : clipping  ? s.clip.fits.title() + "…"
                           : analysing ? s.jobs.analysis.title()
                                       : s.loading.models.title() + ": " + s.loading.models.what();
  ImGui::SameLine(right - w);
  ImGui::PushStyleColor(ImGuiCol_PlotHistogram, ImVec4(0.32f, 0.88f, 0.76f, 0.9f));
  ImGui::ProgressBar(fraction, ImVec2(w, 0.0f), fitText(what, w).c_str());
  ImGui::PopStyleColor();
  return right - w;
}

// One entry of the model selector; a choice that fails says why in the log.
void modelChoice(AppState& s, const char* label, bool selected, bool enabled,
                 const std::string& which) {
  if (!enabled) ImGui::BeginDisabled();
  if (radioWrapped(label, selected) && !selected) {
    try {
      actions::setModelSource(s, which);
    } catch (const std::exception& e) {
      actions::reportError(s, "Could not use that model", e.what());
    }
  }
  if (!enabled) ImGui::EndDisabled();
}

// One button of the header: its label, what it says on hover, whether it can be pressed now.
struct HeaderButton {
  const char* label;
  const char* tooltip;
  bool enabled;
  std::function<void()> press;
  const char* menuLabel = nullptr;  // under More…, where a symbol alone says too little
};

std::vector<HeaderButton> headerButtons(AppState& s, HeaderPanel& h) {
  return {
      {"Open…", "Open a population, a walker, a keypoint clip or a video", true,
       [&s] { s.panels.data.open = !s.panels.data.open; }},
      {"Model…", "Which model the walkers are inspected against", true, [&h] { h.modelMenuOpen = !h.modelMenuOpen; }},
      {"Export…", "Screenshots, video, the walker as CSV/BVH, the model", true,
       [&s] { s.panels.exports.open = !s.panels.exports.open; }},
      {"Analysis", "Error against view angle, over every walker", true,
       [&s] { s.panels.analysis.open = !s.panels.analysis.open; }},
      {"Gait", "Gait report: cadence, stride, stance, … and flexion curves, against the population", true,
       [&s] { s.panels.gait.open = !s.panels.gait.open; }},
      {"Tour", "A guided tour of the method, step by step", true,
       [&s] {
         if (s.panels.tour.active) {
           actions::tourEnd(s);
         } else if (s.doc.ready()) {
           actions::tourStart(s);
         }
       }},
      {"Present", "Presentation mode: only the two views, large captions (F5)", true,
       [&s] { actions::setPresentation(s, true); }},
      {"↶", "Undo the last change (Ctrl+Z)", canUndo(s), [&s] { undo(s); }, "↶  Undo"},
      {"↷", "Redo (Ctrl+Shift+Z or Ctrl+Y)", canRedo(s), [&s] { redo(s); }, "↷  Redo"},
      {"?", "Keyboard and mouse (F1)", true, [&s] { s.panels.help.open = !s.panels.help.open; },
       "?  Keyboard and mouse"},
  };
}

void drawHeaderButton(const HeaderButton& b) {
  ImGui::BeginDisabled(!b.enabled);
  if (ImGui::Button(b.label)) b.press();
  ImGui::EndDisabled();
  if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", b.tooltip);
}

// The buttons that fit `room` in a row, the rest under a "More" button's menu (a small
// window or a large UI scale).
void drawHeaderButtons(AppState& s, std::vector<HeaderButton> buttons, float room) {
  HeaderPanel& h = s.panels.header;
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float moreW = buttonWidth("More…") + spacing;
  float total = 0.0f;
  for (const auto& b : buttons) total += buttonWidth(b.label) + spacing;
  std::size_t inRow = buttons.size();
  if (total > room) {
    float used = moreW;
    inRow = 0;
    while (inRow < buttons.size() && used + buttonWidth(buttons[inRow].label) + spacing <= room)
      used += buttonWidth(buttons[inRow++].label) + spacing;
  }
  for (std::size_t i = 0; i < inRow; ++i) {
    if (i > 0) ImGui::SameLine();
    drawHeaderButton(buttons[i]);
  }
  h.moreShown = inRow < buttons.size();
  if (!h.moreShown) {
    h.openMore = false;
    return;
  }
  if (inRow > 0) ImGui::SameLine();
  if (ImGui::Button("More…") || h.openMore) ImGui::OpenPopup("##header_more");
  h.openMore = false;
  // Under its button, as a menu drops (not wherever the mouse was), kept on the screen.
  const ImVec2 under(ImGui::GetItemRectMin().x, ImGui::GetItemRectMax().y);
  ImGui::SetNextWindowPos(under, ImGuiCond_Appearing);
  if (ImGui::BeginPopup("##header_more")) {
    s.lastFrame.drawn.emplace_back("header_more");
    for (std::size_t i = inRow; i < buttons.size(); ++i) {
      const auto& b = buttons[i];
      const std::string item = std::string(b.menuLabel ? b.menuLabel : b.label) + "##more";
      if (ImGui::MenuItem(item.c_str(), nullptr, false, b.enabled)) b.press();
      if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", b.tooltip);
    }
    ImGui::EndPopup();
  }
}

}  // namespace

std::vector<std::string> clipLines(const ClipResult& c) {
  const CameraFit& f = c.rec.fit;
  const WalkCamera& cam = f.camera;
  char camera[200], brief[120];
  if (cam.model == CameraModel::Pinhole) {
    // The walker's distance, not the camera's from its look-at point: a walk along the line of
    // sight barely fixes that point, and the walker is what the user asks about.
    std::snprintf(camera, sizeof camera, "camera: azimuth %.1f° · %s · focal %.0f px%s · walker %.2f m away · reprojection %.1f px RMS",
                  cam.alphaDeg, tiltText(cam.elevationDeg).c_str(), cam.focalPx,
                  c.settings.focalPx || !c.settings.calibrationFile.empty() ? "" : " (est.)",
                  f.walkerDistanceM, f.reprojectionRmsPx);
    std::snprintf(brief, sizeof brief, "az %.1f° · %s · f %.0f px · %.1f m · %.1f px", cam.alphaDeg,
                  tiltText(cam.elevationDeg).c_str(), cam.focalPx, f.walkerDistanceM, f.reprojectionRmsPx);
  } else {
    std::snprintf(camera, sizeof camera, "camera (scaled orthography): azimuth %.1f° · %s · %.3f px/mm · reprojection %.1f px RMS",
                  cam.alphaDeg, tiltText(cam.elevationDeg).c_str(), cam.pxPerMm, f.reprojectionRmsPx);
    std::snprintf(brief, sizeof brief, "az %.1f° · %s · %.1f px", cam.alphaDeg, tiltText(cam.elevationDeg).c_str(),
                  f.reprojectionRmsPx);
  }
  const std::string held = heldCameraValues(c.settings);
  const std::string withHeld = std::string(camera) + (held.empty() ? "" : "  ·  held: " + held);
  const std::string model = "model: " + c.model.name;
  const std::string clip = "clip: " + c.settings.path.filename().string() + " (" + c.rec.trial.format + ", " +
                           c.rec.trial.layout->name + ", " + std::to_string(c.rec.trial.frameCount) + " frames)";
  return {withHeld + "  ·  " + model + "  ·  " + clip, withHeld + "  ·  " + model, camera, brief};
}

std::vector<std::string> modelLines(const AppState& s) {
  std::string full, medium, brief;
  if (s.doc.mode == Mode::Clip) {
    if (s.clip.fit()) return clipLines(*s.clip.fit());
    return {"", "", "", ""};
  }
  if (s.doc.mode == Mode::Reconstruct) {
    if (const auto* r = s.derived.recon()) {
      const std::string n =
          "N = " + std::to_string(r->components) + (r->autoComponents ? " auto" : "");
      full = "model: " + r->modelName + "  ·  ";
      full += r->inModel ? "in the model: leave-one-out model without " + r->heldOutSubject + " (" +
                               std::to_string(r->modelWalkers) + " walkers)"
                         : std::string("walker not in the model");
      full += "  ·  " + componentsText(r->components, r->autoComponents, r->explained);
      medium = "model: " + r->modelName + "  ·  " +
               (r->inModel ? "in it: leave-one-out without " + r->heldOutSubject
                           : "walker not in the model") +
               "  ·  " + n;
      brief =
          r->modelName + " · " + (r->inModel ? "without " + r->heldOutSubject : "not in the model");
    } else if (s.doc.heldModel()) {
      full = medium = brief = "model: " + heldModelName(s.doc);
    }
  } else if (const auto* e = s.derived.explore()) {
    full = "model: " + e->modelName + ", all " + std::to_string(e->modelWalkers) + " walkers  ·  " +
           componentsText(e->components, e->autoComponents, e->explained);
    medium = brief = "model: " + e->modelName;
  }
  // The model's facts alone come before the data's: they matter more when room is short.
  std::string withData = full;
  if (s.doc.population)
    withData += (withData.empty() ? "" : "  ·  ") + std::string("data: ") +
                s.doc.population->label + " (" + std::to_string(s.doc.population->walkerCount()) +
                " walkers)";
  if (s.doc.inspected)
    withData +=
        "  ·  inspecting " + std::to_string(s.doc.inspected->walkerCount()) + " of your own";
  return {withData, full, medium, brief};
}

void HeaderPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "##header", rect,
                 ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar)) {
    // The name goes first when the window is too narrow for it and every button (a large UI
    // scale), then the buttons that do not fit go under "More": the buttons are what the
    // header is for.
    const ImGuiStyle& style = ImGui::GetStyle();
    auto buttons = headerButtons(s, *this);
    float buttonsW = 0.0f;
    for (const auto& b : buttons) buttonsW += buttonWidth(b.label) + style.ItemSpacing.x;
    if (s.fonts.large) ImGui::PushFont(s.fonts.large);
    const bool named = ImGui::CalcTextSize("Eigenwalker").x + 18.0f * ctx.scale + buttonsW <=
                       ImGui::GetContentRegionAvail().x;
    if (named) {
      ImGui::TextColored(ImVec4(1.0f, 0.72f, 0.38f, 1.0f), "Eigenwalker");
      ImGui::SameLine(0.0f, 18.0f * ctx.scale);
    }
    if (s.fonts.large) ImGui::PopFont();
    const float rowX = ImGui::GetCursorPosX();
    drawHeaderButtons(s, std::move(buttons), ImGui::GetContentRegionAvail().x);
    // The model selector opens under its button, the row's second.
    modelButtonX = ImGui::GetWindowPos().x + rowX + buttonWidth("Open…") + style.ItemSpacing.x;
    modelButtonBottom = ImGui::GetItemRectMax().y;
    ImGui::SameLine(0.0f, 18.0f * ctx.scale);
    const float lineX = ImGui::GetCursorPosX();
    const float progressX = drawProgress(s, ctx, ImGui::GetWindowContentRegionMax().x);
    // The model line fills what the buttons and the progress bar leave, never overprinting.
    // The longest of the line's forms that fits (the last one shortened when none does).
    const auto lines = modelLines(s);
    // (Left out when the room would hold only a word or two of it.)
    if (!lines.front().empty() && progressX - lineX >= 160.0f * ctx.scale) {
      ImGui::SameLine(lineX);
      ImGui::AlignTextToFramePadding();
      const float room = std::max(0.0f, progressX - lineX - 12.0f * ctx.scale);
      std::string shown = lines.back().empty() ? lines.front() : lines.back();
      for (const auto& l : lines) {
        if (ImGui::CalcTextSize(l.c_str()).x <= room) {
          shown = l;
          break;
        }
      }
      ImGui::TextUnformatted(fitText(shown, room).c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", lines.front().c_str());
    }
  }
  ImGui::End();
}

void HeaderPanel::drawModelMenu(AppState& s, const FrameContext& ctx) {
  if (!modelMenuOpen) return;
  const auto& d = s.doc;
  const std::string pop = d.population ? "Population: " + d.population->label + " (" +
                                             std::to_string(d.population->walkerCount()) +
                                             " walkers, leave-one-out)"
                                       : std::string("Population (none loaded)");
  const std::string def =
      d.defaultModel ? "Default: " + d.defaultModel->name : std::string("Default: real walkers");
  std::vector<std::string> files;
  for (const auto& m : d.modelFiles)
    files.push_back("File: " + m->name + " (" + std::to_string(m->model.walkerCount()) + " walkers)");
  const char* about = "Every walker is reconstructed with this model; a walker it was built from is "
                      "reconstructed with the model without its subject.";
  const char* footer = "Open or drop a .ewm file (eigenwalker-cli build) to add one.";
  // As wide as its longest line wants, but never past the screen's edge: there it wraps.
  float wanted = std::max(ImGui::CalcTextSize(footer).x,
                          ImGui::CalcTextSize("Every walker is reconstructed with this model; a walker it was built").x);
  for (const std::string* l : {&pop, &def}) wanted = std::max(wanted, toggleWidth(l->c_str()));
  for (const auto& l : files) wanted = std::max(wanted, toggleWidth(l.c_str()));
  const float margin = 8.0f * ctx.scale;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = std::min(wanted + 2.0f * ImGui::GetStyle().WindowPadding.x, display.x - 2.0f * margin);
  const float x = std::clamp(modelButtonX, margin, display.x - margin - width);
  ImGui::SetNextWindowPos(ImVec2(x, modelButtonBottom + 4.0f * ctx.scale), ImGuiCond_Always);
  ImGui::SetNextWindowSize(ImVec2(width, 0.0f), ImGuiCond_Always);  // 0: the height fits the content
  bool open = true;
  if (ImGui::Begin("Model###model_menu", &open,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoMove)) {
    textDisabledWrapped(about);
    ImGui::Separator();
    modelChoice(s, pop.c_str(), d.modelSource == ModelSource::Population, d.models != nullptr,
                "population");
    modelChoice(s, def.c_str(), d.modelSource == ModelSource::Default, true, "default");
    for (std::size_t i = 0; i < files.size(); ++i) {
      ImGui::PushID(static_cast<int>(i));
      modelChoice(s, files[i].c_str(),
                  d.modelSource == ModelSource::File && d.modelFile == static_cast<int>(i), true,
                  d.modelFiles[i]->file.string());
      ImGui::PopID();
    }
    ImGui::Separator();
    textDisabledWrapped(footer);
  }
  ImGui::End();
  if (!open) modelMenuOpen = false;
}

}  // namespace ew::ui

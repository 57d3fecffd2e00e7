#include "ui/panels/joint_errors_panel.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>

#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/render/palette.h"

namespace ew::ui {

namespace {

// One bar per joint: `values` (NaN: none, drawn as "–"), `apart` joints in the
// model-estimated colour with their value in parentheses. Returns the joint under the
// mouse, or -1.
int drawJointBars(const std::array<double, kJointCount>& values, const std::array<bool, kJointCount>& apart,
                  float scaleMax, float scale) {
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const float labelW = ImGui::CalcTextSize("r_shoulder ").x;
  const float valueW = ImGui::CalcTextSize("(000.0)").x + 6.0f * scale;
  const float textH = ImGui::GetTextLineHeight();
  // One column when 15 rows fit, else two side by side where each still shows its label,
  // value and a bar; else one column that scrolls (two cramped columns cut every value: the
  // drawer at 1280 × 720, UI scale 2).
  const bool rowsFit = size.y / static_cast<float>(kJointCount) >= textH + 2.0f;
  const bool twoColumnsFit = 0.5f * size.x >= labelW + valueW + 24.0f * scale;
  const int columns = rowsFit || !twoColumnsFit ? 1 : 2;
  const int rows = (kJointCount + columns - 1) / columns;
  const float colW = size.x / static_cast<float>(columns);
  const float rowH = std::max(size.y / static_cast<float>(rows), textH + 2.0f);
  const float height = rowH * static_cast<float>(rows);
  // The bar takes what the label and the value leave; none when they fill the column.
  const float barMax = std::max(0.0f, colW - labelW - valueW - 8.0f * scale);
  for (int j = 0; j < kJointCount; ++j) {
    const auto ju = static_cast<std::size_t>(j);
    const float x = p0.x + colW * static_cast<float>(j / rows);
    const float y = p0.y + rowH * static_cast<float>(j % rows);
    const bool known = std::isfinite(values[ju]);
    const float v = known ? static_cast<float>(values[ju]) : 0.0f;
    const float w = barMax * std::min(v / scaleMax, 1.0f);
    const auto name = kJointNames[ju];
    // Each cell clipped to its column: a narrow panel cuts a value, never overprints the
    // next column.
    dl->PushClipRect(ImVec2(x, p0.y), ImVec2(x + colW - 4.0f * scale, p0.y + height), true);
    dl->AddText(ImVec2(x, y + 0.5f * (rowH - textH)),
                apart[ju] ? toImU32(palette::kModelEstimated) : ImGui::GetColorU32(ImGuiCol_TextDisabled), name.data(),
                name.data() + name.size());
    const float bh = std::max(3.0f, std::min(rowH * 0.62f, textH * 0.8f));
    const float by = y + 0.5f * (rowH - bh);
    dl->AddRectFilled(ImVec2(x + labelW, by), ImVec2(x + labelW + barMax, by + bh), ImGui::GetColorU32(ImGuiCol_FrameBg),
                      2.0f);
    dl->AddRectFilled(ImVec2(x + labelW, by), ImVec2(x + labelW + w, by + bh),
                      apart[ju] ? toImU32(palette::kModelEstimated) : toImU32(palette::errorColour(v / scaleMax)), 2.0f);
    // Outlined: the map's pale low end on the light theme's track would barely show.
    if (w >= 1.0f)
      dl->AddRect(ImVec2(x + labelW, by), ImVec2(x + labelW + w, by + bh), ImGui::GetColorU32(ImGuiCol_TextDisabled, 0.7f),
                  2.0f, 0, std::max(1.0f, scale));
    char buf[32];
    if (!known) {
      std::snprintf(buf, sizeof buf, "–");
    } else {
      std::snprintf(buf, sizeof buf, apart[ju] ? "(%.1f)" : "%.1f", static_cast<double>(v));
    }
    dl->AddText(ImVec2(x + labelW + w + 4.0f * scale, y + 0.5f * (rowH - textH)),
                apart[ju] ? toImU32(palette::kModelEstimated) : ImGui::GetColorU32(ImGuiCol_Text), buf);
    dl->PopClipRect();
  }
  ImGui::Dummy(ImVec2(size.x, height));
  if (!ImGui::IsItemHovered()) return -1;
  const int col = std::clamp(static_cast<int>((ImGui::GetMousePos().x - p0.x) / colW), 0, columns - 1);
  const int row = std::clamp(static_cast<int>((ImGui::GetMousePos().y - p0.y) / rowH), 0, rows - 1);
  return std::min(col * rows + row, kJointCount - 1);
}

// Mode::Clip: each joint's reprojection residual, RMS over the frames that see it (px); a
// joint never seen has none (the model estimated it).
void drawClipResiduals(const AppState& s, float scale) {
  const ClipReconstruction& rec = s.clip.fit()->rec;
  std::array<bool, kJointCount> unseen{};
  for (int j : rec.fit.unseenJoints) unseen[static_cast<std::size_t>(j)] = true;
  double worst = 0.0;
  for (double v : rec.residualRmsPx)
    if (std::isfinite(v)) worst = std::max(worst, v);
  const float scaleMax = std::max(5.0f, palette::errorScaleMm(static_cast<float>(worst)));
  const int j = drawJointBars(rec.residualRmsPx, unseen, scaleMax, scale);
  if (j < 0) return;
  const auto ju = static_cast<std::size_t>(j);
  if (unseen[ju]) {
    ImGui::SetTooltip("%s: never seen in the clip; the model estimated it", kJointNames[ju].data());
  } else {
    ImGui::SetTooltip("%s: reprojection residual %.1f px RMS over the %.0f %% of frames that see it%s",
                      kJointNames[ju].data(), rec.residualRmsPx[ju], 100.0 * rec.trial.seenShare[ju],
                      rec.trial.derived[ju] ? "\nbuilt from other keypoints (not a detector point of its own)" : "");
  }
}

// Compare mode: a row of metrics per engine, then each joint's depth error per engine as
// three thin bars in the engines' colours.
void drawCompare(const CompareResult& c, float scale) {
  // Columns as wide as their contents: the panel is narrow; each header's tooltip says what it is.
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingFixedFit;
  static constexpr const char* kHeaders[] = {"engine", "MPJPE", "E_a", "E_r", "α", "2D", "ms"};
  static constexpr const char* kWhat[] = {
      "", "MPJPE: mean 3D joint error over one cycle (mm)", "E_a: mean squared depth error (mm²)",
      "E_r: E_a over the walker's own depth variance", "α the engine used (estimated when unknown)",
      "2D: RMS of the reconstruction's reprojection against the input (mm)",
      "ms: the reconstruction's wall time (the snippet prior's training included the first time)"};
  // A narrow panel keeps engine, MPJPE, α and ms; a row's tooltip gives every column.
  const float full = ImGui::CalcTextSize("skeleton  MPJPE  E_a  E_r  -179.9°  2D  1527").x + 12.0f * 7 * scale;
  const float reduced = ImGui::CalcTextSize("skeleton  MPJPE  -179.9°  1527").x + 12.0f * 4 * scale;
  const float avail = ImGui::GetContentRegionAvail().x;
  const std::vector<int> shown = avail >= full      ? std::vector<int>{0, 1, 2, 3, 4, 5, 6}
                                 : avail >= reduced ? std::vector<int>{0, 1, 4, 6}
                                                    : std::vector<int>{0, 1, 4};
  if (ImGui::BeginTable("compare_table", static_cast<int>(shown.size()), flags)) {
    for (int col : shown) ImGui::TableSetupColumn(kHeaders[col]);
    ImGui::TableNextRow(ImGuiTableRowFlags_Headers);
    for (std::size_t i = 0; i < shown.size(); ++i) {
      ImGui::TableSetColumnIndex(static_cast<int>(i));
      ImGui::TableHeader(kHeaders[shown[i]]);
      if (shown[i] > 0 && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", kWhat[shown[i]]);
    }
    for (const auto& e : c.engines) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextColored(toImVec4(palette::kEngineRight[static_cast<std::size_t>(e.engine)]), "%s", engineName(e.engine));
      if (!e.display || !e.base) {
        ImGui::TableNextColumn();
        ImGui::TextDisabled("no answer");
        if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", e.error.c_str());
        continue;
      }
      const ReconDisplay& d = *e.display;
      char cells[7][32];
      std::snprintf(cells[1], sizeof cells[1], "%.1f", d.mpjpeMm);
      std::snprintf(cells[2], sizeof cells[2], "%.0f", d.absScoredMm2);
      std::snprintf(cells[3], sizeof cells[3], "%.3f", d.relScored);
      std::snprintf(cells[4], sizeof cells[4], "%.1f°", e.base->alphaUsedDeg);
      std::snprintf(cells[5], sizeof cells[5], "%.1f", d.residualRmsMm);
      std::snprintf(cells[6], sizeof cells[6], "%.0f", 1000.0 * e.seconds);
      for (std::size_t i = 1; i < shown.size(); ++i) {
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(cells[shown[i]]);
        if (ImGui::IsItemHovered())
          ImGui::SetTooltip("%s: MPJPE %s mm, E_a %s mm², E_r %s, α %s, 2D %s mm, %s ms", engineName(e.engine),
                            cells[1], cells[2], cells[3], cells[4], cells[5], cells[6]);
      }
    }
    ImGui::EndTable();
  }
  // Per joint: √E_abs(j) of each engine.
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  const ImVec2 size = ImGui::GetContentRegionAvail();
  const int fit = static_cast<int>(size.y / ImGui::GetTextLineHeight());
  if (3 * fit < kJointCount) {  // three columns of joints do not fit: no bars rather than overprinted ones
    ImGui::TextDisabled("per-joint errors: a taller window shows them");
    return;
  }
  double worst = 1.0;
  for (const auto& e : c.engines)
    if (e.display) worst = std::max(worst, e.display->depthRmsMm.maxCoeff());
  const float scaleMax = palette::errorScaleMm(static_cast<float>(worst));
  const int columns = fit >= kJointCount ? 1 : 3;
  const int rows = (kJointCount + columns - 1) / columns;
  const float colW = size.x / static_cast<float>(columns), rowH = size.y / static_cast<float>(rows);
  const float labelW = ImGui::CalcTextSize("r_shoulder ").x;
  const float barMax = std::max(0.0f, colW - labelW - 10.0f * scale);
  for (int j = 0; j < kJointCount; ++j) {
    const float x = p0.x + colW * static_cast<float>(j / rows), y = p0.y + rowH * static_cast<float>(j % rows);
    const auto name = kJointNames[static_cast<std::size_t>(j)];
    dl->AddText(ImVec2(x, y + 0.5f * (rowH - ImGui::GetTextLineHeight())), ImGui::GetColorU32(ImGuiCol_TextDisabled),
                name.data(), name.data() + name.size());
    const float bh = std::max(1.5f, std::min(rowH / 3.6f, 5.0f * scale));
    for (std::size_t k = 0; k < c.engines.size(); ++k) {
      const auto& e = c.engines[k];
      if (!e.display) continue;
      const float w = barMax * std::min(static_cast<float>(e.display->depthRmsMm(j)) / scaleMax, 1.0f);
      const float by = y + 0.5f * rowH - 1.5f * bh + static_cast<float>(k) * bh;
      dl->AddRectFilled(ImVec2(x + labelW, by), ImVec2(x + labelW + w, by + bh * 0.85f),
                        toImU32(palette::kEngineRight[k]));
    }
  }
  ImGui::Dummy(size);
  if (ImGui::IsItemHovered()) {
    const int col = std::clamp(static_cast<int>((ImGui::GetMousePos().x - p0.x) / colW), 0, columns - 1);
    const int row = std::clamp(static_cast<int>((ImGui::GetMousePos().y - p0.y) / rowH), 0, rows - 1);
    const int j = std::min(col * rows + row, kJointCount - 1);
    std::string tip = std::string(kJointNames[static_cast<std::size_t>(j)]) + ": RMS depth error";
    for (const auto& e : c.engines) {
      char line[96];
      if (e.display)
        std::snprintf(line, sizeof line, "\n  %s %.1f mm", engineName(e.engine), e.display->depthRmsMm(j));
      else
        std::snprintf(line, sizeof line, "\n  %s: no answer", engineName(e.engine));
      tip += line;
    }
    ImGui::SetTooltip("%s", tip.c_str());
  }
}

}  // namespace

void JointErrorsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  const bool clip = s.doc.mode == Mode::Clip;
  const bool compare = s.doc.compareEngines && s.doc.mode == Mode::Reconstruct;
  const char* title = clip      ? fittingTitle("Reprojection residual per joint (RMS over the clip, px)###joint_errors",
                                               "Residual per joint (px)###joint_errors", rect.size.x)
                      : compare ? fittingTitle("Engines vs ground truth; depth RMS per joint (mm)###joint_errors",
                                               "Engines: depth RMS (mm)###joint_errors", rect.size.x)
                                : fittingTitle("Depth error per joint (RMS over one cycle, mm)###joint_errors",
                                               "Depth error per joint (mm)###joint_errors", rect.size.x);
  if (beginPanel(ctx.backdrop, title, rect)) {  // a scrollbar only where one column overflows
    const ReconDisplay* d = s.derived.display();
    const ReconBase* r = s.derived.recon();
    if (s.doc.mode == Mode::Explore) {
      ImGui::TextDisabled("reconstruct mode only");
    } else if (!s.view.overlays.errorBars) {
      ImGui::TextDisabled("hidden (overlay \"error bars\")");
    } else if (compare) {
      if (const CompareResult* c = s.derived.compare()) {
        drawCompare(*c, ctx.scale);
      } else {
        ImGui::TextDisabled("no reconstruction");
      }
    } else if (clip) {
      if (s.clip.fit()) {
        drawClipResiduals(s, ctx.scale);
      } else {
        ImGui::TextDisabled("no fit yet");
      }
    } else if (d) {
      std::array<double, kJointCount> values{};
      std::array<bool, kJointCount> estimated{};
      for (int j = 0; j < kJointCount; ++j) {
        values[static_cast<std::size_t>(j)] = d->depthRmsMm(j);
        // Model-estimated joints (the marker set lacked them) have no truth, only the model's
        // completion: drawn apart, so they never read as measured errors.
        estimated[static_cast<std::size_t>(j)] = r && r->modelEstimated[static_cast<std::size_t>(j)];
      }
      const float scaleMm = palette::errorScaleMm(static_cast<float>(d->depthRmsMm.maxCoeff()));
      const int j = drawJointBars(values, estimated, scaleMm, ctx.scale);
      if (j >= 0) {
        ImGui::SetTooltip("%s: RMS depth error %.1f mm (E_abs %.0f mm², E_rel %.3f)%s",
                          kJointNames[static_cast<std::size_t>(j)].data(), d->depthRmsMm(j),
                          d->errors.absPerJoint(j), d->errors.relPerJoint(j),
                          estimated[static_cast<std::size_t>(j)]
                              ? "\nmodel-estimated: the marker set lacks this joint; the error is "
                                "against the model's own completion, not a measurement"
                              : "");
      }
    } else {
      ImGui::TextDisabled("no reconstruction");
    }
  }
  ImGui::End();
}

}  // namespace ew::ui

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
  // One column when 15 rows fit, else two side by side.
  const int columns = size.y / static_cast<float>(kJointCount) >= textH + 2.0f ? 1 : 2;
  const int rows = (kJointCount + columns - 1) / columns;
  const float colW = size.x / static_cast<float>(columns);
  const float rowH = size.y / static_cast<float>(rows);
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
    dl->PushClipRect(ImVec2(x, p0.y), ImVec2(x + colW - 4.0f * scale, p0.y + size.y), true);
    dl->AddText(ImVec2(x, y + 0.5f * (rowH - textH)),
                apart[ju] ? toImU32(palette::kModelEstimated) : ImGui::GetColorU32(ImGuiCol_TextDisabled), name.data(),
                name.data() + name.size());
    const float bh = std::max(3.0f, std::min(rowH * 0.62f, textH * 0.8f));
    const float by = y + 0.5f * (rowH - bh);
    dl->AddRectFilled(ImVec2(x + labelW, by), ImVec2(x + labelW + barMax, by + bh), ImGui::GetColorU32(ImGuiCol_FrameBg),
                      2.0f);
    dl->AddRectFilled(ImVec2(x + labelW, by), ImVec2(x + labelW + w, by + bh),
                      apart[ju] ? toImU32(palette::kModelEstimated) : toImU32(palette::errorColour(v / scaleMax)), 2.0f);
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
  ImGui::Dummy(size);
  if (!ImGui::IsItemHovered()) return -1;
  const int col = std::clamp(static_cast<int>((ImGui::GetMousePos().x - p0.x) / colW), 0, columns - 1);
  const int row = std::clamp(static_cast<int>((ImGui::GetMousePos().y - p0.y) / rowH), 0, rows - 1);
  return std::min(col * rows + row, kJointCount - 1);
}

// Mode::Clip: each joint's reprojection residual, RMS over the frames that see it (px); a
// joint never seen has none (the model estimated it).
void drawClipResiduals(const AppState& s, float scale) {
  const ClipReconstruction& rec = s.clip->rec;
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

}  // namespace

void JointErrorsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  const bool clip = s.doc.mode == Mode::Clip;
  const char* title = clip ? "Reprojection residual per joint (RMS over the clip, px)###joint_errors"
                           : "Depth error per joint (RMS over one cycle, mm)###joint_errors";
  if (beginPanel(ctx.backdrop, title, rect, ImGuiWindowFlags_NoScrollbar)) {
    const ReconDisplay* d = s.derived.display();
    const ReconBase* r = s.derived.recon();
    if (s.doc.mode == Mode::Explore) {
      ImGui::TextDisabled("reconstruct mode only");
    } else if (!s.view.overlays.errorBars) {
      ImGui::TextDisabled("hidden (overlay \"error bars\")");
    } else if (clip) {
      if (s.clip) {
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

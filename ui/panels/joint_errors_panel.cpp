#include "ui/panels/joint_errors_panel.h"

#include <algorithm>
#include <cstdio>

#include "ui/app/app_state.h"
#include "ui/convert.h"
#include "ui/render/palette.h"

namespace ew::ui {

void JointErrorsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  if (beginPanel(ctx.backdrop, "Depth error per joint (RMS over one cycle, mm)", rect, ImGuiWindowFlags_NoScrollbar)) {
    const ReconDisplay* d = s.derived.display();
    const ReconBase* r = s.derived.recon();
    if (s.doc.mode == Mode::Explore) {
      ImGui::TextDisabled("reconstruct mode only");
    } else if (!s.view.overlays.errorBars) {
      ImGui::TextDisabled("hidden (overlay \"error bars\")");
    } else if (d) {
      ImDrawList* dl = ImGui::GetWindowDrawList();
      const ImVec2 p0 = ImGui::GetCursorScreenPos();
      const ImVec2 size = ImGui::GetContentRegionAvail();
      const float labelW = ImGui::CalcTextSize("r_shoulder ").x;
      const float valueW = ImGui::CalcTextSize("(000.0)").x + 6.0f * ctx.scale;
      const float textH = ImGui::GetTextLineHeight();
      // One column when 15 rows fit, else two side by side.
      const int columns = size.y / static_cast<float>(kJointCount) >= textH + 2.0f ? 1 : 2;
      const int rows = (kJointCount + columns - 1) / columns;
      const float colW = size.x / static_cast<float>(columns);
      const float rowH = size.y / static_cast<float>(rows);
      // The bar takes what the label and the value leave; none when they fill the column.
      const float barMax = std::max(0.0f, colW - labelW - valueW - 8.0f * ctx.scale);
      const float scaleMm = palette::errorScaleMm(static_cast<float>(d->depthRmsMm.maxCoeff()));
      for (int j = 0; j < kJointCount; ++j) {
        const float x = p0.x + colW * static_cast<float>(j / rows);
        const float y = p0.y + rowH * static_cast<float>(j % rows);
        const float v = static_cast<float>(d->depthRmsMm(j));
        const float w = barMax * std::min(v / scaleMm, 1.0f);
        const auto name = kJointNames[static_cast<std::size_t>(j)];
        // Model-estimated joints (the marker set lacked them) have no truth, only the model's
        // completion: name, bar and value in the legend's colour, the value in parentheses,
        // so they never read as measured errors.
        const bool estimated = r && r->modelEstimated[static_cast<std::size_t>(j)];
        // Each cell clipped to its column: a narrow panel cuts a value, never overprints
        // the next column.
        dl->PushClipRect(ImVec2(x, p0.y), ImVec2(x + colW - 4.0f * ctx.scale, p0.y + size.y), true);
        dl->AddText(ImVec2(x, y + 0.5f * (rowH - textH)),
                    estimated ? toImU32(palette::kModelEstimated)
                              : ImGui::GetColorU32(ImGuiCol_TextDisabled),
                    name.data(), name.data() + name.size());
        const float bh = std::max(3.0f, std::min(rowH * 0.62f, textH * 0.8f));
        const float by = y + 0.5f * (rowH - bh);
        dl->AddRectFilled(ImVec2(x + labelW, by), ImVec2(x + labelW + barMax, by + bh),
                          ImGui::GetColorU32(ImGuiCol_FrameBg), 2.0f);
        dl->AddRectFilled(ImVec2(x + labelW, by), ImVec2(x + labelW + w, by + bh),
                          estimated ? toImU32(palette::kModelEstimated)
                                    : toImU32(palette::errorColour(v / scaleMm)),
                          2.0f);
        char buf[32];
        std::snprintf(buf, sizeof buf, estimated ? "(%.1f)" : "%.1f", static_cast<double>(v));
        dl->AddText(ImVec2(x + labelW + w + 4.0f * ctx.scale, y + 0.5f * (rowH - textH)),
                    estimated ? toImU32(palette::kModelEstimated) : ImGui::GetColorU32(ImGuiCol_Text),
                    buf);
        dl->PopClipRect();
      }
      ImGui::Dummy(size);
      if (ImGui::IsItemHovered()) {
        const int col = std::clamp(static_cast<int>((ImGui::GetMousePos().x - p0.x) / colW), 0, columns - 1);
        const int row = std::clamp(static_cast<int>((ImGui::GetMousePos().y - p0.y) / rowH), 0, rows - 1);
        const int j = std::min(col * rows + row, kJointCount - 1);
        ImGui::SetTooltip("%s: RMS depth error %.1f mm (E_abs %.0f mm², E_rel %.3f)%s",
                          kJointNames[static_cast<std::size_t>(j)].data(), d->depthRmsMm(j),
                          d->errors.absPerJoint(j), d->errors.relPerJoint(j),
                          r && r->modelEstimated[static_cast<std::size_t>(j)]
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

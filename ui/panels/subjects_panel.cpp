#include "ui/panels/subjects_panel.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/gait/dataset.h"
#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/text_fit.h"

namespace ew::ui {

namespace {

bool containsNoCase(const std::string& text, const char* needle) {
  std::string a = text, b = needle;
  auto lower = [](std::string& x) {
    std::transform(x.begin(), x.end(), x.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  };
  lower(a);
  lower(b);
  return a.find(b) != std::string::npos;
}

void fact(const char* label, const std::string& value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextDisabled("%s", label);
  ImGui::TableNextColumn();
  ImGui::TextWrapped("%s", value.c_str());
}

}  // namespace

void SubjectsPanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& rect) {
  // A notice row opening or closing moves the panel: keep the selected walker in view.
  if (rect.size.y != lastHeight) scrollToSelection = true;
  lastHeight = rect.size.y;
  if (beginPanel(ctx.backdrop, "Subjects", rect)) {
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputTextWithHint("##filter", "search subjects…", filter.data(), filter.size());
    // What goes below the list (the facts, whose rows vary with the walker, and the open row)
    // as the last frame measured it; a guess on the first.
    const float belowListHeight = belowList > 0.0f ? belowList : 175.0f * ctx.scale;
    const float listHeight = std::max(80.0f * ctx.scale, ImGui::GetContentRegionAvail().y - belowListHeight);
    // The source column only when the subject ids have room beside it (the facts below name it).
    const float idW = ImGui::CalcTextSize("SYN000_0").x, sourceW = ImGui::CalcTextSize("synthetic").x;
    const float hzW = ImGui::CalcTextSize("0.00").x;
    const float cellPad = 2.0f * ImGui::GetStyle().CellPadding.x + ImGui::GetStyle().ScrollbarSize;
    const bool withSource = idW + sourceW + hzW + 3.0f * cellPad <= ImGui::GetContentRegionAvail().x;
    if (ImGui::BeginTable("walkers", withSource ? 3 : 2,
                          ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH,
                          ImVec2(0.0f, listHeight))) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("subject", ImGuiTableColumnFlags_WidthStretch);
      if (withSource) ImGui::TableSetupColumn("source", ImGuiTableColumnFlags_WidthStretch);
      ImGui::TableSetupColumn("Hz", ImGuiTableColumnFlags_WidthFixed, hzW);
      ImGui::TableHeadersRow();
      {
        // The population's walkers, then the user's own trials inspected against the model.
        for (int i = 0; i < s.doc.walkerCount(); ++i) {
          const auto& w = *s.doc.walkerAt(i);
          if (i == s.doc.populationCount()) {
            ImGui::TableNextRow();
            ImGui::TableNextColumn();
            ImGui::TextColored(ImVec4(0.32f, 0.88f, 0.76f, 1.0f), "inspected");
            if (ImGui::IsItemHovered())
              ImGui::SetTooltip("Trials you opened, reconstructed with the model held (Model…)");
          }
          if (filter[0] != '\0' && !containsNoCase(w.id, filter.data()) &&
              !containsNoCase(w.source, filter.data()))
            continue;
          ImGui::TableNextRow();
          ImGui::TableNextColumn();
          const bool selected = i == s.doc.walker;
          ImGui::PushID(i);
          // (A long id ends in "…" in a narrow list; hovering names it whole.)
          const std::string shown = fitText(w.subject, ImGui::GetContentRegionAvail().x);
          if (ImGui::Selectable(shown.c_str(), selected, ImGuiSelectableFlags_SpanAllColumns))
            actions::selectWalker(s, i);
          if (shown != w.subject && ImGui::IsItemHovered()) ImGui::SetTooltip("%s", w.subject.c_str());
          if (selected && scrollToSelection) {
            // The list's height counts rows added this frame only from the next one: scroll twice.
            ImGui::SetScrollHereY(0.5f);
            if (++scrolledFrames >= 2) {
              scrollToSelection = false;
              scrolledFrames = 0;
            }
          }
          ImGui::PopID();
          if (withSource) {
            ImGui::TableNextColumn();
            ImGui::TextDisabled("%s", fitText(w.source, ImGui::GetContentRegionAvail().x).c_str());
          }
          ImGui::TableNextColumn();
          ImGui::Text("%.2f", s.doc.factsAt(i)->strideHz);
        }
      }
      ImGui::EndTable();
    }
    const float belowListTop = ImGui::GetCursorPosY();

    if (s.doc.selectedWalker()) {
      const auto& w = *s.doc.selectedWalker();
      const auto& f = *s.doc.selectedFacts();
      ImGui::Spacing();
      if (ImGui::BeginTable("facts", 2, ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, ImGui::CalcTextSize("from model").x);
        ImGui::TableSetupColumn("v", ImGuiTableColumnFlags_WidthStretch);
        fact("walker", w.subject);
        // A file opened on its own has no condition ("unspecified"): no row to say so.
        if (w.condition != kUnspecifiedCondition) fact("condition", w.condition);
        fact("source", w.source == f.format || f.format.empty() ? w.source : w.source + " (" + f.format + ")");
        char buf[128];
        if (f.speedMps) {
          std::snprintf(buf, sizeof buf, "%.2f Hz · %.2f m/s", f.strideHz, *f.speedMps);
        } else {
          std::snprintf(buf, sizeof buf, "%.2f Hz · speed unknown", f.strideHz);
        }
        fact("stride", buf);
        std::string estimated;
        for (const auto& j : f.estimatedJoints) estimated += (estimated.empty() ? "" : ", ") + j;
        std::string fromModel;
        for (int j = 0; j < kJointCount; ++j)
          if (f.modelEstimated[static_cast<std::size_t>(j)])
            fromModel += (fromModel.empty() ? "" : ", ") +
                         std::string(kJointNames[static_cast<std::size_t>(j)]);
        fact("estimated", !estimated.empty()  ? estimated + " (from the markers)"
                          : fromModel.empty() ? "none (all measured)"
                                              : "none from the markers");
        if (!fromModel.empty()) fact("from model", fromModel + " (the marker set lacks them)");
        if (f.h1Share > 0.0) {
          std::snprintf(buf, sizeof buf, "%.1f %% + %.1f %% (%d trial%s)", 100.0 * f.h1Share, 100.0 * f.h2Share,
                        f.trials, f.trials == 1 ? "" : "s");
          fact("harmonics", buf);
        }
        ImGui::EndTable();
      }
    }

    ImGui::Separator();
    ImGui::SetNextItemWidth(-70.0f * ctx.scale);
    const bool enter = ImGui::InputTextWithHint("##open", "manifest, folder or file…", openPath.data(),
                                                openPath.size(), ImGuiInputTextFlags_EnterReturnsTrue);
    ImGui::SameLine();
    if ((ImGui::Button("Open") || enter) && openPath[0] != '\0') {
      actions::open(s, {std::filesystem::path(openPath.data())});
      scrollToSelection = true;
    }
    const char* back = buttonWidth("Synthetic default population") <= ImGui::GetContentRegionAvail().x
                           ? "Synthetic default population"
                           : "Default population";
    if (ImGui::SmallButton(back)) actions::open(s, {});
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("Back to the synthetic default population (the program's own)");
    belowList = ImGui::GetCursorPosY() - belowListTop;
  }
  ImGui::End();
}

}  // namespace ew::ui

#include "ui/panels/subjects_panel.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"

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
    const float factsHeight = 175.0f * ctx.scale;
    const float listHeight = std::max(80.0f * ctx.scale, ImGui::GetContentRegionAvail().y - factsHeight);
    if (ImGui::BeginTable("walkers", 3,
                          ImGuiTableFlags_ScrollY | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH,
                          ImVec2(0.0f, listHeight))) {
      ImGui::TableSetupScrollFreeze(0, 1);
      ImGui::TableSetupColumn("subject", ImGuiTableColumnFlags_WidthStretch);
      ImGui::TableSetupColumn("source", ImGuiTableColumnFlags_WidthStretch);
      ImGui::TableSetupColumn("Hz", ImGuiTableColumnFlags_WidthFixed, 44.0f * ctx.scale);
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
          if (ImGui::Selectable(w.subject.c_str(), selected, ImGuiSelectableFlags_SpanAllColumns))
            actions::selectWalker(s, i);
          if (selected && scrollToSelection) {
            // The list's height counts rows added this frame only from the next one: scroll twice.
            ImGui::SetScrollHereY(0.5f);
            if (++scrolledFrames >= 2) {
              scrollToSelection = false;
              scrolledFrames = 0;
            }
          }
          ImGui::PopID();
          ImGui::TableNextColumn();
          ImGui::TextDisabled("%s", w.source.c_str());
          ImGui::TableNextColumn();
          ImGui::Text("%.2f", s.doc.factsAt(i)->strideHz);
        }
      }
      ImGui::EndTable();
    }

    if (s.doc.selectedWalker()) {
      const auto& w = *s.doc.selectedWalker();
      const auto& f = *s.doc.selectedFacts();
      ImGui::Spacing();
      if (ImGui::BeginTable("facts", 2, ImGuiTableFlags_SizingStretchProp)) {
        ImGui::TableSetupColumn("k", ImGuiTableColumnFlags_WidthFixed, 92.0f * ctx.scale);
        ImGui::TableSetupColumn("v", ImGuiTableColumnFlags_WidthStretch);
        fact("walker", w.id);
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
        fact("estimated", !estimated.empty()  ? estimated
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
    if (ImGui::SmallButton("Synthetic default population")) actions::open(s, {});
  }
  ImGui::End();
}

}  // namespace ew::ui

#include "ui/panels/semantic_controls.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/derived.h"
#include "ui/widgets/flow.h"
#include "ui/widgets/text_fit.h"

namespace ew::ui {
namespace {

// An axis worth a slider in plain view: it predicts its attribute well from the walker.
bool strongAxis(const SemanticAxisView& a) {
  if (a.axis.categorical) return std::isfinite(a.quality.accuracy) && a.quality.accuracy >= a.quality.chance + 0.1;
  return std::isfinite(a.quality.r2) && a.quality.r2 >= 0.5;
}

std::string escapePercent(const std::string& text) {
  std::string out;
  for (char c : text) out += c == '%' ? std::string("%%") : std::string(1, c);
  return out;
}

// printf format for ImGui's slider: the value with the attribute's decimals and unit ('%' escaped).
std::string sliderFormat(const SemanticAxisView& a) {
  std::string text = formatAttributeValue(a, 1.0);  // "1.00 m/s": its decimals and unit
  const auto space = text.find(' ');
  const auto dot = text.find('.');
  const int decimals = dot == std::string::npos ? 0 : static_cast<int>((space == std::string::npos ? text.size() : space) - dot - 1);
  return "%." + std::to_string(decimals) + "f" + escapePercent(space == std::string::npos ? "" : text.substr(space));
}

// "speed (m/s, measured)" → "speed, measured"; "cadence (steps/min)" → "cadence".
std::string shortLabel(const std::string& label) {
  const auto open = label.find(" (");
  if (open == std::string::npos) return label;
  return label.substr(0, open) + (label.find("measured", open) != std::string::npos ? ", measured" : "");
}

std::string qualityText(const SemanticAxisView& a) {
  char text[160];
  if (a.axis.categorical) {
    std::snprintf(text, sizeof text, "leave-one-subject-out accuracy %.0f %% (chance %.0f %%, %d walkers)",
                  100.0 * a.quality.accuracy, 100.0 * a.quality.chance, a.quality.walkers);
  } else {
    std::snprintf(text, sizeof text, "leave-one-subject-out R² %.2f, RMSE %s (%d walkers)", a.quality.r2,
                  formatAttributeValue(a, a.quality.rmse).c_str(), a.quality.walkers);
  }
  return text;
}

void axisTooltip(const SemanticAxisView& a) {
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  ImGui::TextUnformatted(a.axis.label.c_str());
  ImGui::TextDisabled("%s", a.source == "measured" ? "measured on each walker's own cycle" : "a column of the data's table");
  ImGui::TextUnformatted(qualityText(a).c_str());
  ImGui::TextDisabled("Dragging moves the walker along these walkers' regression of the walker on\n"
                      "this attribute (Troje 2002): how walkers with more of it differ.");
  if (a.axis.categorical)
    ImGui::TextDisabled("0 = %s, 1 = %s: the mean walker of each class", a.axis.classes[0].c_str(), a.axis.classes[1].c_str());
  ImGui::EndTooltip();
}

// Gait space in the model's first two eigenwalkers (SD units, ±3): the population's walkers, the
// explorer's walker, and from it an arrow per strong axis for +1 SD of its attribute — long when
// the attribute lives in e1 × e2, short when it lives in the other components.
void drawGaitSpace(const AppState& s, const SemanticAxes& axes, float scale) {
  const auto* e = s.derived.explore();
  if (!e || e->components < 2) return;
  const float w = ImGui::GetContentRegionAvail().x;
  const float h = std::min(w * 0.75f, 220.0f * scale);
  if (w < 80.0f * scale) return;
  textDisabledWrapped("gait space e1 × e2 (SD units)");
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("dots: the walkers the axes are learnt from; orange: the explorer's walker\n"
                      "arrows: the direction each attribute grows in, 2.5 SD long when the axis lies\n"
                      "wholly in e1 × e2, shorter by the share of it in the other eigenwalkers");
  const ImVec2 p0 = ImGui::GetCursorScreenPos();
  ImGui::Dummy(ImVec2(w, h));
  const ImVec2 p1(p0.x + w, p0.y + h);
  // The explorer's walker and the arrows' tips, in SD units.
  const Eigen::Vector2d from(e->k.size() > 0 ? e->k(0) / std::max(e->sd(0), 1e-12) : 0.0,
                             e->k.size() > 1 ? e->k(1) / std::max(e->sd(1), 1e-12) : 0.0);
  std::vector<std::pair<Eigen::Vector2d, const SemanticAxisView*>> tips;
  double extent = 3.0;  // ±3 SD at least; more when the walker or a tip lies further out
  for (const auto& a : axes.axes) {
    if (!strongAxis(a)) continue;
    // The axis in SD units of each component; the arrow shows its direction in e1 × e2, 2.5 SD
    // long when the axis lies wholly in the plane and shorter by the share that lies outside.
    Eigen::VectorXd inSd = a.axis.directionK.head(std::min<Eigen::Index>(a.axis.directionK.size(), e->sd.size()));
    for (Eigen::Index i = 0; i < inSd.size(); ++i) inSd(i) /= std::max(e->sd(i), 1e-12);
    const Eigen::Vector2d plane = inSd.head(2);
    if (plane.norm() < 1e-12 || inSd.norm() < 1e-12) continue;
    const Eigen::Vector2d d = plane.normalized() * 2.5 * plane.norm() / inSd.norm();
    tips.emplace_back(from + d, &a);
    extent = std::max(extent, (from + d).cwiseAbs().maxCoeff());
  }
  extent = std::max(extent, from.cwiseAbs().maxCoeff()) * 1.1;
  const float perSd = 0.5f * std::min(w, h) / static_cast<float>(extent);
  const ImVec2 centre((p0.x + p1.x) * 0.5f, (p0.y + p1.y) * 0.5f);
  const auto at = [&](const Eigen::Vector2d& v) {
    return ImVec2(centre.x + static_cast<float>(v.x()) * perSd, centre.y - static_cast<float>(v.y()) * perSd);
  };
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->PushClipRect(p0, p1, true);
  const ImU32 grid = ImGui::GetColorU32(ImGuiCol_Border);
  dl->AddRect(p0, p1, grid);
  dl->AddLine(ImVec2(p0.x, centre.y), ImVec2(p1.x, centre.y), grid);
  dl->AddLine(ImVec2(centre.x, p0.y), ImVec2(centre.x, p1.y), grid);
  const ImU32 dot = ImGui::GetColorU32(ImGuiCol_TextDisabled);
  for (Eigen::Index r = 0; r < axes.walkersSd.cols(); ++r)
    dl->AddCircleFilled(at(axes.walkersSd.col(r)), 2.5f * scale, dot);
  const ImVec2 origin = at(from);
  const ImU32 arrow = ImGui::GetColorU32(ImGuiCol_PlotLines);
  const ImU32 text = ImGui::GetColorU32(ImGuiCol_Text);
  std::vector<ImVec4> labels;  // placed label rectangles: a label that would overlap one is left out
  for (const auto& [tip, a] : tips) {
    const ImVec2 to = at(tip);
    dl->AddLine(origin, to, arrow, 2.0f * scale);
    const float len = std::hypot(to.x - origin.x, to.y - origin.y);
    if (len < 4.0f * scale) continue;
    const ImVec2 u((to.x - origin.x) / len, (to.y - origin.y) / len);
    const float head = 7.0f * scale;
    dl->AddTriangleFilled(to, ImVec2(to.x - head * u.x + 0.5f * head * u.y, to.y - head * u.y - 0.5f * head * u.x),
                          ImVec2(to.x - head * u.x - 0.5f * head * u.y, to.y - head * u.y + 0.5f * head * u.x), arrow);
    const ImVec2 size = ImGui::CalcTextSize(a->axis.highWord.c_str());
    ImVec2 pos(to.x + (u.x >= 0 ? 4.0f * scale : -size.x - 4.0f * scale), to.y - 0.5f * size.y);
    pos.x = std::clamp(pos.x, p0.x + 2.0f, p1.x - size.x - 2.0f);
    pos.y = std::clamp(pos.y, p0.y + 2.0f, p1.y - size.y - 2.0f);
    const ImVec4 rect(pos.x, pos.y, pos.x + size.x, pos.y + size.y);
    const bool overlaps = std::any_of(labels.begin(), labels.end(), [&](const ImVec4& o) {
      return rect.x < o.z && o.x < rect.z && rect.y < o.w && o.y < rect.w;
    });
    if (overlaps) continue;
    labels.push_back(rect);
    dl->AddText(pos, text, a->axis.highWord.c_str());
  }
  dl->AddCircleFilled(origin, 5.0f * scale, ImGui::GetColorU32(ImGuiCol_PlotHistogram));
  dl->PopClipRect();
}

}  // namespace

void SemanticControls::drawExplore(AppState& s, float scale) {
  const SemanticAxes* axes = s.derived.semantic();
  if (!ImGui::CollapsingHeader("Semantic axes", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (!axes) {
    textDisabledWrapped("needs at least 3 walkers to learn from (the population, or the model held when it is another)");
    return;
  }
  textDisabledWrapped(("learnt from " + axes->from).c_str());
  if (axes->axes.empty()) {
    textDisabledWrapped("no attribute of these walkers is predictable from the walker");
    return;
  }
  const auto row = [&](const SemanticAxisView& a) {
    const std::string& name = a.axis.attribute;
    const ExploreState now = actions::exploreState(s);
    const auto it = shown.find(name);
    float value = static_cast<float>(it != shown.end() && it->second.state == now ? it->second.value
                                                                                 : actions::semanticReading(s, name));
    const float before = value;
    const double lo = a.axis.categorical ? -0.5 : a.axis.mean - 3.0 * a.axis.sd;
    const double hi = a.axis.categorical ? 1.5 : a.axis.mean + 3.0 * a.axis.sd;
    ImGui::PushID(name.c_str());
    // "slower      1.42 m/s      faster": the words at the slider's ends when they fit beside the
    // value, else above it.
    const std::string valueFormat = sliderFormat(a);
    const float width = ImGui::GetContentRegionAvail().x;
    const float pad = ImGui::GetStyle().FramePadding.x;
    const float lowW = ImGui::CalcTextSize(a.axis.lowWord.c_str()).x;
    const float highW = ImGui::CalcTextSize(a.axis.highWord.c_str()).x;
    const float valueW = ImGui::CalcTextSize(formatAttributeValue(a, value).c_str()).x;
    const bool inside = lowW + highW + valueW + 2.0f * pad + 24.0f * scale < width;
    if (!inside) textDisabledWrapped((a.axis.lowWord + "  ↔  " + a.axis.highWord).c_str());
    ImGui::SetNextItemWidth(width);
    const bool changed = ImGui::SliderFloat("##axis", &value, static_cast<float>(lo), static_cast<float>(hi), valueFormat.c_str());
    if (inside) {
      const ImVec2 r0 = ImGui::GetItemRectMin(), r1 = ImGui::GetItemRectMax();
      const float y = 0.5f * (r0.y + r1.y - ImGui::GetTextLineHeight());
      const ImU32 words = ImGui::GetColorU32(ImGuiCol_TextDisabled);
      ImDrawList* dl = ImGui::GetWindowDrawList();
      dl->AddText(ImVec2(r0.x + pad, y), words, a.axis.lowWord.c_str());
      dl->AddText(ImVec2(r1.x - pad - highW, y), words, a.axis.highWord.c_str());
    }
    axisTooltip(a);
    if (ImGui::IsItemActivated()) {
      dragging = name;
      anchor = now;
      anchorValue = before;
    }
    if (changed && dragging == name) {
      actions::moveAlongAxis(s, name, anchor, value - anchorValue);
      shown[name] = {actions::exploreState(s), value};
    }
    if (ImGui::IsItemDeactivated()) dragging.clear();
    ImGui::PopID();
  };
  const auto count = [&](const char* source, bool strong) {
    return std::count_if(axes->axes.begin(), axes->axes.end(),
                         [&](const SemanticAxisView& a) { return a.source == source && strongAxis(a) == strong; });
  };
  const auto group = [&](const char* source, bool strong, const char* heading) {
    if (count(source, strong) == 0) return;
    if (heading) textDisabledWrapped(heading);
    for (const auto& a : axes->axes)
      if (a.source == source && strongAxis(a) == strong) row(a);
  };
  group("manifest", true, "from the data's table");
  group("measured", true, "measured on the walkers");
  if (count("manifest", false) + count("measured", false) > 0) {
    const bool open = ImGui::TreeNode("weaker axes");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("R² < 0.5, or accuracy near chance: a poor predictor of the attribute");
    if (open) {
      group("manifest", false, nullptr);
      group("measured", false, nullptr);
      ImGui::TreePop();
    }
  }
  drawGaitSpace(s, *axes, scale);
}

void SemanticControls::drawFromView(const AppState& s, float scale) {
  const auto& rows = s.derived.attributesFromView();
  if (rows.empty()) return;
  // (The header's label shortened where the panel is too narrow for it: a large UI scale.)
  const float arrowW = ImGui::GetFontSize() + 3.0f * ImGui::GetStyle().FramePadding.x;
  const char* header = arrowW + ImGui::CalcTextSize("Attributes from the 2D view").x <= ImGui::GetContentRegionAvail().x
                           ? "Attributes from the 2D view###from_view"
                           : "From the 2D view###from_view";
  if (!ImGui::CollapsingHeader(header, ImGuiTreeNodeFlags_DefaultOpen)) return;
  ImGui::TextWrapped("Each attribute predicted from the reconstruction alone, from the walker's own 3D cycle, and its "
                     "true value; the axes learnt from %s%s.",
                     s.derived.attributesFromViewAxes().from.c_str(),
                     s.derived.attributesFromViewAxes().without.empty() ? "" : ", without this subject");
  const ImGuiTableFlags flags = ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerH | ImGuiTableFlags_SizingStretchProp;
  // The column of values from the walker's own 3D cycle goes first when the panel is narrow:
  // the 2D view's against the truth is the point.
  const float numberW = ImGui::CalcTextSize("00.00").x + 2.0f * ImGui::GetStyle().CellPadding.x;
  const bool with3d = ImGui::CalcTextSize("stride length").x + 3.0f * numberW <= 0.9f * ImGui::GetContentRegionAvail().x;
  if (!ImGui::BeginTable("from_view", with3d ? 4 : 3, flags)) return;
  ImGui::TableSetupColumn("attribute", ImGuiTableColumnFlags_WidthStretch, 2.2f);
  // "2D view" where the column has room for it (beside "3D" the short name reads the same).
  const float columnW = ImGui::GetContentRegionAvail().x / (with3d ? 5.2f : 4.2f);
  const bool roomy = ImGui::CalcTextSize("2D view").x + 2.0f * ImGui::GetStyle().CellPadding.x <= columnW;
  ImGui::TableSetupColumn(roomy ? "2D view" : "2D", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  if (with3d) ImGui::TableSetupColumn("3D", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableSetupColumn("true", ImGuiTableColumnFlags_WidthStretch, 1.0f);
  ImGui::TableHeadersRow();
  for (const auto& r : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextWrapped("%s", shortLabel(r.label).c_str());
    const auto cell = [&](double v) {
      ImGui::TableNextColumn();
      if (r.categorical) {
        ImGui::TextUnformatted(fitText(r.classes[v >= 0.5 ? 1 : 0], ImGui::GetContentRegionAvail().x).c_str());
      } else {
        ImGui::Text("%.*f", std::abs(v) >= 100 ? 0 : std::abs(v) >= 10 ? 1 : 2, v);
      }
    };
    cell(r.from2d);
    if (with3d) cell(r.from3d);
    cell(r.truth);
  }
  ImGui::EndTable();
  (void)scale;
}

}  // namespace ew::ui

#include "ui/widgets/flow.h"
#include "ui/panels/notice_panel.h"

#include <imgui.h>
#include <imgui_internal.h>

#include <algorithm>
#include <string>
#include <vector>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/widgets/text_fit.h"

namespace ew::ui {

namespace {

// The row keeps its own dark colours in every theme, so its text colours are fixed too.
const ImVec4 kErrorBg{0.23f, 0.07f, 0.09f, 1.0f};
const ImVec4 kErrorAccent{1.0f, 0.45f, 0.5f, 1.0f};
const ImVec4 kWarningBg{0.22f, 0.16f, 0.05f, 1.0f};
const ImVec4 kWarningAccent{0.98f, 0.8f, 0.35f, 1.0f};
const ImVec4 kDetailText{0.95f, 0.93f, 0.93f, 1.0f};
const ImVec4 kKeptText{0.62f, 0.88f, 0.8f, 1.0f};

// A "name: " prefix that names a file or folder (no spaces, a dot or a slash in it).
std::size_t filePrefixEnd(const std::string& line) {
  const std::size_t colon = line.find(": ");
  if (colon == std::string::npos || colon == 0) return 0;
  const std::string head = line.substr(0, colon);
  if (head.find(' ') != std::string::npos) return 0;
  if (head.find('.') == std::string::npos && head.find('/') == std::string::npos) return 0;
  return colon + 2;
}

// The buttons of a notice, left to right.
std::vector<const char*> buttonsFor(const AppState& s, const NoticeView& n) {
  std::vector<const char*> buttons{"Details…"};
  if (n.canRetry) buttons.push_back("Retry");
  if (n.kind == NoticeView::Kind::Open && n.error && s.doc.walkerCount() == 0 && !s.jobsBusy())
    buttons.push_back("Open the synthetic default");
  buttons.push_back("Dismiss");
  return buttons;
}

}  // namespace

std::string shortReason(const std::string& message) {
  std::string line = message.substr(0, message.find('\n'));
  line.erase(0, filePrefixEnd(line));
  std::size_t cut = line.size();
  for (const char* stop : {"; ", " (", ". "}) cut = std::min(cut, line.find(stop));
  line.resize(cut);
  return line;
}

std::optional<NoticeView> NoticePanel::current(const AppState& s) const {
  if (s.notices.banner) {
    const auto& o = *s.notices.banner;
    return NoticeView{NoticeView::Kind::Open,
                      o.error,
                      o.title,
                      o.detail,
                      o.fullText,
                      o.kept,
                      o.canRetry,
                      o.serial,
                      o.shortTitle};
  }
  if (!s.exports.lastError.empty())
    return NoticeView{NoticeView::Kind::Export,
                      true,
                      "Export failed",
                      s.exports.lastError,
                      s.exports.lastError,
                      "Nothing was written; what is shown has not changed.",
                      false,
                      0,
                      ""};
  const std::string& recon = s.derived.error();
  if (!recon.empty() && recon != dismissedReconError)
    return NoticeView{NoticeView::Kind::Reconstruction,
                      true,
                      "Reconstruction failed",
                      recon,
                      recon,
                      "Choose another walker, model or setting.",
                      false,
                      0,
                      ""};
  return std::nullopt;
}

void NoticePanel::apply(AppState& s, const NoticeView& n, const std::string& clicked) {
  if (clicked.empty()) return;
  if (clicked == "Details…") {
    detailsOpen = true;
    return;
  }
  detailsOpen = false;
  if (n.kind == NoticeView::Kind::Export) {
    s.exports.lastError.clear();
  } else if (n.kind == NoticeView::Kind::Reconstruction) {
    dismissedReconError = n.detail;
  } else if (clicked == "Retry") {
    const auto paths = s.notices.banner->retryPaths;
    actions::dismissNotice(s);
    actions::open(s, paths);
  } else if (clicked == "Open the synthetic default") {
    actions::dismissNotice(s);
    actions::open(s, {});
  } else {
    actions::dismissNotice(s);
  }
}

void NoticePanel::draw(AppState& s, const FrameContext& ctx, const PanelRect& row) {
  const auto shown = current(s);
  if (!shown || row.size.y <= 0.0f) return;
  const NoticeView n = *shown;  // a button below may replace or clear it
  const ImVec4 accent = n.error ? kErrorAccent : kWarningAccent;
  ImGui::PushStyleColor(ImGuiCol_WindowBg, n.error ? kErrorBg : kWarningBg);
  const bool open = beginPanel(ctx.backdrop, "##notice_row", row,
                               ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoScrollbar |
                                   ImGuiWindowFlags_NoScrollWithMouse | ImGuiWindowFlags_NoNav);
  ImGui::PopStyleColor();
  if (open) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const auto buttons = buttonsFor(s, n);
    float buttonsW = 0.0f;
    for (const char* b : buttons) buttonsW += buttonWidth(b) + style.ItemSpacing.x;
    // Title and reason share what the buttons leave; the title gets at most half of it.
    const float room =
        std::max(0.0f, ImGui::GetContentRegionAvail().x - buttonsW - style.ItemSpacing.x);
    // Where the title itself would be cut (a narrow drawer), its short form, or just what kind
    // of notice it is: hovering, or Details…, tells the rest.
    const bool cramped = ImGui::CalcTextSize((n.title + ":").c_str()).x > 0.5f * room;
    ImGui::AlignTextToFramePadding();
    if (cramped) {
      const bool shortFits = !n.shortTitle.empty() && ImGui::CalcTextSize(n.shortTitle.c_str()).x <= room;
      // Where even the kind does not fit beside the buttons (a scaled-up UI), cut it: never under them.
      const std::string label = fitText(shortFits ? n.shortTitle : n.error ? "Error" : "Warning", room);
      ImGui::TextColored(accent, "%s", label.c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", n.fullText.c_str());
    } else {
      ImGui::TextColored(accent, "%s", (n.title + ":").c_str());
      const float used = ImGui::GetItemRectSize().x + style.ItemSpacing.x;
      ImGui::SameLine();
      const std::string reason = fitText(shortReason(n.detail), std::max(0.0f, room - used));
      ImGui::TextColored(kDetailText, "%s", reason.c_str());
      if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", n.fullText.c_str());
    }
    ImGui::SameLine(ImGui::GetWindowContentRegionMax().x - buttonsW + style.ItemSpacing.x);
    std::string clicked;
    for (std::size_t i = 0; i < buttons.size(); ++i) {
      if (i > 0) ImGui::SameLine();
      if (ImGui::Button(buttons[i])) clicked = buttons[i];
    }
    apply(s, n, clicked);
  }
  ImGui::End();
}

void NoticePanel::drawDetails(AppState& s, const FrameContext& ctx) {
  const auto shown = current(s);
  if (!shown) detailsOpen = false;
  if (!detailsOpen) return;
  const NoticeView n = *shown;
  const ImVec2 display = ImGui::GetIO().DisplaySize;
  const float width = std::min(760.0f * ctx.scale, display.x - 40.0f * ctx.scale);
  ImGui::SetNextWindowPos(ImVec2(display.x * 0.5f, display.y * 0.4f), ImGuiCond_Appearing,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(width, 0.0f), ImVec2(width, display.y * 0.8f));
  bool keep = true;
  if (ImGui::Begin((n.title + "###notice_details").c_str(), &keep,
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse |
                       ImGuiWindowFlags_AlwaysAutoResize)) {
    if (n.serial != frontSerial) {
      ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
      frontSerial = n.serial;
    }
    const float contentW = width - 2.0f * ImGui::GetStyle().WindowPadding.x;
    const float maxH = 12.0f * ImGui::GetTextLineHeightWithSpacing();
    const float textH = ImGui::CalcTextSize(n.fullText.c_str(), nullptr, false, contentW).y;
    ImGui::PushStyleColor(ImGuiCol_Text, kDetailText);
    ImGui::BeginChild("##full", ImVec2(contentW, std::min(maxH, textH + 8.0f * ctx.scale)));
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(n.fullText.c_str());
    ImGui::PopTextWrapPos();
    ImGui::EndChild();
    ImGui::PopStyleColor();
    if (!n.kept.empty()) {
      ImGui::PushTextWrapPos(ImGui::GetCursorPosX() + contentW);
      ImGui::TextColored(kKeptText, "%s", n.kept.c_str());
      ImGui::PopTextWrapPos();
    }
    ImGui::Separator();
    std::string clicked;
    if (ImGui::Button("Copy")) ImGui::SetClipboardText(n.fullText.c_str());
    for (const char* b : buttonsFor(s, n)) {
      if (std::string(b) == "Details…") continue;
      ImGui::SameLine();
      if (ImGui::Button(b)) clicked = b;
    }
    ImGui::SameLine();
    if (ImGui::Button("Close")) keep = false;
    apply(s, n, clicked);
  }
  ImGui::End();
  if (!keep) detailsOpen = false;
}

}  // namespace ew::ui

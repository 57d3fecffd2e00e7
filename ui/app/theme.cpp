#include "ui/app/theme.h"

#include <imgui.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>
#include <system_error>

namespace ew::ui {

namespace {

constexpr const char* kFontDirs[] = {"/usr/share/fonts/truetype/dejavu"};

}  // namespace

std::filesystem::path findFont(const char* file) {
  for (const char* dir : kFontDirs) {
    std::error_code ec;
    const auto p = std::filesystem::path(dir) / file;
    if (std::filesystem::is_regular_file(p, ec)) return p;
  }
  return {};
}

namespace {

// Latin, Latin-1, Greek (α, σ, λ), punctuation and arrows, super/subscripts, math.
// (Constant data that must outlive the atlas build, hence namespace scope.)
constexpr ImWchar kGlyphRanges[] = {0x0020, 0x00FF, 0x0370, 0x03FF, 0x2000, 0x206F,
                                    0x2070, 0x209F, 0x2190, 0x21FF, 0x2200, 0x22FF, 0};

ImFont* addFont(ImFontAtlas& atlas, const std::filesystem::path& file, float px) {
  if (file.empty()) {
    ImFontConfig config;
    config.SizePixels = std::max(13.0f, px * 0.8f);
    return atlas.AddFontDefault(&config);
  }
  ImFontConfig config;
  config.OversampleH = 2;
  config.OversampleV = 1;
  return atlas.AddFontFromFileTTF(file.string().c_str(), px, &config, kGlyphRanges);
}

void applyColours(ImGuiStyle& style) {
  ImGui::StyleColorsDark(&style);
  ImVec4* c = style.Colors;
  const ImVec4 bg{0.075f, 0.082f, 0.095f, 1.0f};
  const ImVec4 panel{0.095f, 0.104f, 0.120f, 1.0f};
  const ImVec4 frame{0.15f, 0.165f, 0.19f, 1.0f};
  const ImVec4 accent{1.00f, 0.62f, 0.26f, 1.0f};
  const ImVec4 accentDim{0.75f, 0.46f, 0.20f, 1.0f};
  c[ImGuiCol_Text] = {0.90f, 0.92f, 0.95f, 1.0f};
  c[ImGuiCol_TextDisabled] = {0.52f, 0.56f, 0.62f, 1.0f};
  c[ImGuiCol_WindowBg] = panel;
  c[ImGuiCol_ChildBg] = {0, 0, 0, 0};
  c[ImGuiCol_PopupBg] = {0.11f, 0.12f, 0.14f, 0.98f};
  c[ImGuiCol_Border] = {0.20f, 0.22f, 0.26f, 1.0f};
  c[ImGuiCol_FrameBg] = frame;
  c[ImGuiCol_FrameBgHovered] = {0.20f, 0.22f, 0.26f, 1.0f};
  c[ImGuiCol_FrameBgActive] = {0.24f, 0.26f, 0.31f, 1.0f};
  c[ImGuiCol_TitleBg] = bg;
  c[ImGuiCol_TitleBgActive] = bg;
  c[ImGuiCol_TitleBgCollapsed] = bg;
  c[ImGuiCol_MenuBarBg] = bg;
  c[ImGuiCol_ScrollbarBg] = {0, 0, 0, 0};
  c[ImGuiCol_CheckMark] = accent;
  c[ImGuiCol_SliderGrab] = accentDim;
  c[ImGuiCol_SliderGrabActive] = accent;
  c[ImGuiCol_Button] = {0.17f, 0.19f, 0.22f, 1.0f};
  c[ImGuiCol_ButtonHovered] = {0.24f, 0.27f, 0.31f, 1.0f};
  c[ImGuiCol_ButtonActive] = accentDim;
  c[ImGuiCol_Header] = {0.96f, 0.58f, 0.24f, 0.28f};
  c[ImGuiCol_HeaderHovered] = {0.96f, 0.58f, 0.24f, 0.18f};
  c[ImGuiCol_HeaderActive] = {0.96f, 0.58f, 0.24f, 0.40f};
  c[ImGuiCol_Separator] = {0.20f, 0.22f, 0.26f, 1.0f};
  c[ImGuiCol_TableHeaderBg] = {0.12f, 0.13f, 0.15f, 1.0f};
  c[ImGuiCol_TableRowBgAlt] = {1.0f, 1.0f, 1.0f, 0.025f};
  c[ImGuiCol_PlotHistogram] = accent;
}

// Light panels for rooms with the lights on; the accent darkened so it reads on white.
void applyLightColours(ImGuiStyle& style) {
  ImGui::StyleColorsLight(&style);
  ImVec4* c = style.Colors;
  const ImVec4 accent{0.86f, 0.45f, 0.08f, 1.0f};
  const ImVec4 accentDim{0.93f, 0.60f, 0.30f, 1.0f};
  c[ImGuiCol_Text] = {0.07f, 0.08f, 0.10f, 1.0f};
  c[ImGuiCol_TextDisabled] = {0.36f, 0.39f, 0.44f, 1.0f};
  c[ImGuiCol_WindowBg] = {0.965f, 0.968f, 0.975f, 1.0f};
  c[ImGuiCol_PopupBg] = {1.0f, 1.0f, 1.0f, 0.98f};
  c[ImGuiCol_Border] = {0.76f, 0.78f, 0.82f, 1.0f};
  c[ImGuiCol_FrameBg] = {0.89f, 0.90f, 0.92f, 1.0f};
  c[ImGuiCol_FrameBgHovered] = {0.84f, 0.86f, 0.89f, 1.0f};
  c[ImGuiCol_FrameBgActive] = {0.80f, 0.82f, 0.86f, 1.0f};
  c[ImGuiCol_TitleBg] = {0.90f, 0.91f, 0.93f, 1.0f};
  c[ImGuiCol_TitleBgActive] = {0.86f, 0.87f, 0.90f, 1.0f};
  c[ImGuiCol_CheckMark] = accent;
  c[ImGuiCol_SliderGrab] = accentDim;
  c[ImGuiCol_SliderGrabActive] = accent;
  c[ImGuiCol_Button] = {0.86f, 0.87f, 0.90f, 1.0f};
  c[ImGuiCol_ButtonHovered] = {0.80f, 0.82f, 0.86f, 1.0f};
  c[ImGuiCol_ButtonActive] = accentDim;
  c[ImGuiCol_Header] = {0.96f, 0.58f, 0.24f, 0.35f};
  c[ImGuiCol_HeaderHovered] = {0.96f, 0.58f, 0.24f, 0.22f};
  c[ImGuiCol_HeaderActive] = {0.96f, 0.58f, 0.24f, 0.50f};
  c[ImGuiCol_Separator] = {0.76f, 0.78f, 0.82f, 1.0f};
  c[ImGuiCol_TableHeaderBg] = {0.90f, 0.91f, 0.93f, 1.0f};
  c[ImGuiCol_TableRowBgAlt] = {0.0f, 0.0f, 0.0f, 0.03f};
  c[ImGuiCol_PlotHistogram] = accent;
}

// The dark theme with white text and brighter borders: contrast survives a washed-out projector.
void applyProjectorColours(ImGuiStyle& style) {
  applyColours(style);
  ImVec4* c = style.Colors;
  c[ImGuiCol_Text] = {1.0f, 1.0f, 1.0f, 1.0f};
  c[ImGuiCol_TextDisabled] = {0.70f, 0.74f, 0.80f, 1.0f};
  c[ImGuiCol_WindowBg] = {0.03f, 0.035f, 0.045f, 1.0f};
  c[ImGuiCol_Border] = {0.34f, 0.37f, 0.43f, 1.0f};
  c[ImGuiCol_FrameBg] = {0.16f, 0.18f, 0.21f, 1.0f};
}

}  // namespace

Theme themeFromName(const std::string& name) {
  if (name == "dark") return Theme::Dark;
  if (name == "light") return Theme::Light;
  if (name == "projector") return Theme::Projector;
  throw std::invalid_argument("unknown theme \"" + name + "\" (known: dark, light, projector)");
}

const char* themeName(Theme theme) {
  switch (theme) {
    case Theme::Dark: return "dark";
    case Theme::Light: return "light";
    case Theme::Projector: return "projector";
  }
  return "dark";
}

ImVec4 warningTextColour() {
  const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  const bool light = 0.3f * bg.x + 0.59f * bg.y + 0.11f * bg.z > 0.5f;
  return light ? ImVec4(0.70f, 0.38f, 0.0f, 1.0f) : ImVec4(0.98f, 0.8f, 0.35f, 1.0f);
}

ImVec4 goodTextColour() {
  const ImVec4 bg = ImGui::GetStyleColorVec4(ImGuiCol_WindowBg);
  const bool light = 0.3f * bg.x + 0.59f * bg.y + 0.11f * bg.z > 0.5f;
  return light ? ImVec4(0.0f, 0.45f, 0.38f, 1.0f) : ImVec4(0.5f, 0.9f, 0.8f, 1.0f);
}

static void addFonts(ImFontAtlas& atlas, Fonts& fonts, float scale) {
  const auto regular = findFont("DejaVuSans.ttf");
  const auto bold = findFont("DejaVuSans-Bold.ttf");
  fonts.body = addFont(atlas, regular, 16.0f * scale);
  fonts.large = addFont(atlas, bold.empty() ? regular : bold, 21.0f * scale);
  fonts.small = addFont(atlas, regular, 13.5f * scale);
}

void applyTheme(Fonts& fonts, Fonts& presentation, float scale, Theme theme) {
  ImGuiIO& io = ImGui::GetIO();
  io.Fonts->Clear();
  addFonts(*io.Fonts, fonts, scale);
  addFonts(*io.Fonts, presentation, scale * kPresentationTextScale);
  io.FontDefault = fonts.body;
  io.Fonts->Build();

  ImGuiStyle style;
  if (theme == Theme::Light) {
    applyLightColours(style);
  } else if (theme == Theme::Projector) {
    applyProjectorColours(style);
  } else {
    applyColours(style);
  }
  style.WindowPadding = {10, 8};
  style.FramePadding = {8, 4};
  style.ItemSpacing = {8, 6};
  style.ItemInnerSpacing = {6, 4};
  style.WindowRounding = 0.0f;
  style.FrameRounding = 4.0f;
  style.GrabRounding = 4.0f;
  style.GrabMinSize = 10.0f;
  style.ScrollbarSize = 12.0f;
  style.ScrollbarRounding = 6.0f;
  style.WindowBorderSize = theme == Theme::Projector ? 2.0f : 1.0f;
  style.FrameBorderSize = 0.0f;
  style.WindowTitleAlign = {0.0f, 0.5f};
  style.AntiAliasedLines = true;
  style.AntiAliasedFill = true;
  style.ScaleAllSizes(scale);
  ImGui::GetStyle() = style;
}

}  // namespace ew::ui

#pragma once
// The audience window (issue 56): a second window — another monitor or the projector — that
// shows only the stage (the two views, or one), while the main window keeps the controls.
// Its size and theme are its own. This is what the user asked for; the app's frame loop
// (ui/app/audience_window.h) opens, resizes and draws the window to match.

#include <filesystem>
#include <optional>
#include <string>

namespace ew::ui {

enum class AudienceViews { Both, Input, Reconstruction };
enum class AudienceTheme { Dark, Projector };  // the views' dots are light: no light theme

struct AudienceFeature {
  bool open = false;
  int widthPx = 1280, heightPx = 720;  // the window's size (screen coordinates)
  AudienceTheme theme = AudienceTheme::Projector;
  AudienceViews views = AudienceViews::Both;
  std::optional<std::filesystem::path> capture;  // a PNG of its next frame (scripts, tests)
  bool shown = false;  // its window is up (the frame loop sets it)
  std::string error;   // why it could not open
};

const char* audienceViewsName(AudienceViews v);  // "both", "input", "reconstruction"
const char* audienceThemeName(AudienceTheme t);  // "dark", "projector"

}  // namespace ew::ui

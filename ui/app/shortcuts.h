#pragma once
// The keyboard, as a table (docs/VIEWER.md "Keyboard"): each row of the F1 overlay is one
// entry, with the keys it names and the actions they call — the same actions:: functions the
// panels' controls call, so a key does exactly what a click does. The frame loop and the
// script action "key" both go through applyShortcut.

#include <optional>
#include <span>
#include <string>
#include <vector>

namespace ew::ui {

struct AppState;

// A key (GLFW key code) with the modifiers that must be down; any other modifier (Alt, Super)
// stops it matching.
struct KeyChord {
  int key = 0;
  bool ctrl = false;
  bool shift = false;
  bool operator==(const KeyChord&) const = default;
};

struct KeyBinding {
  KeyChord chord;
  bool repeats = false;  // held down, it repeats (α, frame steps, undo)
  void (*apply)(AppState&) = nullptr;
};

struct ShortcutRow {
  const char* keys;  // as the F1 overlay shows them: "[ / ]", "Ctrl+Z"
  const char* what;
  std::vector<KeyBinding> bindings;
};

// Every key the viewer answers to, in the F1 overlay's order.
std::span<const ShortcutRow> shortcutRows();

// Applies the binding of `chord`; false when no key is bound to it.
bool applyShortcut(AppState& s, const KeyChord& chord);

// "]", "shift+]", "ctrl+z", "f5", "page_down", "escape", … (case-insensitive); nullopt when
// the name is no key the table knows.
std::optional<KeyChord> parseKeyChord(const std::string& text);
// "Shift+]", "Page Down": the key's name as the F1 overlay writes it.
std::string keyName(int key);

// The α step of the fine and coarse keys, in degrees.
inline constexpr double kAngleFineStepDeg = 1.0;
inline constexpr double kAngleCoarseStepDeg = 15.0;
// α + `deltaDeg`, wrapped into [-180, 180] (a step past 180° comes round from −180°).
double stepAngleDeg(double alphaDeg, double deltaDeg);

}  // namespace ew::ui

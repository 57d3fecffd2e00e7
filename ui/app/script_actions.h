#pragma once
// The script actions as one table, as ui/app/shortcuts.h is for the keys: each name with what
// parses and applies its argument, and what the runner waits for after it. parseScript knows
// the names from it, applyAction (the guided tour's steps) and ScriptRunner apply through it.
// Adding an action is adding a row (script_actions.cpp) and its line in docs/VIEWER.md.

#include <filesystem>
#include <optional>
#include <span>
#include <string_view>

#include "ui/app/script.h"

namespace ew::ui {

struct AppState;

// Parses the action's argument and applies it; throws std::invalid_argument with a readable
// message for a bad argument (the runner adds the action's position and name).
using ScriptApply = void (*)(AppState& s, const ScriptAction& a, ScriptWaits& waits);

struct ScriptActionKind {
  std::string_view name;
  ScriptApply apply = nullptr;
  // Only a ScriptRunner applies it: it waits for what it starts (open, screenshot, exports…);
  // applyAction refuses it ("cannot be used here").
  bool runnerOnly = false;
  // The next action comes a frame later at least, after the UI has seen this one.
  bool yields = false;
};

// Every action, in the table's order.
std::span<const ScriptActionKind> scriptActions();
// The action named `name`, else null.
const ScriptActionKind* scriptAction(std::string_view name);
// The action inside {"expect_failure": {NAME: ARG}}; throws std::invalid_argument when it is
// none (an unknown name, or expect_failure itself).
ScriptAction innerAction(const ScriptAction& a);
// Applies any action (the runner's way): unknown names throw "cannot be used here".
void applyScriptAction(AppState& s, const ScriptAction& a, ScriptWaits& waits);

}  // namespace ew::ui

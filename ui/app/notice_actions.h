#pragma once
// Errors the user sees (notice_actions.cpp): the log, and the banner over the views (OpenNotice).
// Part of the viewer's actions (ui/app/actions.h): each validates its argument and throws
// std::invalid_argument with a readable message when it cannot apply.

#include <filesystem>
#include <string>
#include <vector>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

// [SECTION] Errors the user sees: the log, and the banner over the views (OpenNotice).
// "walk.csv", "a.bvh, b.bvh, c.bvh, … (2 more)", "the synthetic default population".
std::string describePaths(const std::vector<std::filesystem::path>& paths);
// An error banner (title, the reason, what is still shown) and lastError; no Retry.
void reportError(AppState& s, const std::string& title, const std::string& detail);
// An amber banner (not an error: nothing failed, but the user should know), and the log.
void reportNote(AppState& s, const std::string& title, const std::string& detail,
                const std::string& shortTitle = "");
// "Could not open PATHS" with the reason, and Retry (which opens `paths` again).
void reportOpenError(AppState& s, const std::vector<std::filesystem::path>& paths,
                     const std::string& message);
void dismissNotice(AppState& s);  // hides the banner, clears lastError

}  // namespace ew::ui::actions

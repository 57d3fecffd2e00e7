#pragma once
// What the feature files of the actions (ui/app/*_actions.cpp) share among themselves, not
// for panels: the public operations are in actions.h.

#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include "ui/app/app_state.h"

namespace ew::ui::actions {

// [SECTION] Data loading (load_actions.cpp)
// The model that completes trials lacking joints (joint_completion.h): the one they will be
// inspected against (the default model when the synthetic population, or nothing, is shown).
std::shared_ptr<const EigenwalkerModel> completionModel(AppState& s);

// [SECTION] Errors the user sees (notice_actions.cpp)
// What the user still has after a failure.
std::string keptDescription(const AppState& s);
// `message` with each of `paths` shortened to its name.
std::string shortenPaths(std::string message, const std::vector<std::filesystem::path>& paths);
// The banner over the views shows `notice` (a new serial: it comes to the front once).
void showNotice(AppState& s, OpenNotice notice);

// [SECTION] Keypoint clips (clip_actions.cpp)
// Once a frame (pollJobs): a fit that finished is shown, or its failure said
// (clip_actions.cpp says how).
void pollClipFit(AppState& s);
// Then: starts the fit the clip's settings ask for, unless it is shown, running, or failed
// already; a fit that cannot start fails as one that ran.
void refitClip(AppState& s);
// Opens the first keypoint clip among `paths` and returns the others; further clips are
// refused (one clip at a time), and every clip when a video was opened with them.
std::vector<std::filesystem::path> openClips(AppState& s, std::vector<std::filesystem::path> paths,
                                             std::vector<std::string>& refused, bool withVideo = false);

// [SECTION] Document edits (document_actions.cpp)
// Throws std::invalid_argument("no data loaded") when no walker is loaded.
void requireLoaded(const AppState& s);

}  // namespace ew::ui::actions

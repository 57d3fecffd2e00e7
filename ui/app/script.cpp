#include "ui/app/script.h"

#include <fstream>
#include <optional>
#include <stdexcept>
#include <utility>

#include "ui/app/app_state.h"
#include "ui/app/script_actions.h"
#include "ui/app/undo.h"

namespace ew::ui {

namespace {

// Frames rendered after the work is done before a screenshot, so the UI has settled.
constexpr int kSettleFrames = 2;

}  // namespace

std::vector<ScriptAction> parseScript(const nlohmann::json& script, const std::string& name) {
  if (!script.is_array()) throw std::runtime_error(name + ": a script is a JSON array of actions");
  std::vector<ScriptAction> actions;
  int position = 0;
  for (const auto& item : script) {
    ++position;
    if (!item.is_object() || item.size() != 1)
      throw std::runtime_error(name + ": action " + std::to_string(position) +
                               ": each action is an object with exactly one key, got " +
                               item.dump());
    const auto entry = item.begin();
    const std::string key = entry.key();
    if (!scriptAction(key))
      throw std::runtime_error(name + ": action " + std::to_string(position) +
                               ": unknown action \"" + key + "\"");
    actions.push_back({key, entry.value(), position});
    if (key == "expect_failure") {
      try {
        (void)innerAction(actions.back());
      } catch (const std::invalid_argument& e) {
        throw std::runtime_error(name + ": action " + std::to_string(position) +
                                 ": expect_failure " + e.what());
      }
    }
  }
  return actions;
}

std::vector<ScriptAction> readScript(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the script");
  nlohmann::json script;
  try {
    in >> script;
  } catch (const nlohmann::json::exception& e) {
    throw std::runtime_error(file.string() + ": not valid JSON: " + e.what());
  }
  return parseScript(script, file.string());
}

ScriptRunner::ScriptRunner(std::vector<ScriptAction> actions, std::string name)
    : actions_(std::move(actions)), name_(std::move(name)) {}

void ScriptRunner::requestCapture(std::filesystem::path file) {
  capture_ = std::move(file);
  captureSettle_ = kSettleFrames;
  captureDue_ = false;
}

std::optional<std::filesystem::path> ScriptRunner::takeCapture() {
  if (!captureDue_) return std::nullopt;
  captureDue_ = false;
  auto file = std::move(capture_);
  capture_.reset();
  return file;
}

void ScriptRunner::step(AppState& s) {
  if (failed()) return;
  // Everything waits for the background work (and reports a failed load).
  if (s.busy()) return;
  if (waits_.checkLoad) {
    waits_.checkLoad = false;
    const bool expected = std::exchange(waits_.expectFailure, false);
    if (expected && s.notices.failures == waits_.failuresBefore) {
      error_ = name_ + ": action " + std::to_string(actions_[next_ - 1].position) +
               " (expect_failure): the open was expected to fail, but it succeeded";
      return;
    }
    if (expected) {
      s.log.info("script: failed as expected");
    } else if (s.notices.failures != waits_.failuresBefore) {
      error_ = name_ + ": action " + std::to_string(actions_[next_ - 1].position) + " (" +
               actions_[next_ - 1].name + "): " + s.notices.lastError;
      return;
    }
  }
  if (waits_.checkExport) {
    waits_.checkExport = false;
    if (s.exports.failures != waits_.exportFailuresBefore) {
      const ScriptAction& last = actions_[next_ - 1];
      error_ = name_ + ": action " + std::to_string(last.position) + " (" + last.name +
               "): " + s.exports.lastError;
      return;
    }
  }
  if (waits_.frames > 0) {
    --waits_.frames;
    return;
  }
  if (capture_) {
    if (captureSettle_ > 0) {
      --captureSettle_;
    } else {
      captureDue_ = true;
    }
    return;
  }
  while (next_ < actions_.size()) {
    const ScriptAction& a = actions_[next_++];
    try {
      applyScriptAction(s, a, waits_);
      if (waits_.capture) requestCapture(*std::exchange(waits_.capture, std::nullopt));
    } catch (const std::exception& e) {
      error_ = name_ + ": action " + std::to_string(a.position) + " (" + a.name + " " +
               a.argument.dump() + "): " + e.what();
      return;
    }
    s.log.info("script: " + a.name + " " + a.argument.dump());
    // Each action its own undo step, as each click is (the frame loop would merge a frame's).
    s.history.observe(captureParameters(s), captureParameterContext(s), true);
    // An action that started background work (a track, a fit, a model) yields, so that the
    // next one sees its result: `track_video` then `export_state` once exported the state
    // from before the track.
    if (scriptAction(a.name)->yields || waits_.checkLoad || s.busy())
      return;
  }
}

}  // namespace ew::ui

#pragma once
// Scripted runs (tests, screenshots): a JSON array of one-key objects applied in order,
// one action per frame at most, each after the background work it depends on is done.
// The actions and their arguments: docs/VIEWER.md. An unknown or failed action stops the
// script with an error (the app then exits non-zero).

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

namespace ew::ui {

struct AppState;

struct ScriptAction {
  std::string name;
  nlohmann::json argument;
  int position = 0;  // 1-based, for messages
};

// Reads and validates the script's shape and action names; throws std::runtime_error
// naming the file and the action.
std::vector<ScriptAction> readScript(const std::filesystem::path& file);
std::vector<ScriptAction> parseScript(const nlohmann::json& script, const std::string& name);

// Applies one action that needs no waiting (everything except open, wait_frames,
// screenshot, export_png and export_video, which only a ScriptRunner can wait for): the
// guided tour's steps go through it too. Throws std::invalid_argument on a bad argument.
void applyAction(AppState& s, const ScriptAction& a);

class ScriptRunner {
 public:
  ScriptRunner() = default;
  ScriptRunner(std::vector<ScriptAction> actions, std::string name);

  // Called once per frame before the UI is built: applies actions until one has to wait.
  void step(AppState& s);
  // A screenshot to write at the end of this frame, if one is due (taken once).
  std::optional<std::filesystem::path> takeCapture();

  bool active() const { return !actions_.empty() || waitFrames_ > 0 || capture_; }
  bool finished() const { return next_ >= actions_.size() && waitFrames_ == 0 && !capture_ && !checkExport_; }
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }

  // Requests a capture of `file` once the background work is done and the UI has settled.
  void requestCapture(std::filesystem::path file);

 private:
  void apply(AppState& s, const ScriptAction& a);
  // {"expect_failure": {NAME: ARG}}: the action (or the load it starts) must fail; the failure
  // is shown as in an interactive session and the script goes on.
  void applyExpectingFailure(AppState& s, const ScriptAction& a);

  std::vector<ScriptAction> actions_;
  std::string name_;
  std::size_t next_ = 0;
  int waitFrames_ = 0;
  int failuresBefore_ = 0;
  bool checkLoad_ = false;                     // the last action opened data
  bool expectFailure_ = false;                 // … and that open must fail
  int exportFailuresBefore_ = 0;
  bool checkExport_ = false;                   // the last action started a PNG / video export
  std::optional<std::filesystem::path> capture_;
  int captureSettle_ = 0;
  bool captureDue_ = false;
  std::string error_;
};

}  // namespace ew::ui

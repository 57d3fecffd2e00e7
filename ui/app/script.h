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

// What an action leaves the runner to wait for before the next one (ScriptRunner::step).
struct ScriptWaits {
  int failuresBefore = 0;
  bool checkLoad = false;      // it started work whose failure fails the script (a load, a fit…)
  bool expectFailure = false;  // … and that work must fail (expect_failure)
  int exportFailuresBefore = 0;
  bool checkExport = false;  // it started a PNG / video export
  int frames = 0;            // frames to draw before the next action (wait_frames, mouse)
  std::optional<std::filesystem::path> capture;  // a screenshot, once the work is done

  // The work just started: its failure (notices.failures moving on) fails the script.
  void load(const AppState& s);
};

struct ScriptAction {
  std::string name;
  nlohmann::json argument;
  int position = 0;  // 1-based, for messages
};

// Reads and validates the script's shape and action names; throws std::runtime_error
// naming the file and the action.
std::vector<ScriptAction> readScript(const std::filesystem::path& file);
std::vector<ScriptAction> parseScript(const nlohmann::json& script, const std::string& name);

// Applies one action that needs no waiting (every action of the table in script_actions.h
// but those only a ScriptRunner can wait for: open, wait_frames, screenshot, export_png…):
// the guided tour's steps go through it too. Throws std::invalid_argument on a bad argument.
void applyAction(AppState& s, const ScriptAction& a);

class ScriptRunner {
 public:
  ScriptRunner() = default;
  ScriptRunner(std::vector<ScriptAction> actions, std::string name);

  // Called once per frame before the UI is built: applies actions until one has to wait.
  void step(AppState& s);
  // A screenshot to write at the end of this frame, if one is due (taken once).
  std::optional<std::filesystem::path> takeCapture();

  bool active() const { return !actions_.empty() || waits_.frames > 0 || capture_; }
  bool finished() const { return next_ >= actions_.size() && waits_.frames == 0 && !capture_ && !waits_.checkExport; }
  bool failed() const { return !error_.empty(); }
  const std::string& error() const { return error_; }

  // Requests a capture of `file` once the background work is done and the UI has settled.
  void requestCapture(std::filesystem::path file);

 private:
  std::vector<ScriptAction> actions_;
  std::string name_;
  std::size_t next_ = 0;
  ScriptWaits waits_;  // what the last action left to wait for
  std::optional<std::filesystem::path> capture_;
  int captureSettle_ = 0;
  bool captureDue_ = false;
  std::string error_;
};

}  // namespace ew::ui

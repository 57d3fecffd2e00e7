#pragma once
// Undo and redo of the parameters the user chooses (docs/VIEWER.md "Undo"): the walker, the
// mode, α, the estimator, σ², N, unknown α, the engine, compare mode, the coefficient sliders,
// the semantic axes, the overlays, the theme and the UI scale. Not the data, the models or
// anything derived (those follow from the parameters), not the 3D camera or playback (how the
// walker is being looked at as it moves: a double-click or a preset puts the camera back), and
// not a video's keyframes (their own history: ui/app/video.h). The app's undo steps through
// both in the order the changes were made: each step carries an edit serial (nextEditSerial).
//
// The frame loop shows the history the parameters after every frame (observe): a change is
// recorded once it has settled — no control held by the mouse, no repeating key down — so a
// slider dragged over many frames is one step. A new load, another model or another clip
// starts a new history: walker indices and coefficient counts of the old one mean nothing
// for the new.

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "ui/app/document.h"

namespace ew::ui {

struct AppState;

struct Parameters {
  int walker = 0;
  Mode mode = Mode::Reconstruct;
  ReconstructionSettings recon;  // σ² is 0 unless chosen: it follows the model otherwise
  bool sigma2Chosen = false;
  std::vector<double> exploreSd, editedSd;
  bool compareEngines = false;
  std::array<bool, 3> compareShown{true, true, true};
  Overlays overlays;
  double exploreOmegaOffsetRadS = 0.0;  // a semantic axis moves the explorer's stride too
  Theme theme = Theme::Dark;
  float uiScale = 1.0f;
  bool operator==(const Parameters&) const = default;
};

// What the walker indices and coefficient vectors refer to.
struct ParameterContext {
  std::uint64_t generation = 0;
  ModelSource modelSource = ModelSource::Population;
  int modelFile = 0;
  const void* inspected = nullptr;  // the population of walkers opened to inspect
  std::string clip;                 // the keypoint clip or video open ("" none)
  bool operator==(const ParameterContext&) const = default;
};

Parameters captureParameters(const AppState& s);
ParameterContext captureParameterContext(const AppState& s);
// Puts `p` back (σ² following the model again when it was then).
void restoreParameters(AppState& s, const Parameters& p);

// A number from one counter for every change either history records, so that the app's
// undo can take back the latest change whichever history holds it.
std::uint64_t nextEditSerial();
// The serial of the newest change made (0 before any). A step undone before a newer change was
// made is no longer redone by the app's redo: a new change drops what could be redone, in
// either history.
std::uint64_t latestEditSerial();

class ParameterHistory {
 public:
  static constexpr std::size_t kMaxSteps = 200;

  // Once a frame: records `now` as a step when it differs from the last recorded and has
  // `settled`; a new context clears the history.
  void observe(const Parameters& now, const ParameterContext& context, bool settled);
  // The parameters to restore, or nothing when there is no step. `now` first records what
  // has not settled yet, so an undo always goes back from what is shown.
  std::optional<Parameters> undo(const Parameters& now);
  std::optional<Parameters> redo(const Parameters& now);

  std::size_t undoSteps() const { return undo_.size(); }
  std::size_t redoSteps() const { return redo_.size(); }
  // The edit serial of the change undo would take back (a change of `now` not yet recorded is
  // the latest of all), and of the one redo would bring back; nothing when there is none.
  std::optional<std::uint64_t> undoSerial(const Parameters& now) const;
  std::optional<std::uint64_t> redoSerial(const Parameters& now) const;

 private:
  struct Step {
    Parameters parameters;  // on the undo stack: before the change; on the redo stack: after it
    std::uint64_t serial = 0;
    std::uint64_t newestWhenUndone = 0;  // on the redo stack: latestEditSerial() at the undo
  };
  void record(const Parameters& now);

  std::vector<Step> undo_, redo_;  // oldest first
  std::optional<Parameters> current_;    // the last recorded
  std::optional<ParameterContext> context_;
};

// The app's undo and redo (Ctrl+Z, Ctrl+Shift+Z / Ctrl+Y, the header's buttons): the latest
// change, of a parameter or, with a video open in the clip mode, of its keyframes (a mark, a
// correction of a detected video's joint) — whichever was made last; redo brings back the
// earliest undone first.
void undo(AppState& s);
void redo(AppState& s);
bool canUndo(const AppState& s);
bool canRedo(const AppState& s);

}  // namespace ew::ui

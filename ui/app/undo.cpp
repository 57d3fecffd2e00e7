#include "ui/app/undo.h"

#include <algorithm>
#include <limits>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui {

// [SECTION] The parameters, out of and back into the state

Parameters captureParameters(const AppState& s) {
  const Document& d = s.doc;
  Parameters p{d.walker,    d.mode,           d.recon,        d.sigma2Chosen,   d.exploreSd,
               d.editedSd,  d.compareEngines, d.compareShown, s.view.overlays, d.exploreOmegaOffsetRadS,
               s.view.theme, s.view.uiScale};
  // σ² that follows the model is no choice of the user's: another model changes it by itself.
  if (!d.sigma2Chosen) p.recon.sigma2Mm2 = 0.0;
  return p;
}

ParameterContext captureParameterContext(const AppState& s) {
  const Document& d = s.doc;
  const std::string clip = s.video.session   ? s.video.session->path.string()
                           : s.clip.settings ? s.clip.settings->path.string()
                                             : std::string();
  return {d.generation, d.modelSource, d.modelFile, d.inspected.get(), clip};
}

void restoreParameters(AppState& s, const Parameters& p) {
  Document& d = s.doc;
  const int walker = std::clamp(p.walker, 0, std::max(0, d.walkerCount() - 1));
  if (walker != d.walker) s.panels.subjects.scrollToSelection = true;  // bring it into the list's view
  d.walker = walker;
  d.mode =
      p.mode == Mode::Clip && !s.clip.settings && !s.video.session ? Mode::Reconstruct : p.mode;
  const double sigma2 = d.recon.sigma2Mm2;
  d.recon = p.recon;
  d.sigma2Chosen = p.sigma2Chosen;
  if (!p.sigma2Chosen) {
    d.recon.sigma2Mm2 = sigma2;
    actions::followModelSigma2(s);  // before the coefficients: it clears edits when σ² moves
  }
  d.exploreSd = p.exploreSd;
  d.exploreOmegaOffsetRadS = p.exploreOmegaOffsetRadS;
  d.editedSd = p.editedSd;
  d.compareEngines = p.compareEngines;
  d.compareShown = p.compareShown;
  s.view.overlays = p.overlays;
  s.view.theme = p.theme;
  s.view.uiScale = p.uiScale;
}

// [SECTION] The history

namespace {
std::uint64_t newestSerial = 0;
}  // namespace

std::uint64_t nextEditSerial() { return ++newestSerial; }

std::uint64_t latestEditSerial() { return newestSerial; }

void ParameterHistory::observe(const Parameters& now, const ParameterContext& context, bool settled) {
  if (context_ != context) {
    context_ = context;
    undo_.clear();
    redo_.clear();
    current_ = now;
    return;
  }
  if (settled && current_ != now) record(now);
}

void ParameterHistory::record(const Parameters& now) {
  if (current_) {
    undo_.push_back({*current_, nextEditSerial()});
    if (undo_.size() > kMaxSteps) undo_.erase(undo_.begin());
  }
  current_ = now;
  redo_.clear();
}

std::optional<Parameters> ParameterHistory::undo(const Parameters& now) {
  if (current_ != now) record(now);
  if (undo_.empty()) return std::nullopt;
  redo_.push_back({*current_, undo_.back().serial, latestEditSerial()});
  current_ = undo_.back().parameters;
  undo_.pop_back();
  return current_;
}

std::optional<Parameters> ParameterHistory::redo(const Parameters& now) {
  if (current_ != now) record(now);  // a change since the undo: nothing is left to redo
  if (redo_.empty()) return std::nullopt;
  undo_.push_back({*current_, redo_.back().serial});
  current_ = redo_.back().parameters;
  redo_.pop_back();
  return current_;
}

std::optional<std::uint64_t> ParameterHistory::undoSerial(const Parameters& now) const {
  if (current_ && *current_ != now) return std::numeric_limits<std::uint64_t>::max();
  if (undo_.empty()) return std::nullopt;
  return undo_.back().serial;
}

std::optional<std::uint64_t> ParameterHistory::redoSerial(const Parameters& now) const {
  if ((current_ && *current_ != now) || redo_.empty()) return std::nullopt;
  if (redo_.back().newestWhenUndone != latestEditSerial()) return std::nullopt;  // a change since
  return redo_.back().serial;
}

// [SECTION] The app's undo and redo

namespace {

// The video's keyframe history takes part while its walker is shown (the clip mode): elsewhere
// an undo would change what cannot be seen.
const VideoSession* keyframesShown(const AppState& s) {
  return s.video.session && s.doc.mode == Mode::Clip ? &*s.video.session : nullptr;
}

std::optional<std::uint64_t> keyframeUndoSerial(const AppState& s) {
  const VideoSession* v = keyframesShown(s);
  if (!v || v->undo.empty()) return std::nullopt;
  return v->undo.back().serial;
}

std::optional<std::uint64_t> keyframeRedoSerial(const AppState& s) {
  const VideoSession* v = keyframesShown(s);
  if (!v || v->redo.empty()) return std::nullopt;
  if (v->redo.back().newestWhenUndone != latestEditSerial()) return std::nullopt;  // a change since
  return v->redo.back().serial;
}

// Undo takes the later of the two histories' latest changes; redo the earlier of their latest
// undone ones, so that redoing retraces the undos backwards.
bool keyframesFirst(std::optional<std::uint64_t> keyframes, std::optional<std::uint64_t> parameters,
                    bool later) {
  if (!keyframes) return false;
  if (!parameters) return true;
  return later ? *keyframes > *parameters : *keyframes < *parameters;
}

// The history brought up to date (a load just finished: a new context) before stepping in it.
void observeSettled(AppState& s) { s.history.observe(captureParameters(s), captureParameterContext(s), true); }

}  // namespace

void undo(AppState& s) {
  observeSettled(s);
  const Parameters now = captureParameters(s);
  if (keyframesFirst(keyframeUndoSerial(s), s.history.undoSerial(now), true))
    actions::undoKeyframes(s);
  else if (const auto p = s.history.undo(now))
    restoreParameters(s, *p);
}

void redo(AppState& s) {
  observeSettled(s);
  const Parameters now = captureParameters(s);
  if (keyframesFirst(keyframeRedoSerial(s), s.history.redoSerial(now), false))
    actions::redoKeyframes(s);
  else if (const auto p = s.history.redo(now))
    restoreParameters(s, *p);
}

bool canUndo(const AppState& s) { return keyframeUndoSerial(s) || s.history.undoSteps() > 0; }

bool canRedo(const AppState& s) { return keyframeRedoSerial(s) || s.history.redoSteps() > 0; }

}  // namespace ew::ui

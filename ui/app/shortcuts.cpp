#include "ui/app/shortcuts.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <filesystem>
#include <iterator>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"
#include "ui/app/undo.h"

namespace ew::ui {

double stepAngleDeg(double alphaDeg, double deltaDeg) {
  double a = alphaDeg + deltaDeg;
  if (a > 180.0) a -= 360.0;
  if (a < -180.0) a += 360.0;
  return a;
}

namespace {

// [SECTION] What the keys do (each through the actions the controls call)

void nudgeAngle(AppState& s, double deltaDeg) { actions::setAngle(s, stepAngleDeg(s.doc.recon.alphaDeg, deltaDeg)); }

// The next (+1) or previous (−1) walker, round the list.
void stepWalker(AppState& s, int delta) {
  const int n = s.doc.walkerCount();
  if (n == 0) return;
  actions::selectWalker(s, ((s.doc.walker + delta) % n + n) % n);
  s.panels.subjects.scrollToSelection = true;
}

void toggleEstimator(AppState& s) {
  actions::setEstimator(s, s.doc.recon.estimator == Estimator::Map ? Estimator::Lsq : Estimator::Map);
}

void nextEngine(AppState& s) {
  const auto next = (static_cast<std::size_t>(s.doc.recon.engine) + 1) % std::size(kEngineKinds);
  actions::setEngine(s, kEngineKinds[next]);
}

// The clip or video view, when one is open (as the Controls panel's third mode button).
void clipMode(AppState& s) {
  if (s.clip.settings || s.video.session) actions::setMode(s, Mode::Clip);
}

// A video's joints being marked (the keys S and Enter answer only then).
bool markingVideo(const AppState& s) { return s.video.session && s.video.session->marking; }


// ← / →: a quiz's answer while one runs, else a frame back or on.
void leftOrRight(AppState& s, WalkDirection d) {
  if (s.quiz.running())
    actions::quizAnswer(s, d);
  else
    actions::stepFrame(s, d == WalkDirection::Left ? -1 : 1);
}

void startOrStopQuiz(AppState& s) {
  if (s.quiz.running())
    actions::quizStop(s);
  else if (s.doc.mode != Mode::Clip)
    actions::quizStart(s, s.quiz.options);
}

// F12: a PNG of the window in the export folder, named with the time so none is overwritten.
void screenshot(AppState& s) {
  const auto& e = s.panels.exports;
  const auto stamp =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  actions::requestPng(s,
                      std::filesystem::path(e.folder.data()) /
                          (std::string(e.baseName.data()) + "-" + std::to_string(stamp) + ".png"),
                      CaptureView::Window);
}

// Esc closes the innermost thing open: the help, else the tour, else presentation mode.
void escape(AppState& s) {
  if (s.panels.help.open) {
    s.panels.help.open = false;
  } else if (s.panels.tour.active) {
    actions::tourEnd(s);
  } else if (s.view.presentation) {
    actions::setPresentation(s, false);
  }
}

KeyBinding key(int k, void (*apply)(AppState&), bool repeats = false) { return {{k, false, false}, repeats, apply}; }
KeyBinding shifted(int k, void (*apply)(AppState&), bool repeats = false) { return {{k, false, true}, repeats, apply}; }
KeyBinding ctrl(int k, void (*apply)(AppState&), bool shift = false) { return {{k, true, shift}, true, apply}; }

// [SECTION] The table (the F1 overlay's rows, in its order)

std::vector<ShortcutRow> makeRows() {
  constexpr bool kRepeats = true;
  return {
      {"Space", "play / pause", {key(GLFW_KEY_SPACE, [](AppState& s) { s.view.playback.playing = !s.view.playback.playing; })}},
      {"← / →", "one frame back / on (a quiz running: the answer, left / right)",
       {key(GLFW_KEY_LEFT, [](AppState& s) { leftOrRight(s, WalkDirection::Left); }, kRepeats),
        key(GLFW_KEY_RIGHT, [](AppState& s) { leftOrRight(s, WalkDirection::Right); }, kRepeats)}},
      {"[ / ]", "view angle α −1° / +1°",
       {key(GLFW_KEY_LEFT_BRACKET, [](AppState& s) { nudgeAngle(s, -kAngleFineStepDeg); }, kRepeats),
        key(GLFW_KEY_RIGHT_BRACKET, [](AppState& s) { nudgeAngle(s, kAngleFineStepDeg); }, kRepeats)}},
      {"Shift+[ / ]", "view angle α −15° / +15°",
       {shifted(GLFW_KEY_LEFT_BRACKET, [](AppState& s) { nudgeAngle(s, -kAngleCoarseStepDeg); }, kRepeats),
        shifted(GLFW_KEY_RIGHT_BRACKET, [](AppState& s) { nudgeAngle(s, kAngleCoarseStepDeg); }, kRepeats)}},
      {"U", "unknown view angle on / off (estimate α)",
       {key(GLFW_KEY_U, [](AppState& s) { actions::setUnknownAngle(s, !s.doc.recon.unknownAngle); })}},
      {"M", "estimator: LSQ ↔ MAP", {key(GLFW_KEY_M, toggleEstimator)}},
      {"G", "engine: eigenwalker → snippets → skeleton", {key(GLFW_KEY_G, nextEngine)}},
      {"N / B · Page Down / Page Up", "next / previous walker",
       {key(GLFW_KEY_N, [](AppState& s) { stepWalker(s, 1); }), key(GLFW_KEY_B, [](AppState& s) { stepWalker(s, -1); }),
        key(GLFW_KEY_PAGE_DOWN, [](AppState& s) { stepWalker(s, 1); }, kRepeats),
        key(GLFW_KEY_PAGE_UP, [](AppState& s) { stepWalker(s, -1); }, kRepeats)}},
      {"R / E / V", "mode: reconstruct / explore gait space / the clip or video (when open)",
       {key(GLFW_KEY_R, [](AppState& s) { actions::setMode(s, Mode::Reconstruct); }),
        key(GLFW_KEY_E, [](AppState& s) { actions::setMode(s, Mode::Explore); }), key(GLFW_KEY_V, clipMode)}},
      {"C", "compare all three engines on / off",
       {key(GLFW_KEY_C, [](AppState& s) { actions::setCompareEngines(s, !s.doc.compareEngines); })}},
      {"1 / 2 / 3 / 4", "3D camera: front / side / top / three-quarter",
       {key(GLFW_KEY_1, [](AppState& s) { actions::setCamera(s, "front"); }),
        key(GLFW_KEY_2, [](AppState& s) { actions::setCamera(s, "side"); }),
        key(GLFW_KEY_3, [](AppState& s) { actions::setCamera(s, "top"); }),
        key(GLFW_KEY_4, [](AppState& s) { actions::setCamera(s, "three_quarter"); })}},
      {"S / Enter", "marking a video's joints: skip the joint asked for (hidden) / done",
       {key(GLFW_KEY_S, [](AppState& s) { if (markingVideo(s)) actions::skipMarkedJoint(s); }),
        key(GLFW_KEY_ENTER, [](AppState& s) { if (markingVideo(s)) actions::stopMarking(s); })}},
      {"P", "point-light display on / off (dots only)",
       {key(GLFW_KEY_P, [](AppState& s) { s.view.overlays.pointLights = !s.view.overlays.pointLights; })}},
      // The classroom displays (ui/app/stage_actions.h)
      {"I", "display: inverted on / off", {key(GLFW_KEY_I, [](AppState& s) { actions::setInverted(s, !s.stage.display.inverted); })}},
      {"X", "display: scrambled dots, none → phase → position", {key(GLFW_KEY_X, actions::cycleScramble)}},
      {"K", "display: masking noise dots on / off (how many: Controls)", {key(GLFW_KEY_K, actions::toggleMask)}},
      {"L", "display: limited-lifetime dots on / off", {key(GLFW_KEY_L, actions::toggleLifetime)}},
      {"W", "display: walking backwards on / off",
       {key(GLFW_KEY_W, [](AppState& s) { actions::setBackwards(s, !s.stage.display.backwards); })}},
      {"O", "display: overground (walks across) / treadmill",
       {key(GLFW_KEY_O, [](AppState& s) { actions::setTranslating(s, !s.stage.display.translating); })}},
      {"D", "the depth-reversed walker beside the true one on / off",
       {key(GLFW_KEY_D, [](AppState& s) { actions::setDepthReversed(s, !s.stage.depthReversed); })}},
      {"T", "turning stage: turn / pause", {key(GLFW_KEY_T, [](AppState& s) { actions::setTurning(s, !s.stage.turning); })}},
      {"0", "every display off, the stage unturned", {key(GLFW_KEY_0, actions::resetStage)}},
      {"A", "the audience window (projector) on / off",
       {key(GLFW_KEY_A, [](AppState& s) { actions::setAudienceOpen(s, !s.audience.open); })}},
      {"Q", "quiz \"which way is it walking?\": start / stop", {key(GLFW_KEY_Q, startOrStopQuiz)}},
      {"Ctrl+Z", "undo the last change: a setting, or a video's joint marked or corrected",
       {ctrl(GLFW_KEY_Z, [](AppState& s) { undo(s); })}},
      {"Ctrl+Shift+Z / Ctrl+Y", "redo",
       {ctrl(GLFW_KEY_Z, [](AppState& s) { redo(s); }, true), ctrl(GLFW_KEY_Y, [](AppState& s) { redo(s); })}},
      {"F5", "presentation mode: only the two views, large captions",
       {key(GLFW_KEY_F5, [](AppState& s) { actions::setPresentation(s, !s.view.presentation); })}},
      {"F1", "this help", {key(GLFW_KEY_F1, [](AppState& s) { s.panels.help.open = !s.panels.help.open; })}},
      {"F12", "save a PNG of the window (Export… sets the folder)", {key(GLFW_KEY_F12, screenshot)}},
      {"Esc", "close this help / end the tour / leave presentation mode", {key(GLFW_KEY_ESCAPE, escape)}},
  };
}

struct NamedKey {
  const char* script;  // as scripts write it
  const char* shown;   // as the F1 overlay does
  int key;
};

constexpr NamedKey kNamedKeys[] = {
    {"space", "Space", GLFW_KEY_SPACE},         {"left", "←", GLFW_KEY_LEFT},
    {"right", "→", GLFW_KEY_RIGHT},             {"page_up", "Page Up", GLFW_KEY_PAGE_UP},
    {"page_down", "Page Down", GLFW_KEY_PAGE_DOWN}, {"escape", "Esc", GLFW_KEY_ESCAPE},
    {"[", "[", GLFW_KEY_LEFT_BRACKET},          {"]", "]", GLFW_KEY_RIGHT_BRACKET},
    {"enter", "Enter", GLFW_KEY_ENTER},
};

std::string lower(std::string text) {
  std::transform(text.begin(), text.end(), text.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return text;
}

std::optional<int> keyFromName(const std::string& name) {
  for (const NamedKey& k : kNamedKeys)
    if (name == k.script) return k.key;
  if (name == "esc") return GLFW_KEY_ESCAPE;
  if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
    return std::toupper(static_cast<unsigned char>(name[0]));  // GLFW's letters and digits are their ASCII codes
  if (name.size() >= 2 && name[0] == 'f' && std::all_of(name.begin() + 1, name.end(), [](unsigned char c) { return std::isdigit(c) != 0; })) {
    const int n = std::stoi(name.substr(1));
    if (n >= 1 && n <= 12) return GLFW_KEY_F1 + n - 1;
  }
  return std::nullopt;
}

}  // namespace

std::span<const ShortcutRow> shortcutRows() {
  static const std::vector<ShortcutRow> rows = makeRows();  // constant data, built once
  return rows;
}

bool applyShortcut(AppState& s, const KeyChord& chord) {
  for (const ShortcutRow& row : shortcutRows())
    for (const KeyBinding& b : row.bindings)
      if (b.chord == chord) {
        b.apply(s);
        return true;
      }
  return false;
}

std::optional<KeyChord> parseKeyChord(const std::string& text) {
  KeyChord chord;
  std::string rest = lower(text);
  for (;;) {
    if (rest.rfind("ctrl+", 0) == 0) {
      chord.ctrl = true;
      rest = rest.substr(5);
    } else if (rest.rfind("shift+", 0) == 0) {
      chord.shift = true;
      rest = rest.substr(6);
    } else {
      break;
    }
  }
  const auto k = keyFromName(rest);
  if (!k) return std::nullopt;
  chord.key = *k;
  return chord;
}

std::string keyName(int key) {
  for (const NamedKey& k : kNamedKeys)
    if (k.key == key) return k.shown;
  if (key >= GLFW_KEY_F1 && key <= GLFW_KEY_F12) return "F" + std::to_string(key - GLFW_KEY_F1 + 1);
  return std::string(1, static_cast<char>(key));
}

}  // namespace ew::ui

// The keyboard table (ui/app/shortcuts.h): every key named on its F1 row, none bound twice,
// the α keys' steps and wrap, and keys applied to a state do what the controls do.

#include "ui/app/shortcuts.h"

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>

#include "ui/app/app_state.h"

namespace ew::ui {
namespace {

KeyChord chord(const std::string& name) {
  const auto c = parseKeyChord(name);
  EXPECT_TRUE(c.has_value()) << name;
  return c.value_or(KeyChord{});
}

TEST(Shortcuts, EveryKeyIsNamedOnItsHelpRowAndBoundOnce) {
  std::set<std::tuple<int, bool, bool>> seen;
  for (const ShortcutRow& row : shortcutRows()) {
    const std::string keys = row.keys;
    ASSERT_FALSE(row.bindings.empty()) << keys;
    for (const KeyBinding& b : row.bindings) {
      EXPECT_NE(keys.find(keyName(b.chord.key)), std::string::npos) << keyName(b.chord.key) << " not on \"" << keys << "\"";
      if (b.chord.shift) {
        EXPECT_NE(keys.find("Shift"), std::string::npos) << keys;
      }
      if (b.chord.ctrl) {
        EXPECT_NE(keys.find("Ctrl"), std::string::npos) << keys;
      }
      EXPECT_TRUE(seen.insert({b.chord.key, b.chord.ctrl, b.chord.shift}).second) << "bound twice: " << keys;
      EXPECT_NE(b.apply, nullptr) << keys;
    }
  }
  // The keys the viewer had before this table keep their meaning.
  for (const char* kept : {"space", "left", "right", "p", "f1", "f12", "escape"})
    EXPECT_TRUE(seen.contains({chord(kept).key, false, false})) << kept;
}

TEST(Shortcuts, KeyNamesParse) {
  EXPECT_EQ(chord("]"), (KeyChord{chord("]").key, false, false}));
  EXPECT_EQ(chord("Shift+]"), (KeyChord{chord("]").key, false, true}));
  EXPECT_EQ(chord("ctrl+shift+z"), (KeyChord{chord("z").key, true, true}));
  EXPECT_EQ(chord("n").key, chord("N").key);
  EXPECT_NE(chord("f5").key, chord("f1").key);
  EXPECT_EQ(keyName(chord("page_down").key), "Page Down");
  EXPECT_FALSE(parseKeyChord("hyper+q").has_value());
  EXPECT_FALSE(parseKeyChord("f13").has_value());
  EXPECT_FALSE(parseKeyChord("").has_value());
}

TEST(Shortcuts, AngleStepsWrapRoundTheCircle) {
  EXPECT_DOUBLE_EQ(stepAngleDeg(30.0, kAngleFineStepDeg), 31.0);
  EXPECT_DOUBLE_EQ(stepAngleDeg(30.0, -kAngleCoarseStepDeg), 15.0);
  EXPECT_DOUBLE_EQ(stepAngleDeg(179.0, 1.0), 180.0);
  EXPECT_DOUBLE_EQ(stepAngleDeg(180.0, 1.0), -179.0);
  EXPECT_DOUBLE_EQ(stepAngleDeg(-170.0, -15.0), 175.0);
}

// Keys on a state with nothing loaded: the settings they change need no data.
TEST(Shortcuts, KeysChangeWhatTheControlsChange) {
  AppState s;
  s.doc.recon.alphaDeg = 30.0;
  ASSERT_TRUE(applyShortcut(s, chord("]")));
  EXPECT_DOUBLE_EQ(s.doc.recon.alphaDeg, 31.0);
  ASSERT_TRUE(applyShortcut(s, chord("shift+[")));
  EXPECT_DOUBLE_EQ(s.doc.recon.alphaDeg, 16.0);
  const Estimator before = s.doc.recon.estimator;
  applyShortcut(s, chord("m"));
  EXPECT_NE(s.doc.recon.estimator, before);
  applyShortcut(s, chord("m"));
  EXPECT_EQ(s.doc.recon.estimator, before);
  applyShortcut(s, chord("u"));
  EXPECT_TRUE(s.doc.recon.unknownAngle);
  applyShortcut(s, chord("e"));
  EXPECT_EQ(s.doc.mode, Mode::Explore);
  applyShortcut(s, chord("v"));  // no clip or video open: stays
  EXPECT_EQ(s.doc.mode, Mode::Explore);
  applyShortcut(s, chord("r"));
  EXPECT_EQ(s.doc.mode, Mode::Reconstruct);
  applyShortcut(s, chord("g"));
  EXPECT_EQ(s.doc.recon.engine, EngineKind::Snippet);
  applyShortcut(s, chord("c"));
  EXPECT_TRUE(s.doc.compareEngines);
  applyShortcut(s, chord("2"));
  EXPECT_EQ(s.view.camera.yawDeg, OrbitCamera::preset(CameraPreset::Side).yawDeg);
  applyShortcut(s, chord("n"));  // nothing loaded: no walker to go to, and no error
  EXPECT_EQ(s.doc.walker, 0);
  // F5 and Esc: in and out of presentation mode; Esc closes the help first.
  applyShortcut(s, chord("f5"));
  EXPECT_TRUE(s.view.presentation);
  applyShortcut(s, chord("f1"));
  applyShortcut(s, chord("escape"));
  EXPECT_FALSE(s.panels.help.open);
  EXPECT_TRUE(s.view.presentation);
  applyShortcut(s, chord("escape"));
  EXPECT_FALSE(s.view.presentation);
  // The classroom displays: each its key, 0 all off.
  applyShortcut(s, chord("i"));
  EXPECT_TRUE(s.stage.display.inverted);
  applyShortcut(s, chord("x"));
  EXPECT_EQ(s.stage.display.scramble, Scramble::Phase);
  applyShortcut(s, chord("x"));
  EXPECT_EQ(s.stage.display.scramble, Scramble::Position);
  applyShortcut(s, chord("k"));
  EXPECT_EQ(s.stage.display.maskDots, kDefaultMaskDots);
  applyShortcut(s, chord("l"));
  EXPECT_GT(s.stage.display.dotLifetimeS, 0.0);
  applyShortcut(s, chord("w"));
  EXPECT_TRUE(s.stage.display.backwards);
  applyShortcut(s, chord("o"));
  EXPECT_TRUE(s.stage.display.translating);
  applyShortcut(s, chord("d"));
  EXPECT_TRUE(s.stage.depthReversed);
  applyShortcut(s, chord("t"));
  EXPECT_TRUE(s.stage.turning);
  applyShortcut(s, chord("0"));
  EXPECT_FALSE(s.stage.shown());
  applyShortcut(s, chord("a"));
  EXPECT_TRUE(s.audience.open);
  EXPECT_FALSE(applyShortcut(s, chord("j")));  // unbound
}

}  // namespace
}  // namespace ew::ui

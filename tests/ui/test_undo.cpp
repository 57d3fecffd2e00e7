// Undo and redo of the parameters (ui/app/undo.h): a drag over many frames is one step, undo
// and redo walk the steps both ways, a new change drops what could be redone, a new load starts
// a new history, the history is bounded; on a state, undo puts back α and the estimator.

#include "ui/app/undo.h"

#include <gtest/gtest.h>

#include "ui/app/actions.h"
#include "ui/app/app_state.h"

namespace ew::ui {
namespace {

Parameters withAlpha(double alphaDeg) {
  Parameters p;
  p.recon.alphaDeg = alphaDeg;
  return p;
}

TEST(Undo, ADragIsOneStep) {
  ParameterHistory h;
  const ParameterContext context;
  h.observe(withAlpha(30), context, true);
  // The slider held over four frames: nothing recorded until it is let go.
  for (double alpha : {31.0, 32.5, 34.0, 35.0}) h.observe(withAlpha(alpha), context, false);
  EXPECT_EQ(h.undoSteps(), 0u);
  h.observe(withAlpha(35), context, true);
  h.observe(withAlpha(35), context, true);  // settled frames after it add nothing
  EXPECT_EQ(h.undoSteps(), 1u);
  const auto back = h.undo(withAlpha(35));
  ASSERT_TRUE(back.has_value());
  EXPECT_DOUBLE_EQ(back->recon.alphaDeg, 30.0);
  EXPECT_EQ(h.undoSteps(), 0u);
  EXPECT_EQ(h.redoSteps(), 1u);
}

TEST(Undo, UndoAndRedoWalkTheStepsAndANewChangeDropsTheRedo) {
  ParameterHistory h;
  const ParameterContext context;
  for (double alpha : {10.0, 20.0, 30.0}) h.observe(withAlpha(alpha), context, true);
  EXPECT_DOUBLE_EQ(h.undo(withAlpha(30))->recon.alphaDeg, 20.0);
  EXPECT_DOUBLE_EQ(h.undo(withAlpha(20))->recon.alphaDeg, 10.0);
  EXPECT_FALSE(h.undo(withAlpha(10)).has_value());  // nothing before the first
  EXPECT_DOUBLE_EQ(h.redo(withAlpha(10))->recon.alphaDeg, 20.0);
  // A change that has not settled yet is recorded before undoing it: undo goes back from it.
  EXPECT_DOUBLE_EQ(h.undo(withAlpha(25))->recon.alphaDeg, 20.0);
  EXPECT_EQ(h.redoSteps(), 1u);
  h.observe(withAlpha(40), context, true);  // a new change: the redo is gone
  EXPECT_EQ(h.redoSteps(), 0u);
  EXPECT_FALSE(h.redo(withAlpha(40)).has_value());
}

TEST(Undo, ANewContextStartsANewHistoryAndTheHistoryIsBounded) {
  ParameterHistory h;
  ParameterContext context;
  for (int i = 0; i < 300; ++i) h.observe(withAlpha(i % 180), context, true);
  EXPECT_EQ(h.undoSteps(), ParameterHistory::kMaxSteps);
  context.generation = 1;  // new data: its walker indices mean something else
  h.observe(withAlpha(5), context, true);
  EXPECT_EQ(h.undoSteps(), 0u);
  EXPECT_EQ(h.redoSteps(), 0u);
}

TEST(Undo, OnTheStateUndoPutsBackTheAngleAndTheEstimator) {
  AppState s;
  s.doc.recon.alphaDeg = 30.0;
  s.doc.recon.estimator = Estimator::Map;
  const auto settle = [&s] { s.history.observe(captureParameters(s), captureParameterContext(s), true); };
  settle();
  actions::setAngle(s, 40.0);
  settle();
  actions::setEstimator(s, Estimator::Lsq);
  actions::setOverlay(s, "grid", false);  // in the same frame: the same step
  settle();
  undo(s);
  EXPECT_EQ(s.doc.recon.estimator, Estimator::Map);
  EXPECT_TRUE(s.view.overlays.grid);
  EXPECT_DOUBLE_EQ(s.doc.recon.alphaDeg, 40.0);
  undo(s);
  EXPECT_DOUBLE_EQ(s.doc.recon.alphaDeg, 30.0);
  undo(s);  // nothing left: no change
  EXPECT_DOUBLE_EQ(s.doc.recon.alphaDeg, 30.0);
  redo(s);
  redo(s);
  EXPECT_DOUBLE_EQ(s.doc.recon.alphaDeg, 40.0);
  EXPECT_EQ(s.doc.recon.estimator, Estimator::Lsq);
  EXPECT_FALSE(canRedo(s));
  EXPECT_TRUE(canUndo(s));
}

// The theme and the UI scale are settings a user undoes too; the 3D camera is not (it is how
// the walker is looked at, not what is shown of it).
TEST(Undo, ThemeAndScaleAreStepsTheCameraIsNot) {
  AppState s;
  const auto settle = [&s] { s.history.observe(captureParameters(s), captureParameterContext(s), true); };
  settle();
  s.view.theme = Theme::Projector;
  settle();
  s.view.uiScale = 1.5f;
  s.view.camera.yawDeg += 40.0f;
  settle();
  undo(s);
  EXPECT_FLOAT_EQ(s.view.uiScale, 1.0f);
  EXPECT_EQ(s.view.theme, Theme::Projector);
  undo(s);
  EXPECT_EQ(s.view.theme, Theme::Dark);
  const float yaw = s.view.camera.yawDeg;
  redo(s);
  redo(s);
  EXPECT_FLOAT_EQ(s.view.uiScale, 1.5f);
  EXPECT_FLOAT_EQ(s.view.camera.yawDeg, yaw);  // the camera moved with none of the steps
}

// σ² the user never set follows the model: undo does not pin it to the value it had then.
TEST(Undo, SigmaSquaredFollowingTheModelStaysFollowing) {
  AppState s;
  s.doc.recon.sigma2Mm2 = 1000.0;  // as followModelSigma2 would have set it
  const auto settle = [&s] { s.history.observe(captureParameters(s), captureParameterContext(s), true); };
  settle();
  actions::setSigma2(s, 250.0);
  settle();
  EXPECT_TRUE(s.doc.sigma2Chosen);
  undo(s);
  EXPECT_FALSE(s.doc.sigma2Chosen);
  redo(s);
  EXPECT_TRUE(s.doc.sigma2Chosen);
  EXPECT_DOUBLE_EQ(s.doc.recon.sigma2Mm2, 250.0);
}

}  // namespace
}  // namespace ew::ui

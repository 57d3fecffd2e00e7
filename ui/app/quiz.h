#pragma once
// "Which way is it walking?" — the quiz for a room (issue 56): left/right trials of the stage's
// walker seen in profile, in masking noise stepped by a 1-up-2-down staircase
// (core/teaching/staircase.h). The trials show the displays chosen on the stage (inverted,
// scrambled, …) with the staircase's noise; the answers come from the presenter's keys
// (← / →), the quiz panel's buttons or a script.

#include <filesystem>
#include <optional>
#include <string>

#include "core/teaching/staircase.h"

namespace ew::ui {

struct QuizFeature {
  StaircaseOptions options{.startDots = 0, .stepDots = 10, .maxDots = 1000, .reversals = 12,
                           .averagedReversals = 8, .seed = 1};
  std::optional<Staircase> staircase;  // the quiz run or being run
  bool stopped = false;                // stopped before its end (its trials kept)
  bool open = false;                   // the quiz panel shown
  std::string status;                  // the last save's, or the last refusal's, words
  bool running() const { return staircase && !staircase->done() && !stopped; }
};

}  // namespace ew::ui

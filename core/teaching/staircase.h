#pragma once
// "Which way is it walking?" — a quiz for a room: left/right trials of a point-light walker in
// masking noise, the noise stepped by the answers with a 1-up-2-down staircase (Levitt 1971):
// two right answers in a row add noise, one wrong answer takes it away, so the noise settles
// where the room answers right 70.7 % of the time. The threshold is the mean noise of the last
// reversals (where the direction of the steps turned).

#include <cstdint>
#include <string>
#include <vector>

namespace ew {

struct StaircaseOptions {
  int startDots = 0;       // noise dots on the first trial
  int stepDots = 10;       // after the first two reversals; twice this before
  int maxDots = 1000;
  int reversals = 12;      // the quiz ends after this many
  int averagedReversals = 8;  // the threshold: mean over this many last reversals
  std::uint64_t seed = 1;  // the walking directions
};

enum class WalkDirection { Left, Right };
const char* walkDirectionName(WalkDirection d);  // "left", "right"

struct QuizTrial {
  int number = 0;            // 1-based
  int noiseDots = 0;
  WalkDirection shown = WalkDirection::Left;
  WalkDirection answered = WalkDirection::Left;
  bool correct = false;
  bool reversal = false;     // the steps turned at this trial
};

class Staircase {
 public:
  // Throws Error(BadArgument) "staircase: …" for counts that are not positive, a start past
  // the maximum, or averaging more reversals than the quiz has.
  explicit Staircase(const StaircaseOptions& options);

  bool done() const;
  int noiseDots() const { return dots_; }             // the next trial's
  WalkDirection direction() const { return next_; }   // the next trial's (random, from the seed)
  // Records the answer to the current trial and sets the next one. Throws when done.
  const QuizTrial& answer(WalkDirection answered);

  const std::vector<QuizTrial>& trials() const { return trials_; }
  int reversalCount() const { return static_cast<int>(reversalDots_.size()); }
  // The mean noise of the last averagedReversals reversals (fewer while the quiz runs; NaN
  // before the first).
  double thresholdDots() const;
  const StaircaseOptions& options() const { return options_; }

 private:
  void drawDirection();

  StaircaseOptions options_;
  int dots_;
  int rightInARow_ = 0;
  int lastStep_ = 0;  // +1 noise added, −1 taken away, 0 none yet
  WalkDirection next_ = WalkDirection::Left;
  std::uint64_t state_;
  std::vector<QuizTrial> trials_;
  std::vector<int> reversalDots_;
};

// trial,noise_dots,shown,answered,correct,reversal — one line a trial, then nothing else (the
// threshold is the caller's to report).
std::string quizCsv(const std::vector<QuizTrial>& trials);

}  // namespace ew

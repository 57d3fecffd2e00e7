#include "core/teaching/staircase.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>

#include "core/common/errors.h"

namespace ew {
namespace {

[[noreturn]] void refuseQuiz(const std::string& problem) {
  throw Error(ErrorKind::BadArgument, "", "", "staircase: " + problem);
}

// SplitMix64: a fixed sequence on every machine (the directions of a saved quiz replay).
std::uint64_t nextRandom(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

}  // namespace

const char* walkDirectionName(WalkDirection d) { return d == WalkDirection::Left ? "left" : "right"; }

Staircase::Staircase(const StaircaseOptions& o) : options_(o), dots_(o.startDots), state_(o.seed) {
  if (o.stepDots < 1) refuseQuiz("the step must be at least one dot");
  if (o.maxDots < 1 || o.startDots < 0 || o.startDots > o.maxDots)
    refuseQuiz("the start must be between 0 and the maximum of " + std::to_string(o.maxDots) + " dots");
  if (o.reversals < 1) refuseQuiz("the quiz needs at least one reversal");
  if (o.averagedReversals < 1 || o.averagedReversals > o.reversals)
    refuseQuiz("the threshold averages 1 to " + std::to_string(o.reversals) + " reversals");
  drawDirection();
}

void Staircase::drawDirection() {
  next_ = (nextRandom(state_) >> 63) ? WalkDirection::Right : WalkDirection::Left;
}

bool Staircase::done() const { return reversalCount() >= options_.reversals; }

const QuizTrial& Staircase::answer(WalkDirection answered) {
  if (done()) refuseQuiz("the quiz is over");
  QuizTrial t;
  t.number = static_cast<int>(trials_.size()) + 1;
  t.noiseDots = dots_;
  t.shown = next_;
  t.answered = answered;
  t.correct = answered == next_;
  // 1 up (more noise: harder) after two right in a row, 1 down after a wrong answer.
  int step = 0;
  if (t.correct) {
    if (++rightInARow_ == 2) {
      step = +1;
      rightInARow_ = 0;
    }
  } else {
    step = -1;
    rightInARow_ = 0;
  }
  if (step != 0) {
    if (lastStep_ != 0 && step != lastStep_) {
      t.reversal = true;
      reversalDots_.push_back(dots_);
    }
    lastStep_ = step;
    // Big steps until the staircase has found the region (two reversals), then fine ones.
    const int size = reversalCount() < 2 ? 2 * options_.stepDots : options_.stepDots;
    dots_ = std::clamp(dots_ + step * size, 0, options_.maxDots);
  }
  trials_.push_back(t);
  drawDirection();
  return trials_.back();
}

double Staircase::thresholdDots() const {
  if (reversalDots_.empty()) return NAN;
  const size_t n = std::min(reversalDots_.size(), static_cast<size_t>(options_.averagedReversals));
  return std::accumulate(reversalDots_.end() - static_cast<std::ptrdiff_t>(n), reversalDots_.end(), 0.0) /
         static_cast<double>(n);
}

std::string quizCsv(const std::vector<QuizTrial>& trials) {
  std::ostringstream out;
  out << "trial,noise_dots,shown,answered,correct,reversal\n";
  for (const auto& t : trials)
    out << t.number << ',' << t.noiseDots << ',' << walkDirectionName(t.shown) << ','
        << walkDirectionName(t.answered) << ',' << (t.correct ? 1 : 0) << ',' << (t.reversal ? 1 : 0) << '\n';
  return out.str();
}

}  // namespace ew

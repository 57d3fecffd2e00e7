#include "ui/app/document.h"

#include <algorithm>
#include <cmath>

namespace ew::ui {

double Playback::phase() const { return cycles - std::floor(cycles); }

void Playback::setPhase(double phase01) {
  cycles = std::floor(cycles) + std::clamp(phase01, 0.0, 1.0);
}

void Playback::advance(double seconds, double strideHz) {
  if (playing) cycles += seconds * static_cast<double>(speed) * strideHz;
}

void Playback::step(int frames, double strideHz) { cycles += frames * strideHz / 60.0; }

}  // namespace ew::ui

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

namespace ew::ui {

// [SECTION] Walkers and the held model

const Walker* Document::walkerAt(int index) const {
  if (index < 0) return nullptr;
  if (index < populationCount()) return &population->walkers[static_cast<std::size_t>(index)];
  const int i = index - populationCount();
  if (!inspected || i >= inspected->walkerCount()) return nullptr;
  return &inspected->walkers[static_cast<std::size_t>(i)];
}

const WalkerFacts* Document::factsAt(int index) const {
  if (index < 0) return nullptr;
  if (index < populationCount()) return &population->facts[static_cast<std::size_t>(index)];
  const int i = index - populationCount();
  if (!inspected || i >= inspected->walkerCount()) return nullptr;
  return &inspected->facts[static_cast<std::size_t>(i)];
}

const EigenwalkerModel* Document::heldModel() const {
  switch (modelSource) {
    case ModelSource::Population:
      return models ? &models->all : nullptr;
    case ModelSource::Default:
      return defaultModel ? &defaultModel->model : nullptr;
    case ModelSource::File:
      if (modelFile < 0 || modelFile >= static_cast<int>(modelFiles.size())) return nullptr;
      return &modelFiles[static_cast<std::size_t>(modelFile)]->model;
  }
  return nullptr;
}

}  // namespace ew::ui

#pragma once
// Wall-clock seconds for the timing columns and logs (experiments, model builds).

#include <chrono>

namespace ew {

inline double secondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace ew

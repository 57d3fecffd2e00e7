#pragma once
// A small, fully specified random number generator for the synthetic population, so a
// seed gives the same walkers on every compiler and standard library (std::normal_distribution
// and friends are implementation-defined and differ between libstdc++ and libc++).
//   seeding:  SplitMix64 (Steele, Lea & Flood 2014), also used to derive child seeds
//   stream:   xoshiro256** 1.0 (Blackman & Vigna 2018, https://prng.di.unimi.it/)
//   uniform:  the top 53 bits as a double in [0, 1)
//   normal:   Box-Muller (both values used, in order)

#include <cmath>
#include <cstdint>
#include <numbers>

namespace ew {

// One SplitMix64 step: advances `state` and returns a well-mixed 64-bit value.
inline std::uint64_t splitMix64(std::uint64_t& state) {
  std::uint64_t z = (state += 0x9E3779B97F4A7C15ull);
  z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
  z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
  return z ^ (z >> 31);
}

// A seed for the `stream`-th independent child of `seed` (walker i of a population,
// trial j of a walker): walker i is the same whatever the population size.
inline std::uint64_t childSeed(std::uint64_t seed, std::uint64_t stream) {
  std::uint64_t state = seed ^ (0xD1B54A32D192ED03ull * (stream + 1));
  splitMix64(state);
  return splitMix64(state);
}

class Rng {
 public:
  explicit Rng(std::uint64_t seed) {
    std::uint64_t state = seed;
    for (auto& word : s_) word = splitMix64(state);
  }

  std::uint64_t next() {
    const std::uint64_t result = rotl(s_[1] * 5, 7) * 9;
    const std::uint64_t t = s_[1] << 17;
    s_[2] ^= s_[0];
    s_[3] ^= s_[1];
    s_[1] ^= s_[2];
    s_[0] ^= s_[3];
    s_[2] ^= t;
    s_[3] = rotl(s_[3], 45);
    return result;
  }

  double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

  double normal() {
    if (hasSpare_) {
      hasSpare_ = false;
      return spare_;
    }
    const double u1 = 1.0 - uniform();  // (0, 1]: log is finite
    const double u2 = uniform();
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(2.0 * std::numbers::pi * u2);
    hasSpare_ = true;
    return r * std::cos(2.0 * std::numbers::pi * u2);
  }
  double normal(double mean, double sd) { return mean + sd * normal(); }

 private:
  static std::uint64_t rotl(std::uint64_t x, int k) { return (x << k) | (x >> (64 - k)); }
  std::uint64_t s_[4]{};
  double spare_ = 0.0;
  bool hasSpare_ = false;
};

}  // namespace ew

#pragma once
// Synthetic walkers: a plausible 15-joint walking pattern in Fourier form (METHOD §3 layout,
// canonical frame of METHOD §2, mm) and random individual variations of it. For tests,
// benchmarks and demos that must not depend on recorded data.

#include <Eigen/Core>
#include <cstdint>

namespace ew {

// The base walker (225): about 1.75 m tall, phase-aligned (z_l_ankle − z_r_ankle has a
// pure positive-sine fundamental), 1st-harmonic leg and arm swing, 2nd-harmonic bounce.
Eigen::VectorXd syntheticBaseWalker();

// `count` walkers (225 × count): body size, segment swing amplitudes and every
// coefficient varied at random (seeded, reproducible on one standard library). Each
// stays phase-aligned, so the set spans count − 1 independent directions. count in
// [1, 100 000], else Error(BadArgument).
Eigen::MatrixXd syntheticWalkerSet(int count, std::uint64_t seed);

}  // namespace ew

#pragma once
// Is the walker the size of a person? A wrong length unit is the commonest motion-capture
// mistake (`--units m` on a file in centimetres makes a walker 100 times too tall), and
// every later stage works on regardless: the steady window, the Fourier fit and the model
// all scale. This check measures the body after mapping to joints and, when it is no
// human size, says so and names the unit that would make it one.

#include <Eigen/Core>
#include <optional>
#include <string>

#include "core/common/trial.h"

namespace ew {

// One measured body length, mm, and the range a person's falls in.
struct BodySize {
  std::string what;     // "head to ankles" or "hips to ankles"
  double lengthMm = 0;  // median over frames
  double minMm = 0;     // plausible range for people (children to very tall adults)
  double maxMm = 0;
  double typicalMm = 0;  // an average adult's, for choosing the likely unit
};

// The median over frames of the distance from the head to the mid-point of the ankles
// (an adult of stature S stands about 0.87 S there: 0.7–2.2 m covers statures of about
// 0.8–2.5 m); without a measured head, the mean of the two hip-to-ankle distances (0.35–
// 1.2 m). Frames with a NaN in the joints used are skipped. framesX45: T × 45, mm, any
// axes. nullopt when no frame has the joints.
std::optional<BodySize> measureBodySize(const Eigen::Ref<const Eigen::MatrixXd>& framesX45);

// A warning when the trial's body size is implausible for a person, naming the file, the
// size measured and, when another length unit (mm, cm, m, in, cmu) makes it plausible,
// that unit: "FILE: the walker measures 19.4 m from head to ankles, no person's size: the
// file's unit is probably cm, not m; use --units cm". `trial.units` is the unit the data
// was read in; nullopt when the size is plausible or cannot be measured.
std::optional<std::string> bodySizeWarning(const JointTrial& trial);

// A walker's stature from its head joint (METHOD §1: the head's centre) above its ankles while
// walking, the cycle mean of the head's height over the mean of the two ankles': that height
// is this share of the stature in the 18 Schreiber-Moissenet walkers, whose C3D files record
// each subject's height (0.843 ± 0.015, mean ± SD, 0.792–0.860; docs/CAMERA.md; measured by
// tests/gait/test_body_size.cpp, which also predicts each walker from the other 17).
inline constexpr double kHeadAboveAnklesOfStature = 0.843;

inline double statureFromHeadAboveAnklesMm(double headAboveAnklesMm) {
  return headAboveAnklesMm / kHeadAboveAnklesOfStature;
}

}  // namespace ew

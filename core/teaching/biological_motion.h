#pragma once
// The classic point-light displays of biological motion over any Fourier walker (METHOD §3),
// as a perception lecture shows them:
//   inverted         upside down about the walker's mid-height (the inversion effect:
//                    Sumi 1984; Troje & Westhoff 2006)
//   phase-scrambled  each dot keeps its own trajectory, started at its own random phase: the
//                    local motion kept, the form (the dots' synchrony) destroyed
//   position-scrambled  each dot keeps its own motion about its own mean, carried to a random
//                    place in the walker's extent: the local motion kept, the form destroyed
//   masked           N noise dots, each moving as one of the walker's dots does (a random dot,
//                    a random phase, a random place in a region twice the walker's extent):
//                    the masking paradigm (Cutting, Moore & Morrison 1988)
//   limited lifetime the walker drawn by dots at random places on its limbs, each living a
//                    given time before moving elsewhere (Beintema & Lappe 2002)
//   backwards        time reversed: a walker walking backwards
//   translating      carried forward at its speed (overground) or not (treadmill)
// and the 2D→3D ambiguity: depthReversed, the walker mirrored in depth at a view, which
// projects to the same image (the mirror minimum of J(α), METHOD §6).
//
// Everything random is drawn once from the seed when the display is made, so a display is a
// pure function of time: the same seed gives the same dots on every machine, in the viewer, a
// script and a test. Positions are mm in the walker's canonical frame (x right, y forward,
// z up).

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

namespace ew {

enum class Scramble { None, Phase, Position };

struct BiologicalMotionOptions {
  bool inverted = false;
  Scramble scramble = Scramble::None;
  int maskDots = 0;               // noise dots; 0 = no mask
  double dotLifetimeS = 0.0;      // > 0: limited-lifetime dots instead of the joints
  int lifetimeDots = 8;           // how many (Beintema & Lappe's displays used 8)
  bool backwards = false;
  bool translating = false;
  double speedMmS = 1300.0;       // the walk's speed when translating
  std::uint64_t seed = 1;
};

inline constexpr int kMaxMaskDots = 2000;      // more is a blank screen, not a display
inline constexpr int kMaxLifetimeDots = 200;

// Why a display draws no lines between its dots: the form is not there to join.
bool displayKeepsTheForm(const BiologicalMotionOptions& options);

// The display's dots at one time.
struct DisplayDots {
  Eigen::Matrix3Xd walkerMm;  // the walker's dots: 15 joints (METHOD §1 order), or the lifetime dots
  Eigen::Matrix3Xd noiseMm;   // the mask's dots
};

class BiologicalMotionDisplay {
 public:
  // w: 225 (METHOD §3), ω > 0, φ: the walker's phase origin. Throws Error(BadArgument)
  // "biological motion: …" for a wrong size, a non-finite value, or counts past the caps.
  BiologicalMotionDisplay(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS, double phaseRad,
                          const BiologicalMotionOptions& options);

  DisplayDots at(double timeS) const;
  const BiologicalMotionOptions& options() const { return options_; }
  double strideS() const;

 private:
  Eigen::Matrix3Xd jointsAt(double timeS) const;  // the walker's 15 joints, moving as it walks

  Eigen::VectorXd w_;
  double omega_, phase_;
  BiologicalMotionOptions options_;
  double midHeightMm_ = 0.0;
  Eigen::Matrix3Xd meanMm_;          // each joint's mean over the cycle (p0)
  Eigen::VectorXd jointPhaseS_;      // phase scrambling: each joint's time offset
  Eigen::Matrix3Xd jointPlaceMm_;    // position scrambling: each joint's new mean
  std::vector<int> noiseSource_;     // mask: the joint each noise dot moves like
  Eigen::VectorXd noisePhaseS_;
  Eigen::Matrix3Xd noisePlaceMm_;
};

// The walker mirrored in depth at view α: every point reflected in the vertical plane of the
// image, so its orthographic projection at α (core/eigenwalker/projection.h) is the walker's
// own and its depth the negative. Applies to a Fourier vector (225) or frames (T × 45).
Eigen::VectorXd depthReversedWalker(const Eigen::Ref<const Eigen::VectorXd>& w, double alphaDeg);
Eigen::MatrixXd depthReversedFrames(const Eigen::Ref<const Eigen::MatrixXd>& framesX45, double alphaDeg);

}  // namespace ew

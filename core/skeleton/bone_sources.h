#pragma once
// Where the skeleton engine's bone lengths come from when the performer was not measured
// in 3D (Zou et al. 2009, §4.1 and Table 2; and, beyond the paper, the eigenwalker):
//
//   stature × Table 2   the paper's relative segment lengths scaled to a stated stature S.
//                       Its segments map onto the 15 joints as lower + upper torso
//                       (20 + 34) = pelvis → sternum, neck 20 = sternum → head, clavicle 21,
//                       upper arm 21, lower arm 24, hip 10, thigh 30, leg 36. The vertical
//                       chain leg + thigh + torso + neck (140 units; the hip bone is
//                       sideways, the pelvis the hips' midpoint) is set to 0.87 S, where a
//                       standing adult's head joint is above the ankles (core/gait/body_size.h).
//   a walker            the median length of each bone over one gait cycle of a Fourier
//                       walker (METHOD §3): the eigenwalker's reconstruction of this walker, or
//                       a model's mean walker for a population's proportions.
//   scaled to stature   any lengths scaled by one factor so that the same chain is 0.87 S.
//   reference frame     §4.1: one frame where the body is parallel to the image plane;
//                       every bone's image length is its length up to one scale, which one
//                       bone of known length fixes. Pixels of a pinhole image (the body at
//                       one depth) or mm of an orthographic view.

#include <Eigen/Core>
#include <string>

#include "core/skeleton/skeleton_tree.h"

namespace ew {

// How far a standing adult's head joint is above the ankles, as a share of stature.
inline constexpr double kHeadAboveAnklesPerStature = 0.87;

// The vertical chain of `bones` standing: the right shank and thigh, pelvis → sternum,
// sternum → head (mm).
double standingChainMm(const BoneLengths& bones);

// Throws Error(BadArgument) naming `what` for a stature outside 0.5–2.5 m.
BoneLengths boneLengthsFromZouTable2(double statureMm, const std::string& what);
BoneLengths scaledToStature(const BoneLengths& bones, double statureMm, const std::string& what);

// w: 225 (METHOD §3); omegaRadS > 0. 64 frames over one cycle. Throws Error(BadArgument)
// naming `what` for a w that is not 225 finite values or a bone of length 0.
BoneLengths boneLengthsFromWalker(const Eigen::Ref<const Eigen::VectorXd>& w, double omegaRadS,
                                  const std::string& what);

// frame: 30 values (u, v per joint, METHOD §1 order); `referenceBone` indexes kBones. Throws
// Error(BadData) naming `what` and the bone for a joint not seen in the frame or a
// reference bone of no image length, Error(BadArgument) for a length that is not positive.
BoneLengths boneLengthsFromReferenceFrame(const Eigen::Ref<const Eigen::RowVectorXd>& frame, int referenceBone,
                                          double referenceLengthMm, const std::string& what);

}  // namespace ew

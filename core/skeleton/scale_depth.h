#pragma once
// The focal length of an uncalibrated camera from one frame (Zou et al. 2009, §3.3.2,
// eq. 2–4): a chain of three linked segments a–b, b–c, c–d whose outer two lie parallel to
// the image plane (the user picks such a frame, as the paper's Fig. 6 does). Under eq. 1,
// u = x / s with s = z / f, each outer segment gives its scale from its known length,
// s_ab = L_ab / |a′b′| and s_cd = L_cd / |c′d′|; the middle one's length gives the depth step
// between them, dz² = L_bc² − |s_cd c′ − s_ab b′|² (eq. 3, image points from the principal
// point); and T(dz) = ds is linear, ds = dz / f (eq. 4), so f = |dz| / |s_cd − s_ab|.

#include <Eigen/Core>
#include <array>
#include <string>

#include "core/common/skeleton.h"
#include "core/skeleton/skeleton_tree.h"

namespace ew {

struct ScaleDepthFocal {
  double focalPx = 0.0;
  double nearScaleMmPerPx = 0.0, farScaleMmPerPx = 0.0;  // s_ab, s_cd (mm per px)
  double depthStepMm = 0.0;                             // |dz| between the outer segments
};

// frame: 30 values (u, v per joint, METHOD §1 order; pixels); the principal point in pixels;
// chain: a, b, c, d. Throws Error(BadArgument) naming `what` for joints that are not a
// chain of three bones, Error(BadData) naming `what` and the joint or bone for a joint not
// seen, an outer segment of no image length, a middle bone that looks longer than it is
// (the outer segments are not parallel to the image plane in this frame) or two outer
// segments at one depth (ds = 0: the focal length is undetermined).
ScaleDepthFocal focalFromScaleDepth(const Eigen::Ref<const Eigen::RowVectorXd>& framePx, double cxPx, double cyPx,
                                    const std::array<Joint, 4>& chain, const BoneLengths& bones,
                                    const std::string& what);

}  // namespace ew

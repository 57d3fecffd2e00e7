#pragma once
// `reconstruct --engine skeleton`: a pose estimator's keypoints through a pinhole camera to
// 3D by geometry alone (Zou et al. 2009; core/skeleton/skeleton_camera.h). The camera: a
// calibration file, a focal length the user gives, or one from the paper's scale-depth
// relation T(dz) on a frame the user picks (§3.3.2). The bone lengths: a 3D reference of the
// same person (the paper's "known bone lengths"; the result is also scored against it), the
// paper's Table 2 scaled to a stature, a frame with the body parallel to the image plane and
// one bone of known length (§4.1), or the eigenwalker's fit of this walker. The branches may
// follow the eigenwalker's fit (a guide).

#include <optional>
#include <string>
#include "app/cli/reconstruct_args.h"

namespace ew::cli {

int runReconstructSkeleton(const SkeletonArgs& args);

}  // namespace ew::cli

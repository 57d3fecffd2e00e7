#pragma once
// `reconstruct --engine skeleton`: a pose estimator's keypoints through a calibrated
// pinhole camera to 3D by geometry alone (Zou et al. 2009; core/skeleton/skeleton_camera.h),
// with the bone lengths of a 3D reference of the same person (the paper's "known bone
// lengths"), against which the result is also scored.

#include <optional>
#include <string>

namespace ew::cli {

struct SkeletonArgs {
  std::string input, out, layout, camera, cameraName, reference;
  std::string angles;  // joint angles (.mot or .csv) of the result, when given
  std::optional<double> fps;
  bool json = false;
};

int runReconstructSkeleton(const SkeletonArgs& args);

}  // namespace ew::cli

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

namespace ew::cli {

struct SkeletonArgs {
  std::string input, out, layout, camera, cameraName, reference;
  std::string angles;  // joint angles (.mot or .csv) of the result, when given
  std::optional<double> fps;
  bool json = false;
  std::string detectModel = "full";  // a video's input: the built-in detector's model
  // Without a calibration: a focal length, or T(dz) on a frame and a chain "a,b,c,d"; the
  // principal point is the middle of --image-size WxH.
  std::optional<double> focalPx;
  std::string imageSize;
  std::optional<int> scaleDepthFrame;
  std::string scaleDepthChain;
  // Bone lengths: "" (the reference's), reference, table2 (with statureM), eigenwalker
  // (scaled to statureM when given), frame (boneFrame and referenceBone "a-b=MM").
  std::string bones;
  std::optional<double> statureM;
  std::optional<int> boneFrame;
  std::string referenceBone;
  std::string guide;  // "" or eigenwalker
};

int runReconstructSkeleton(const SkeletonArgs& args);

}  // namespace ew::cli

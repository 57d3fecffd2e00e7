#include "app/cli/reconstruct_skeleton.h"

#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <nlohmann/json.hpp>

#include "core/camera/calibration_file.h"
#include "core/common/errors.h"
#include "core/common/statistics.h"
#include "core/gait/joint_angles.h"
#include "core/io/joint_csv.h"
#include "core/io/load_trial.h"
#include "core/io/trc_writer.h"
#include "core/keypoints/keypoint_trial.h"
#include "core/skeleton/skeleton_camera.h"

namespace ew::cli {
namespace {

using nlohmann::json;

void require(bool given, const char* option, const std::string& why) {
  if (!given) throw Error(ErrorKind::BadArgument, option, "", why);
}

JointTrial readReference(const std::string& file) {
  const JointTrial t = mapRawTrial(readRawTrial(file), {});
  for (int j = 0; j < kJointCount; ++j)
    if (t.missing[static_cast<size_t>(j)])
      throw Error(ErrorKind::BadData, file, "", "the reference lacks the " + std::string(jointName(static_cast<Joint>(j))) +
                                                    ": every bone length is needed");
  return t;
}

json comparisonJson(const ReferenceComparison& c) {
  json perJoint = json::object();
  for (int j = 0; j < kJointCount; ++j)
    perJoint[std::string(jointName(static_cast<Joint>(j)))] = c.perJointMm[static_cast<size_t>(j)];
  json axes = json::array();
  for (int r = 0; r < 3; ++r) axes.push_back({c.referenceToWorld(r, 0), c.referenceToWorld(r, 1), c.referenceToWorld(r, 2)});
  return {{"frames", c.frames}, {"mpjpe_raw_mm", c.rawMm}, {"mpjpe_mean_translation_mm", c.meanTranslationMm},
          {"mpjpe_procrustes_mm", c.procrustesMm}, {"per_joint_mm", perJoint}, {"reference_to_world", axes}};
}

// The result's up: in a calibration's world the axis nearest the body's head-above-ankles
// direction (SPEC §2's rule); in a camera's frame that direction itself (the camera may be tilted).
void writeAngles(const SkeletonArgs& a, const Eigen::MatrixXd& framesMm, double rateHz, bool world) {
  const Eigen::Vector3d up = bodyUp(framesMm, world ? 90.0 : 0.0);
  std::ostringstream upText;
  upText << up.transpose();
  writeJointAngles(a.angles, jointAngles(framesMm, up, a.out), rateHz,
                   {"source=skeleton engine (Zou et al. 2009) of " + a.input, "angles=degrees",
                    "up=" + upText.str() + " (the reconstruction's frame)"});
  std::cerr << "wrote " << a.angles << "\n";
}

}  // namespace

int runReconstructSkeleton(const SkeletonArgs& a) {
  require(!a.camera.empty(), "--camera",
          "the skeleton engine reconstructs through a calibrated pinhole camera: give --camera FILE (a "
          "Pose2Sim calibration); orthographic 2D views are scored by 'evaluate --experiment snippet --engine skeleton'");
  require(!a.reference.empty(), "--reference",
          "the skeleton engine needs the bone lengths: give --reference FILE, a 3D trial of the same person");
  KeypointOptions ko;
  if (!a.layout.empty()) ko.layout = a.layout;
  ko.fps = a.fps;
  const KeypointTrial keypoints = readKeypointTrial(a.input, ko);
  const CalibratedCamera camera =
      readCalibratedCamera(a.camera, a.cameraName.empty() ? std::nullopt : std::optional<std::string>(a.cameraName));
  const JointTrial reference = readReference(a.reference);
  if (a.fps && reference.rateHz > 0.0 && std::abs(reference.rateHz - *a.fps) > 1e-6 * *a.fps)
    throw Error(ErrorKind::BadArgument, a.reference, "--fps",
                "the reference is at " + std::to_string(reference.rateHz) + " Hz, the keypoints at --fps " +
                    std::to_string(*a.fps) + " Hz: frames would not correspond");
  const BoneLengths bones = boneLengthsFromFrames(reference.positionsMm, a.reference);
  const SkeletonCameraResult r = reconstructThroughCamera(keypoints.jointsPx, camera, bones, keypoints.rateHz, a.input);
  const bool world = camera.hasExtrinsics;
  writeJointTrajectories(a.out, world ? r.worldMm : r.sequence.framesMm, keypoints.rateHz,
                {"skeleton engine (Zou et al. 2009) of " + a.input + " through camera " + camera.name + " of " + a.camera,
                 world ? "frame: the calibration's world (mm)" : "frame: the camera's (x right, y down, z forward; mm)"});
  json report = {{"engine", "skeleton"}, {"input", a.input}, {"camera", camera.name}, {"frames", r.sequence.framesMm.rows()},
                 {"rate_hz", keypoints.rateHz}, {"clamped_bone_frames", r.sequence.clampedBoneFrames},
                 {"filled_points", r.filledPoints}, {"frame", world ? "world" : "camera"}};
  const double depthMm = median(r.rootDistanceMm);
  report["pelvis_distance_median_mm"] = depthMm;
  std::cerr << std::fixed << std::setprecision(1) << "skeleton: " << r.sequence.framesMm.rows() << " frames through "
            << camera.name << ", pelvis at " << depthMm << " mm (median), "
            << r.sequence.clampedBoneFrames << " clamped bone-frames, " << r.filledPoints << " joint-frames filled\n";
  if (world) {
    const ReferenceComparison c = compareWithReference(r.worldMm, reference.positionsMm, a.reference);
    report["reference"] = comparisonJson(c);
    std::cerr << "against " << a.reference << " (" << c.frames << " frames): MPJPE " << c.rawMm << " mm as is, "
              << c.meanTranslationMm << " mm without the mean translation, " << c.procrustesMm
              << " mm after Procrustes\n";
  } else {
    std::cerr << "no extrinsics in " << a.camera << ": the result stays in the camera's frame and is not scored\n";
  }
  std::cerr << "wrote " << a.out << "\n";
  if (!a.angles.empty()) writeAngles(a, world ? r.worldMm : r.sequence.framesMm, keypoints.rateHz, world);
  if (a.json) std::cout << report.dump(2) << "\n";
  return 0;
}

}  // namespace ew::cli

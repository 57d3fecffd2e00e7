// `eigenwalker-cli reconstruct --unknown-camera` on OpenPose JSON written here: the model's
// mean walker filmed by a pinhole camera (azimuth 40°, 12° down, 6 m, focal 1400 px), its
// keypoints placed as a detector would (sternum = the shoulders' midpoint, not the model's
// sternum: the reprojection is not exact). Measured: azimuth 39.6°, elevation 12.5°,
// distance 6.14 m, speed 1.31 m/s, reprojection RMS 3.1 px.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "core/camera/walk_camera.h"
#include "core/common/skeleton.h"
#include "core/engine/default_model.h"
#include "core/engine/fourier.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path filmedOpenPose(const std::string& stem) {
  WalkCamera c;
  c.model = CameraModel::Pinhole;
  c.alphaDeg = 40;
  c.elevationDeg = 12;
  c.focalPx = 1400;
  c.distanceMm = 6000;
  c.cxPx = 960;
  c.cyPx = 540;
  c.lookAtHeightMm = 900;
  c.speedMmS = 1300;
  c.startOffsetMm = -1300 * 2.5;
  const Eigen::VectorXd t = frameTimes(150, 30.0);
  const Eigen::MatrixXd px =
      projectWalk(synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * 0.95, 0.2, t), t, c);
  const fs::path dir = test::makeTempDir(stem);
  for (int f = 0; f < 150; ++f) {
    const auto p = [&](Joint j, double du = 0, double dv = 0) {
      return std::pair{px(f, 2 * index(j)) + du, px(f, 2 * index(j) + 1) + dv};
    };
    // BODY_25: face points around the head, feet around the ankles.
    const std::vector<std::pair<double, double>> points = {
        p(Joint::Head, 0, 8), p(Joint::Sternum), p(Joint::RShoulder), p(Joint::RElbow), p(Joint::RWrist),
        p(Joint::LShoulder), p(Joint::LElbow), p(Joint::LWrist), p(Joint::Pelvis), p(Joint::RHip),
        p(Joint::RKnee), p(Joint::RAnkle), p(Joint::LHip), p(Joint::LKnee), p(Joint::LAnkle),
        p(Joint::Head, -3, -4), p(Joint::Head, 3, -4), p(Joint::Head, -6, 0), p(Joint::Head, 6, 0),
        p(Joint::LAnkle, 5, 10), p(Joint::LAnkle, 7, 10), p(Joint::LAnkle, -3, 8), p(Joint::RAnkle, 5, 10),
        p(Joint::RAnkle, 7, 10), p(Joint::RAnkle, -3, 8)};
    json flat = json::array();
    for (const auto& [u, v] : points) flat.insert(flat.end(), {u, v, 0.9});
    char name[64];
    std::snprintf(name, sizeof name, "walk_%06d_keypoints.json", f);
    std::ofstream(dir / name) << json{{"people", {{{"pose_keypoints_2d", flat}}}}}.dump();
  }
  return dir;
}

TEST(ReconstructCameraCli, OpenPoseFolderThroughAKnownFocalLength) {
  const fs::path clip = filmedOpenPose("camera_cli");
  const fs::path out = clip.parent_path() / "camera_cli_walk3d.csv";
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                     "--focal-px", "1400", "--out", out.string(), "--json"},
                                    test::makeTempDir("camera_cli_run"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const auto begin = run.output.find("{\n");
  ASSERT_NE(begin, std::string::npos) << run.output;
  const json r = json::parse(run.output.substr(begin));
  EXPECT_EQ(r["camera_model"], "pinhole");
  EXPECT_EQ(r["layout"], "BODY_25");
  EXPECT_NEAR(r["alpha_deg"].get<double>(), 40, 2.0);
  EXPECT_NEAR(r["elevation_deg"].get<double>(), 12, 2.0);
  EXPECT_NEAR(r["distance_m"].get<double>(), 6.0, 0.05 * 6.0);
  EXPECT_NEAR(r["speed_mps"].get<double>(), 1.3, 0.05 * 1.3);
  EXPECT_NEAR(r["stride_hz"].get<double>(), 0.95, 0.01);
  EXPECT_LT(r["reprojection_rms_px"].get<double>(), 6.0);
  // One row per input frame, after the header and comment lines.
  std::ifstream csv(out);
  int rows = 0;
  for (std::string line; std::getline(csv, line);) rows += !line.empty() && line[0] != '#' && line[0] != 'f';
  EXPECT_EQ(rows, 150);
}

// Nothing known but the frame rate: the focal length is estimated too. Measured: 1405 px,
// distance 6.17 m, azimuth 39.5°, RMS 3.1 px.
TEST(ReconstructCameraCli, OpenPoseFolderWithTheFocalLengthUnknown) {
  const fs::path clip = filmedOpenPose("camera_cli_f");
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                     "--out", (clip.parent_path() / "camera_cli_f.csv").string(), "--json"},
                                    test::makeTempDir("camera_cli_f_run"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const json r = json::parse(run.output.substr(run.output.find("{\n")));
  EXPECT_EQ(r["focal_source"], "estimated");
  EXPECT_NEAR(r["focal_px"].get<double>(), 1400, 0.05 * 1400);
  EXPECT_NEAR(r["distance_m"].get<double>(), 6.0, 0.05 * 6.0);
  EXPECT_NEAR(r["alpha_deg"].get<double>(), 40, 2.0);
}

TEST(ReconstructCameraCli, AngleOptionsDoNotApply) {
  const fs::path clip = filmedOpenPose("camera_cli_bad");
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--angle", "30",
                                     "--out", (clip.parent_path() / "x.csv").string()},
                                    test::makeTempDir("camera_cli_bad_run"));
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("the camera's angle is estimated"), std::string::npos) << run.output;
}

}  // namespace
}  // namespace ew

// `eigenwalker-cli reconstruct --unknown-camera` on OpenPose JSON written here: the model's
// mean walker filmed by a pinhole camera (azimuth 40°, 12° down, 6 m, focal 1400 px), its
// keypoints placed as a detector would (sternum = the shoulders' midpoint, not the model's
// sternum, which the fit allows for: docs/KEYPOINTS.md, "The sternum"). Measured: azimuth 40.0°,
// elevation 12.4°, distance 6.00 m, speed 1.30 m/s, reprojection RMS 0.50 px (before the sternum
// was allowed for: 39.6°, 12.5°, 6.14 m, 1.31 m/s, 3.1 px).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <string>

#include "core/camera/walk_camera.h"
#include "tests/camera/filmed_walk.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

fs::path filmedOpenPose(const std::string& stem) {
  const fs::path dir = test::makeTempDir(stem);
  test::writeFilmedOpenPose(dir, test::crossingPinhole(1400, 5.0), 150, 30.0);
  return dir;
}

TEST(ReconstructCameraCli, OpenPoseFolderThroughAKnownFocalLength) {
  const fs::path clip = filmedOpenPose("camera_cli");
  const fs::path out = test::makeTempDir("out") / "camera_cli_walk3d.csv";
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
  EXPECT_FALSE(r["walking_in_place"].get<bool>());
  // One row per input frame, after the header and comment lines.
  std::ifstream csv(out);
  int rows = 0;
  for (std::string line; std::getline(csv, line);) rows += !line.empty() && line[0] != '#' && line[0] != 'f';
  EXPECT_EQ(rows, 150);
}

// A C3D output holds the heels and toes lifted from the clip (BODY_25 has them: the writer puts
// them beside the ankles) and the events they give; `gait` reads them back. Seen from 75°, every
// ray meets the ankles' sagittal planes steeply enough (from 40° the ends of the walk do not).
TEST(ReconstructCameraCli, AC3dOutputCarriesTheLiftedFeet) {
  const fs::path clip = test::makeTempDir("camera_cli_feet");
  WalkCamera camera = test::crossingPinhole(1400, 5.0);
  camera.alphaDeg = 75;
  test::writeFilmedOpenPose(clip, camera, 150, 30.0);
  const fs::path out = test::makeTempDir("out_feet") / "walk3d.c3d";
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                     "--out", out.string(), "--json"},
                                    test::makeTempDir("camera_cli_feet_run"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const json r = json::parse(run.output.substr(run.output.find("{\n")));
  EXPECT_TRUE(r["feet"]["written"].get<bool>()) << r["feet"];
  EXPECT_EQ(r["feet"]["samples_lifted"], r["feet"]["samples_seen"]) << r["feet"];
  EXPECT_EQ(r["feet"]["samples_seen"].get<int>(), 150 * 4);
  EXPECT_TRUE(r["detector_offsets_mm"].contains("sternum")) << r["detector_offsets_mm"];
  const auto gait = test::runProgram(EW_CLI_PATH, {"gait", out.string(), "--events", "kinematics", "--json"},
                                     test::makeTempDir("camera_cli_feet_gait"));
  ASSERT_EQ(gait.exitCode, 0) << gait.output;
  const json g = json::parse(gait.output.substr(gait.output.find('[')))[0];
  EXPECT_EQ(g["events"], "kinematics (heel and toe)");
  // Lifted onto the ankles' sagittal planes, the feet give no foot progression, and say why.
  EXPECT_EQ(g["foot_progression_r_deg"], "nan");
  EXPECT_NE(g["notes"].get<std::string>().find("no foot progression"), std::string::npos) << g["notes"];
  EXPECT_NEAR(std::stod(g["cadence_spm"].get<std::string>()), 120.0 * test::kFilmedStrideHz, 3.0);
}

// `reconstruct --unknown-camera --focal-px 1400 --json` of an OpenPose folder, with `extra`
// arguments: its exit status and printed report.
test::ProgramRun reconstructAt1400Px(const fs::path& clip, const std::vector<std::string>& extra = {}) {
  std::vector<std::string> args{"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                "--focal-px", "1400", "--out", (test::makeTempDir("out") / "walk3d.csv").string(),
                                "--json"};
  args.insert(args.end(), extra.begin(), extra.end());
  return test::runProgram(EW_CLI_PATH, args, test::makeTempDir("run"));
}

json reportOf(const test::ProgramRun& run) { return json::parse(run.output.substr(run.output.find("{\n"))); }

// The walker's stature given: the same image, a walker scaled to it, and the camera's distance
// and the walk's speed with it (core/camera/known_stature.h).
TEST(ReconstructCameraCli, AGivenStatureScalesTheFitNotTheImage) {
  const fs::path clip = filmedOpenPose("camera_cli_stature");
  const json free = reportOf(reconstructAt1400Px(clip));
  const test::ProgramRun run = reconstructAt1400Px(clip, {"--stature", "1.95"});
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const json given = reportOf(run);
  EXPECT_NEAR(given["stature_m"].get<double>(), 1.95, 1e-9);
  EXPECT_EQ(given["stature_source"], "given (--stature)");
  EXPECT_EQ(free["stature_source"], "the model's prior");
  const double s = 1.95 / free["stature_m"].get<double>();
  EXPECT_NEAR(given["distance_m"].get<double>(), s * free["distance_m"].get<double>(), 1e-6);
  EXPECT_NEAR(given["speed_mps"].get<double>(), s * free["speed_mps"].get<double>(), 1e-6);
  EXPECT_NEAR(given["stride_length_m"].get<double>(), s * free["stride_length_m"].get<double>(), 1e-6);
  EXPECT_NEAR(given["alpha_deg"].get<double>(), free["alpha_deg"].get<double>(), 1e-9);
  EXPECT_NEAR(given["view_elevation_deg"].get<double>(), free["view_elevation_deg"].get<double>(), 1e-9);
  EXPECT_NEAR(given["reprojection_rms_px"].get<double>(), free["reprojection_rms_px"].get<double>(), 1e-9);
  // The scale no longer open: the stature is sure, and the stride and the speed surer than they
  // were (the fit's SDs conditioned on the stature), as shares of their values: measured 5.0 %
  // given against 5.6 % free for both (the fit's SDs are mostly the data's here).
  EXPECT_EQ(given["stature_sd_m"].get<double>(), 0.0);
  EXPECT_GT(free["stature_sd_m"].get<double>(), 0.01 * free["stature_m"].get<double>());
  const auto share = [](const json& r, const char* sd, const char* value) {
    return r[sd].get<double>() / r[value].get<double>();
  };
  EXPECT_LT(share(given, "stride_length_sd_m", "stride_length_m"), 0.95 * share(free, "stride_length_sd_m", "stride_length_m"));
  EXPECT_LT(share(given, "speed_sd_mps", "speed_mps"), 0.95 * share(free, "speed_sd_mps", "speed_mps"));
  EXPECT_GT(given["stride_length_sd_m"].get<double>(), 0.0);
  // The walker's distance scales with it and, its focal length given, rests on the walker's
  // size: given the stature, it is far surer.
  EXPECT_NEAR(given["walker_distance_m"].get<double>(), s * free["walker_distance_m"].get<double>(), 1e-6);
  EXPECT_LT(share(given, "walker_distance_sd_m", "walker_distance_m"),
            0.5 * share(free, "walker_distance_sd_m", "walker_distance_m"));
  EXPECT_EQ(free["focal_sd_px"].get<double>(), 0.0);  // given
  EXPECT_GT(free["alpha_sd_deg"].get<double>(), 0.0);
  EXPECT_NE(run.output.find("(stature about 1.95 m)"), std::string::npos) << run.output;  // no ± when given
  EXPECT_NE(run.output.find(" m away (mean "), std::string::npos) << run.output;
  const test::ProgramRun wrong = reconstructAt1400Px(clip, {"--stature", "175"});  // cm for m
  EXPECT_NE(wrong.exitCode, 0);
  EXPECT_NE(wrong.output.find("--stature"), std::string::npos) << wrong.output;
}

// The same walker on a treadmill: fitted walking in place, its speed the belt's (stance feet).
TEST(ReconstructCameraCli, ATreadmillWalkerIsFittedInPlace) {
  const fs::path clip = test::makeTempDir("camera_cli_treadmill");
  WalkCamera camera = test::crossingPinhole(1400, 5.0);
  camera.speedMmS = camera.startOffsetMm = 0.0;
  test::writeFilmedOpenPose(clip, camera, 150, 30.0);
  const auto run = reconstructAt1400Px(clip);
  ASSERT_EQ(run.exitCode, 0) << run.output;
  EXPECT_NE(run.output.find("walking in place (a treadmill), belt speed"), std::string::npos) << run.output;
  const json r = reportOf(run);
  EXPECT_TRUE(r["walking_in_place"].get<bool>());
  EXPECT_NE(r["speed_source"].get<std::string>().find("stance feet"), std::string::npos);
  EXPECT_NEAR(r["alpha_deg"].get<double>(), 40, 3.0);
  EXPECT_NEAR(r["speed_mps"].get<double>(), 1.25, 0.15);  // the mean walker's stance feet
  // Looking down 12° (fitted about 10°) at 40° off the side: no caution asked for, whatever the
  // fitted elevation says, when the azimuth is given.
  const auto given = reconstructAt1400Px(clip, {"--angle", "40"});
  ASSERT_EQ(given.exitCode, 0) << given.output;
  EXPECT_EQ(reportOf(given)["cautions"], json::array());

  // The same walker in place filmed by a level camera: the azimuth is said to be weak.
  const fs::path level = test::makeTempDir("camera_cli_treadmill_level");
  camera.elevationDeg = 0.0;
  test::writeFilmedOpenPose(level, camera, 150, 30.0);
  const auto weak = reconstructAt1400Px(level);
  ASSERT_EQ(weak.exitCode, 0) << weak.output;
  EXPECT_NE(weak.output.find("caution: walking in place, seen from the side or obliquely by a level camera"),
            std::string::npos)
      << weak.output;
  const json cautions = reportOf(weak)["cautions"];
  ASSERT_EQ(cautions.size(), 1u) << cautions;
  EXPECT_NE(cautions[0].get<std::string>().find("may be tens of degrees off"), std::string::npos);
}

// Nothing known but the frame rate: the focal length is estimated too. Measured: 1405 px,
// distance 6.17 m, azimuth 39.5°, RMS 3.1 px.
TEST(ReconstructCameraCli, OpenPoseFolderWithTheFocalLengthUnknown) {
  const fs::path clip = filmedOpenPose("camera_cli_f");
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                     "--out", (test::makeTempDir("out") / "camera_cli_f.csv").string(), "--json"},
                                    test::makeTempDir("camera_cli_f_run"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const json r = json::parse(run.output.substr(run.output.find("{\n")));
  EXPECT_EQ(r["focal_source"], "estimated");
  EXPECT_NEAR(r["focal_px"].get<double>(), 1400, 0.05 * 1400);
  EXPECT_NEAR(r["distance_m"].get<double>(), 6.0, 0.05 * 6.0);
  EXPECT_NEAR(r["alpha_deg"].get<double>(), 40, 2.0);
  // An OpenPose folder has no size: the principal point's row is held near the walker's.
  EXPECT_EQ(r["principal_point_prior"].get<std::string>().rfind("the walker's row", 0), 0u);
  EXPECT_TRUE(r["scene_horizon"].is_null()) << "keypoints alone show no scene to read a horizon from";
  // Given the video's size, the principal point is expected at its centre (where the camera's
  // is): the same camera comes out.
  const auto sized = test::runProgram(EW_CLI_PATH,
                                      {"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                       "--image-size", "1920x1080", "--out",
                                       (test::makeTempDir("out") / "camera_cli_f_sized.csv").string(), "--json"},
                                      test::makeTempDir("camera_cli_f_sized_run"));
  ASSERT_EQ(sized.exitCode, 0) << sized.output;
  const json s = json::parse(sized.output.substr(sized.output.find("{\n")));
  EXPECT_EQ(s["principal_point_prior"], "the image's centre");
  EXPECT_NEAR(s["focal_px"].get<double>(), 1400, 0.05 * 1400);
  EXPECT_NEAR(s["alpha_deg"].get<double>(), 40, 2.0);
  EXPECT_NEAR(s["image_centre_px"][1].get<double>(), 540, 0.05 * 1080);
}

TEST(ReconstructCameraCli, UnknownAngleAndProjectAngleDoNotApply) {
  const fs::path clip = filmedOpenPose("camera_cli_bad");
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--unknown-angle",
                                     "--out", (test::makeTempDir("out") / "x.csv").string()},
                                    test::makeTempDir("camera_cli_bad_run"));
  EXPECT_NE(run.exitCode, 0);
  EXPECT_NE(run.output.find("the camera's azimuth is estimated"), std::string::npos) << run.output;
}

// A pose estimator's keypoints are pixels through a camera: without --unknown-camera they still
// go that way, and --angle holds the camera's azimuth (before, the folder was read as a 3D trial
// and refused for wanting --project-angle).
TEST(ReconstructCameraCli, KeypointsGoThroughTheCameraWithoutBeingToldSo) {
  const fs::path clip = filmedOpenPose("camera_cli_implied");
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--fps", "30", "--angle", "40", "--out",
                                     (test::makeTempDir("out") / "implied.csv").string(), "--json"},
                                    test::makeTempDir("camera_cli_implied_run"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const json r = json::parse(run.output.substr(run.output.find("{\n")));
  EXPECT_EQ(r["camera_model"], "pinhole");
  EXPECT_EQ(r["alpha_source"], "given (--angle)");
  EXPECT_NEAR(r["elevation_deg"].get<double>(), 12, 2.0);
}

// --angle and --elevation hold the azimuth and elevation (the viewer's "fix" controls); the
// JSON says they were given.
TEST(ReconstructCameraCli, KnownAzimuthAndElevationAreHeld) {
  const fs::path clip = filmedOpenPose("camera_cli_fixed");
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                     "--angle", "40", "--elevation", "12", "--out",
                                     (test::makeTempDir("out") / "camera_cli_fixed.csv").string(), "--json"},
                                    test::makeTempDir("camera_cli_fixed_run"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const json r = json::parse(run.output.substr(run.output.find("{\n")));
  EXPECT_EQ(r["alpha_deg"].get<double>(), 40.0);
  EXPECT_EQ(r["elevation_deg"].get<double>(), 12.0);
  EXPECT_EQ(r["elevation_source"], "given (--elevation)");
  EXPECT_NEAR(r["distance_m"].get<double>(), 6.0, 0.05 * 6.0);
  EXPECT_LT(r["reprojection_rms_px"].get<double>(), 6.0);
}

// A calibration file gives the focal length (--camera, --camera-name): the fit is the one
// with --focal-px, and the JSON says where the focal length came from.
TEST(ReconstructCameraCli, CalibrationFileGivesTheFocalLength) {
  const fs::path clip = filmedOpenPose("camera_cli_calib");
  const fs::path calib = test::makeTempDir("out") / "Calib_test.toml";
  std::ofstream(calib) << "[cam_01]\nname = \"side\"\nsize = [1920, 1080]\n"
                          "matrix = [[1400, 0, 960], [0, 1400, 540], [0, 0, 1]]\n"
                          "[cam_02]\nmatrix = [[900, 0, 960], [0, 900, 540], [0, 0, 1]]\n[metadata]\nerror = 0.0\n";
  const fs::path out = test::makeTempDir("out") / "camera_cli_calib.csv";
  const auto run = test::runProgram(EW_CLI_PATH,
                                    {"reconstruct", "--input", clip.string(), "--unknown-camera", "--fps", "30",
                                     "--camera", calib.string(), "--camera-name", "side", "--out", out.string(), "--json"},
                                    test::makeTempDir("camera_cli_calib_run"));
  ASSERT_EQ(run.exitCode, 0) << run.output;
  const json r = json::parse(run.output.substr(run.output.find("{\n")));
  EXPECT_EQ(r["focal_px"].get<double>(), 1400.0);
  EXPECT_EQ(r["focal_source"], "calibration file (side)");
  EXPECT_EQ(r["principal_point_prior"], "the calibration's");
  EXPECT_NEAR(r["distance_m"].get<double>(), 6.0, 0.05 * 6.0);
  // Several cameras and no name, or a focal length twice: refused, naming the choice.
  const auto which = test::runProgram(EW_CLI_PATH,
                                      {"reconstruct", "--input", clip.string(), "--unknown-camera", "--camera",
                                       calib.string(), "--out", out.string()},
                                      test::makeTempDir("camera_cli_calib_which"));
  EXPECT_NE(which.exitCode, 0);
  EXPECT_NE(which.output.find("side, cam_02"), std::string::npos) << which.output;
  const auto twice = test::runProgram(EW_CLI_PATH,
                                      {"reconstruct", "--input", clip.string(), "--unknown-camera", "--camera",
                                       calib.string(), "--camera-name", "side", "--focal-px", "1400", "--out",
                                       out.string()},
                                      test::makeTempDir("camera_cli_calib_twice"));
  EXPECT_NE(twice.exitCode, 0);
  EXPECT_NE(twice.output.find("not both"), std::string::npos) << twice.output;
}

// Issue 53's reproducers on the shared cam01 keypoints: a Pose2Sim-style calibration whose
// focal lengths are 5e-324 px (undistortion dropped all 2519 points, then a SIGSEGV in the
// gait cycles) or 1e308 px (reported as "focal inf px"), and --focal-px 1e308. Each is refused
// naming where the number came from and the rule (core/camera/focal_length.h).
TEST(ReconstructCameraCli, AFocalLengthNoCameraHasIsRefusedNamingItsSource) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path cam01 = test::sharedDataDir() / "pose2sim-balancing" / "pose" / "cam01_json";
  const fs::path dir = test::makeTempDir("camera_cli_focal");
  for (const std::string focal : {"5e-324", "1e308"}) {
    const fs::path calib = dir / ("Calib_" + focal + ".toml");
    std::ofstream(calib) << "[cam_01]\nname = \"cam_01\"\nsize = [ 1088.0, 1920.0]\nmatrix = [[" << focal
                         << ", 0, 960], [0, " << focal << ", 540], [0, 0, 1]]\n"
                         << "distortions = [ -0.0007, 0.0022, 9.5e-06, 1.1e-05]\n";
    const auto run = test::runProgram(EW_CLI_PATH,
                                      {"reconstruct", "--input", cam01.string(), "--unknown-camera", "--camera",
                                       calib.string(), "--out", (dir / "walk3d.csv").string()},
                                      dir);
    EXPECT_EQ(run.exitCode, 1) << run.output;
    EXPECT_NE(run.output.find(calib.string() + ": line 4: [cam_01] matrix: focal length"), std::string::npos)
        << run.output;
    EXPECT_NE(run.output.find("finite and 50-100000 px"), std::string::npos) << run.output;
  }
  const auto given = test::runProgram(EW_CLI_PATH,
                                      {"reconstruct", "--input", cam01.string(), "--unknown-camera", "--focal-px",
                                       "1e308", "--out", (dir / "walk3d.csv").string()},
                                      dir);
  EXPECT_EQ(given.exitCode, 2) << given.output;
  EXPECT_NE(given.output.find("--focal-px"), std::string::npos) << given.output;
  EXPECT_NE(given.output.find("focal length 1e+308 px"), std::string::npos) << given.output;
  EXPECT_EQ(given.output.find("focal inf"), std::string::npos) << given.output;
  EXPECT_FALSE(fs::exists(dir / "walk3d.csv"));
  // Not numbers at all, refused as the options are read (app/cli/checks.h): CLI11's own checks
  // let NaN through and worded an infinity with a 309-digit bound.
  const std::vector<std::pair<std::vector<std::string>, std::string>> notNumbers = {
      {{"--focal-px", "inf"}, "--focal-px: Value inf is not a positive finite number"},
      {{"--fps", "nan"}, "--fps: Value nan is not a positive finite number"},
      {{"--elevation", "nan"}, "--elevation: Value nan is not a number from -30 to 80"},
      {{"--angle", "nan"}, "--angle: Value nan is not a finite number"},
  };
  for (const auto& [option, said] : notNumbers) {
    std::vector<std::string> args = {"reconstruct", "--input", cam01.string(), "--out", (dir / "walk3d.csv").string()};
    args.insert(args.end(), option.begin(), option.end());
    const auto run = test::runProgram(EW_CLI_PATH, args, dir);
    EXPECT_EQ(run.exitCode, 2) << run.output;
    EXPECT_NE(run.output.find(said), std::string::npos) << run.output;
  }
}

}  // namespace
}  // namespace ew

// `eigenwalker-cli detect` and a video where the commands take keypoints (`reconstruct
// --input V.mp4`, `info V.mp4`) end to end on the shared footage (issue 52), and their errors
// for a video with nobody, a file that is no video and missing models.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include <nlohmann/json.hpp>
#include <opencv2/videoio.hpp>

#include "core/keypoints/keypoint_frames.h"
#include "tests/common/test_support.h"
#include "tests/video/pose_models.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;
using test::runCli;

json jsonAfter(const std::string& out) { return json::parse(out.substr(out.find('{'))); }

fs::path sharedVideo(const std::string& relative) { return fs::absolute(test::sharedDataDir() / relative); }

TEST(DetectCli, WritesTheWalkerAsMediaPipeCsvAndMeasuresItAgainstOpenPose) {
  EW_REQUIRE_SHARED_DATA();
  EW_REQUIRE_POSE_MODELS();
  test::useOwnDetectionCache();
  const fs::path dir = test::makeTempDir("detect_cli");
  const fs::path trial = sharedVideo("pose2sim-balancing");
  const std::string args = "detect --video " + (trial / "videos/cam02.mp4").string() + " --last 29 --out out --compare " +
                           (trial / "pose/cam02_json").string() + " --compare-offset 1 --json";
  const test::ShellRun r = runCli(args, dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json report = jsonAfter(r.out);
  EXPECT_EQ(report["frames"], 30);
  EXPECT_EQ(report["people_followed"], 1);
  EXPECT_EQ(report["from_cache"], false);
  EXPECT_LT(report["compare"]["limbs"]["median_px"].get<double>(), 15.0);
  EXPECT_EQ(report["compare"]["left_right"]["frames_swapped"], 0);
  EXPECT_EQ(jsonAfter(test::readTextFile(dir / "out" / "detect.json")), report);
  const KeypointFrames back = readKeypointCsv(dir / "out" / "keypoints.csv");
  EXPECT_EQ(back.frameCount(), 30);
  ASSERT_TRUE(back.imageSize.has_value());
  EXPECT_EQ(back.imageSize->height, 1920);
  // The second run comes from the cache, the same points.
  const test::ShellRun again = runCli(args + " --format openpose", dir);
  ASSERT_EQ(again.exitCode, 0) << again.err;
  EXPECT_EQ(jsonAfter(again.out)["from_cache"], true);
  EXPECT_EQ(jsonAfter(again.out)["compare"]["limbs"], report["compare"]["limbs"]);
  EXPECT_EQ(readKeypointFrames(dir / "out" / "keypoints").frameCount(), 30);
}

// The bar on the real walking video, everything unknown: a stature of 1.55-1.75 m, a
// stride frequency of 0.7-1.3 Hz, a profile view within 15 degrees, the woman who walks chosen.
TEST(DetectCli, TheWalkingVideoBecomesAWalkerWithNoOtherTool) {
  EW_REQUIRE_SHARED_DATA();
  EW_REQUIRE_POSE_MODELS();
  // Under ctest the detections come from GuiDetect's fixture (tests/video/pose_models.h); the
  // detector's own run is tested there and in the test above.
  test::seedDetectionCache(test::useOwnDetectionCache());
  const fs::path dir = test::makeTempDir("reconstruct_video");
  const fs::path video = sharedVideo("video/sports2d-demo/demo.mp4");
  const test::ShellRun r = runCli("reconstruct --input " + video.string() + " --out walk3d.csv --json", dir);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json report = jsonAfter(r.out);
  EXPECT_GE(report["stature_m"].get<double>(), 1.55);
  EXPECT_LE(report["stature_m"].get<double>(), 1.75);
  EXPECT_GE(report["stride_hz"].get<double>(), 0.7);
  EXPECT_LE(report["stride_hz"].get<double>(), 1.3);
  EXPECT_LT(std::abs(std::abs(report["alpha_deg"].get<double>()) - 90.0), 15.0);
  EXPECT_NE(report["format"].get<std::string>().find("BlazePose"), std::string::npos);
  EXPECT_TRUE(fs::exists(dir / "walk3d.csv"));
  // Nothing to warn of: the video's own frame rate is no news.
  EXPECT_EQ(report["warnings"], json::array()) << report["warnings"];
  EXPECT_EQ(r.err.find("warning:"), std::string::npos) << r.err;
  // The scene's horizon: its window rows put it at 563–570 px, a camera 1.45 m up that sees her
  // pelvis 3.4–3.8° from above (docs/CAMERA.md, "The scene's horizon"). Held to it, the fit's
  // camera is 1.2° off it and sees her pelvis 2.4° from above; alone, 4.7° off, its eye near her
  // knees (0.65° from below), and it says so.
  const json& horizon = report["scene_horizon"];
  ASSERT_TRUE(horizon["row_px"].is_number()) << horizon.dump();
  EXPECT_NEAR(horizon["row_px"].get<double>(), 566.0, 10.0);
  EXPECT_TRUE(horizon["used_as_prior"].get<bool>());
  const double cy = report["image_centre_px"][1].get<double>(), f = report["focal_px"].get<double>();
  EXPECT_NEAR(horizon["fit_off_deg"].get<double>(),
              std::atan((cy - horizon["row_px"].get<double>()) / f) * 180.0 / std::numbers::pi -
                  report["elevation_deg"].get<double>(), 1e-9);
  EXPECT_LT(std::abs(horizon["fit_off_deg"].get<double>()), 2.0);
  EXPECT_GT(report["view_elevation_deg"].get<double>(), 1.5);
  EXPECT_EQ(r.err.find("caution: the scene's level lines"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("scene: its level lines put the horizon at row"), std::string::npos) << r.err;
  const test::ShellRun alone =
      runCli("reconstruct --input " + video.string() + " --out alone.csv --json --scene-horizon check", dir);
  ASSERT_EQ(alone.exitCode, 0) << alone.err;
  const json aloneReport = jsonAfter(alone.out);
  EXPECT_FALSE(aloneReport["scene_horizon"]["used_as_prior"].get<bool>());
  EXPECT_GT(aloneReport["scene_horizon"]["fit_off_deg"].get<double>(), 2.0);
  EXPECT_LT(aloneReport["view_elevation_deg"].get<double>(), report["view_elevation_deg"].get<double>() - 1.0);
  EXPECT_NE(alone.err.find("caution: the scene's level lines"), std::string::npos) << alone.err;
  // info on the same video: from the cache, the walker and her stride.
  const test::ShellRun info = runCli("info --json " + video.string(), dir);
  ASSERT_EQ(info.exitCode, 0) << info.err;
  EXPECT_NE(info.err.find("from the cache"), std::string::npos) << info.err;
  const json summary = json::parse(info.out.substr(info.out.find('[')))[0];
  EXPECT_GT(summary["frames"].get<int>(), 200);
  // gait on the video: her measures, from the same detections.
  const test::ShellRun gait = runCli("gait --json " + video.string(), dir);
  ASSERT_EQ(gait.exitCode, 0) << gait.err;
  const json measures = json::parse(gait.out.substr(gait.out.find('[')))[0];
  EXPECT_NEAR(std::stod(measures["cadence_spm"].get<std::string>()), 60.0 * 2.0 * report["stride_hz"].get<double>(), 10.0);
  // Her heels and foot indices, lifted from the image (core/camera/lifted_feet.h), give the
  // events and the ankle curve; the strides are those of the frames she is seen in (5.1 s at
  // 0.81 Hz: 4 a side, not the 6 a side of the whole 7.7 s clip); no foot progression is claimed.
  EXPECT_GT(report["feet"]["samples_lifted"].get<int>(), 0.9 * report["feet"]["samples_seen"].get<int>());
  EXPECT_EQ(measures["events"], "kinematics (heel and toe)");
  EXPECT_LE(std::stoi(measures["strides"].get<std::string>()), 8);
  EXPECT_EQ(measures["foot_progression_r_deg"], "nan");
  const double stance = std::stod(measures["stance_pct"].get<std::string>());
  EXPECT_GT(stance, 55.0);  // adults walk with 58-65 % stance (Perry & Burnfield)
  EXPECT_LT(stance, 68.0);
  EXPECT_GT(std::stod(measures["ankle_flexion_range_deg"].get<std::string>()), 15.0);
  // The camera fit's SDs come with the measures it rests on (measured: 0.045 m/s, 0.057 m).
  EXPECT_NEAR(std::stod(measures["speed_sd_mps"].get<std::string>()), report["speed_sd_mps"].get<double>(), 1e-3);
  EXPECT_NEAR(std::stod(measures["stride_length_sd_m"].get<std::string>()), report["stride_length_sd_m"].get<double>(),
              1e-4);
  EXPECT_GT(std::stod(measures["stride_length_sd_m"].get<std::string>()), 0.0);
}

TEST(DetectCli, VideosItCannotUseAreClearErrors) {
  EW_REQUIRE_POSE_MODELS();
  test::useOwnDetectionCache();
  const fs::path dir = test::makeTempDir("detect_errors");
  test::writeBinaryFile(dir / "broken.mp4", std::string(5000, '\x07'));
  test::ShellRun r = runCli("detect --video broken.mp4 --out o", dir);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("broken.mp4"), std::string::npos) << r.err;
  r = runCli("reconstruct --input broken.mp4 --out w.csv", dir);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("broken.mp4"), std::string::npos) << r.err;
  // Nobody in it: said, not a crash.
  {
    cv::VideoWriter w((dir / "nobody.avi").string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, {160, 120});
    for (int f = 0; f < 8; ++f) w.write(cv::Mat(120, 160, CV_8UC3, cv::Scalar(40, 80, 120)));
  }
  r = runCli("detect --video nobody.avi --out o", dir);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("nobody"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "o" / "keypoints.csv"));
  // Cut short (a copy that did not finish): the error says so, not only "nobody" (once the
  // reason was lost and a damaged video read as an empty one).
  {
    cv::VideoWriter w((dir / "whole.avi").string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, {160, 120});
    for (int f = 0; f < 24; ++f) w.write(cv::Mat(120, 160, CV_8UC3, cv::Scalar(40, 80, 120 + f)));
  }
  const std::string whole = test::readTextFile(dir / "whole.avi");
  test::writeBinaryFile(dir / "cut.avi", whole.substr(0, whole.size() / 2));
  r = runCli("reconstruct --input cut.avi --out w.csv", dir);
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("nobody to follow; the video ends early: "), std::string::npos) << r.err;
  EXPECT_NE(r.err.find(" of 24 frames decode"), std::string::npos) << r.err;
  EXPECT_FALSE(fs::exists(dir / "w.csv"));
  // Without the models: the command that fetches them.
  const test::ShellRun missing = test::runShell("cd \"" + dir.string() + "\" && EIGENWALKER_MODELS=\"" + dir.string() +
                                                    "\" \"" + EW_CLI_PATH + "\" detect --video nobody.avi --out o3 --no-cache",
                                                dir);
  EXPECT_EQ(missing.exitCode, 1) << missing.err;
  EXPECT_NE(missing.err.find("tools/pose_model/fetch_model.sh"), std::string::npos) << missing.err;
}

}  // namespace
}  // namespace ew

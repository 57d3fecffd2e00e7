// A video in the viewer with the built-in detector (issue 52, "Viewer"): opening a video hands
// it to the detector in the background, the people found are drawn over the footage as they
// come, and the walker's keypoints are fitted through the unknown camera as a pose estimator's
// clip is, with the footage under the fit. Without the models the viewer says which command
// fetches them; a video with nobody in it is said so, never a crash.

#include <gtest/gtest.h>

#include <cmath>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>

#include "tests/gui/gui_run.h"
#include "tests/gui/layout_checks.h"
#include "tests/video/pose_models.h"

namespace ew::test::gui {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

class GuiDetect : public GuiTest {
 protected:
  json state(const std::string& name) const { return json::parse(readAll(dir / name)); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
  // The viewer with its detection cache in the test's folder: every run detects afresh.
  RunResult run(const json& script, const std::string& size = "1600x900", const std::string& env = "") {
    const auto file = writeScript(dir, script.dump(2));
    return runViewer(dir, "--size " + size + " --script " + quote(file.string()),
                     std::string(kNoSettings) + " EIGENWALKER_CACHE=" + quote((dir / "cache").string()) + " " + env);
  }
  // A short clip with nobody in it: grey noise, 320×240 at 25 fps.
  fs::path writeEmptyVideo() const {
    const fs::path video = dir / "nobody.avi";
    cv::VideoWriter w(video.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, cv::Size(320, 240));
    EXPECT_TRUE(w.isOpened());
    cv::Mat frame(240, 320, CV_8UC3);
    cv::RNG rng(7);
    for (int i = 0; i < 12; ++i) {
      rng.fill(frame, cv::RNG::UNIFORM, cv::Scalar::all(90), cv::Scalar::all(140));
      w.write(frame);
    }
    return video;
  }
};

// Issue 52's "Must show": demo.mp4 from file to walker in the viewer, with everything unknown.
TEST_F(GuiDetect, DetectsTheSports2dWalkerAndFitsHerOverTheFootage) {
  EW_REQUIRE_SHARED_DATA();
  EW_REQUIRE_POSE_MODELS();
  const fs::path video = sharedDataDir() / "video" / "sports2d-demo" / "demo.mp4";
  const RunResult r = run(json::array({
      {{"detect_video", video.string()}},
      {{"wait_frames", 3}},
      {{"export_state", path("detected.json")}},
      {{"screenshot", path("detected.png")}},
  }));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json s = state("detected.json");
  const json d = s["video"]["detection"];
  ASSERT_TRUE(d["done"].is_object()) << d;
  EXPECT_FALSE(d["running"].get<bool>());
  EXPECT_TRUE(d["shows_fit"].get<bool>());
  EXPECT_EQ(d["done"]["model"], "full");
  EXPECT_FALSE(d["done"]["from_cache"].get<bool>());
  const int frames = s["video"]["frames"].get<int>();
  EXPECT_EQ(d["done"]["frames"].get<int>(), frames);
  EXPECT_GE(d["done"]["frames_with_people"].get<int>(), frames * 8 / 10) << d;
  EXPECT_GE(d["done"]["people"].get<int>(), 1);
  // The clip is the detector's, fitted: the walker chosen by the keypoint clip's rule.
  EXPECT_EQ(s["mode"], "clip");
  EXPECT_EQ(s["clip"]["source"], "detections");
  EXPECT_EQ(s["clip"]["person_chosen"], -1);
  const json fit = s["clip"]["fit"];
  ASSERT_TRUE(fit.is_object()) << s["clip"];
  EXPECT_TRUE(fit["current"].get<bool>());
  EXPECT_EQ(fit["layout"], "MediaPipe-33");
  EXPECT_EQ(fit["frames"].get<int>(), frames);
  std::cout << "demo.mp4 detected: " << d["done"] << "\nfit: stature " << fit["stature_m"] << " m, stride "
            << fit["stride_hz"] << " Hz, alpha " << fit["alpha_deg"] << " deg, RMS " << fit["reprojection_rms_px"]
            << " px, person " << fit["person"] << " of " << fit["people"] << "\n";
  EXPECT_GE(fit["stature_m"].get<double>(), 1.55);  // issue 52's bars
  EXPECT_LE(fit["stature_m"].get<double>(), 1.75);
  EXPECT_GE(fit["stride_hz"].get<double>(), 0.7);
  EXPECT_LE(fit["stride_hz"].get<double>(), 1.3);
  // The scene's horizon, read off the facades' window rows (563–570 px by hand), holds the
  // camera's height as `reconstruct` does: the fitted camera's horizon within 2° of it.
  ASSERT_TRUE(d["done"]["horizon_row_px"].is_number()) << d["done"];
  EXPECT_NEAR(d["done"]["horizon_row_px"].get<double>(), 566.0, 10.0);
  EXPECT_EQ(s["clip"]["scene_horizon_row_px"], d["done"]["horizon_row_px"]);
  EXPECT_EQ(s["clip"]["scene_horizon_held"], true);
  EXPECT_LT(std::abs(fit["horizon_off_deg"].get<double>()), 2.0) << fit["horizon_row_px"];
  // Her heels and foot indices, lifted into 3D and drawn with the walker.
  EXPECT_GT(fit["feet"]["samples_lifted"].get<int>(), fit["feet"]["samples_seen"].get<int>() * 9 / 10) << fit["feet"];
  expectLayoutHolds(s, "demo.mp4 detected, 1600x900", {"input"});
  // The 2D view shows a frame of hers with the footage under the fit.
  EXPECT_GE(s["video"]["shown_frame"].get<int>(), 0);
  const cv::Mat shot = load("detected.png");
  ASSERT_FALSE(shot.empty());
  cv::Mat grey;
  cv::cvtColor(crop(shot, viewRegion(s, "input", shot.cols, shot.rows)), grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, sd;
  cv::meanStdDev(grey, mean, sd);
  EXPECT_GT(sd[0], 20.0) << "footage under the fit";
  // The detections for the tests that need them but not their making (tests/video/pose_models.h).
  if (!HasFailure()) shareDetectionCache(dir / "cache");
}

// Issue 52, "Marking and tracking become correction": a joint dragged on a detected frame is a
// correction (a keyframe) that redoes the walker's track around it, fading over a quarter
// second either side, and fits it again; undoing it puts the detections' fit back. The first
// run finds where the knee was detected; the second, from the detection cache, corrects it.
// Under ctest the first run reads the detections the test above made (a fixture).
TEST_F(GuiDetect, ACorrectedJointRedoesTheTrackAroundItAndUndoes) {
  EW_REQUIRE_SHARED_DATA();
  EW_REQUIRE_POSE_MODELS();
  const fs::path video = sharedDataDir() / "video" / "sports2d-demo" / "demo.mp4";
  constexpr int kFrame = 60;
  constexpr int kKnee = 10;  // r_knee (METHOD §1 order)
  if (seedDetectionCache(dir / "cache")) std::cout << "detections seeded from " << sharedDetectionsFolder() << "\n";
  ASSERT_EQ(run(json::array({{{"detect_video", video.string()}},
                             {{"video_frame", kFrame}},
                             {{"export_state", path("found.json")}}}))
                .exitCode,
            0);
  const json found = state("found.json");
  ASSERT_TRUE(found["clip"]["fit"].is_object()) << found["clip"];
  const json knee = found["clip"]["fit"]["frame_joints_px"];
  ASSERT_EQ(knee.size(), 30u);
  ASSERT_TRUE(knee[2 * kKnee].is_number()) << knee;
  const double dx = 24.0, dy = -10.0;
  const double x = knee[2 * kKnee].get<double>() + dx, y = knee[2 * kKnee + 1].get<double>() + dy;
  const int span = static_cast<int>(std::lround(0.25 * found["clip"]["fit"]["rate_hz"].get<double>()));
  ASSERT_GE(span, 2);
  // Before and after at the corrected frame, 2 frames on, and just beyond the span.
  const int frames[] = {kFrame, kFrame + 2, kFrame + span + 1};
  json script = json::array({{{"detect_video", video.string()}}});
  for (int f : frames) {
    script.push_back({{"video_frame", f}});
    script.push_back({{"export_state", path("before" + std::to_string(f) + ".json")}});
  }
  script.push_back({{"video_frame", kFrame}});
  script.push_back({{"drag_joint", {{"r_knee", {x, y}}}}});
  script.push_back({{"save_keyframes", path("corrections.json")}});
  script.push_back({{"video_zoom", {{"zoom", 3.0}, {"centre", {x, y - 80.0}}}}});  // the walker near
  script.push_back({{"screenshot", path("corrected.png")}});
  for (int f : frames) {
    script.push_back({{"video_frame", f}});
    script.push_back({{"export_state", path("after" + std::to_string(f) + ".json")}});
  }
  script.push_back({{"video_frame", kFrame}});
  script.push_back({{"undo", true}});  // the header's undo: the correction was the last change
  script.push_back({{"export_state", path("undone.json")}});
  const RunResult r = run(script);
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const auto at = [&](const std::string& name, int f) {
    const json s = state(name + std::to_string(f) + ".json");
    EXPECT_EQ(s["video"]["shown_frame"].get<int>(), f) << name;
    return s;
  };
  const auto kneeOf = [](const json& s) {
    const json& p = s["clip"]["fit"]["frame_joints_px"];
    return std::pair{p[2 * kKnee].get<double>(), p[2 * kKnee + 1].get<double>()};
  };
  const json before = at("before", kFrame), after = at("after", kFrame);
  EXPECT_TRUE(before["video"]["detection"]["done"]["from_cache"].get<bool>());
  EXPECT_EQ(before["clip"]["fit"]["corrections"], 0);
  // The fit is redone with the correction, and the clip's knee there is the correction.
  EXPECT_EQ(after["clip"]["corrections"], 1);
  EXPECT_EQ(after["clip"]["fit"]["corrections"], 1);
  EXPECT_TRUE(after["clip"]["fit"]["current"].get<bool>());
  EXPECT_TRUE(after["video"]["detection"]["shows_fit"].get<bool>());
  EXPECT_NE(after["clip"]["fit"]["reprojection_rms_px"], before["clip"]["fit"]["reprojection_rms_px"]);
  EXPECT_NEAR(kneeOf(after).first, x, 1e-9);
  EXPECT_NEAR(kneeOf(after).second, y, 1e-9);
  // Two frames on, the offset faded by 2 / (span + 1); beyond the span, the detection's.
  const double w = 1.0 - 2.0 / (span + 1);
  const auto b2 = kneeOf(at("before", kFrame + 2)), a2 = kneeOf(at("after", kFrame + 2));
  EXPECT_NEAR(a2.first - b2.first, w * dx, 1e-6);
  EXPECT_NEAR(a2.second - b2.second, w * dy, 1e-6);
  EXPECT_EQ(at("after", kFrame + span + 1)["clip"]["fit"]["frame_joints_px"],
            at("before", kFrame + span + 1)["clip"]["fit"]["frame_joints_px"]);
  // Other joints on the corrected frame stay the detector's.
  EXPECT_EQ(after["clip"]["fit"]["frame_joints_px"][2 * kKnee - 2], before["clip"]["fit"]["frame_joints_px"][2 * kKnee - 2]);
  // The corrections save as a keyframe file (`reconstruct --corrections` reads it).
  const json saved = json::parse(readAll(dir / "corrections.json"));
  ASSERT_EQ(saved["keyframes"].size(), 1u);
  EXPECT_EQ(saved["keyframes"][0]["frame"], kFrame);
  EXPECT_NEAR(saved["keyframes"][0]["joints"]["r_knee"][0].get<double>(), x, 1e-6);
  // Undone: no correction, the detections' fit again.
  const json undone = state("undone.json");
  EXPECT_EQ(undone["video"]["keyframes"].size(), 0u);
  EXPECT_EQ(undone["clip"]["fit"]["corrections"], 0);
  EXPECT_TRUE(undone["clip"]["fit"]["current"].get<bool>());
  EXPECT_EQ(undone["clip"]["fit"]["frame_joints_px"], before["clip"]["fit"]["frame_joints_px"]);
  EXPECT_EQ(undone["clip"]["fit"]["reprojection_rms_px"], before["clip"]["fit"]["reprojection_rms_px"]);
  EXPECT_FALSE(load("corrected.png").empty());
}

// Without the models the video still opens for marking, and the banner says which command
// fetches them; asking for a detection fails with the same words.
TEST_F(GuiDetect, SaysWhichCommandFetchesTheModelsWhenTheyAreMissing) {
  const fs::path video = writeEmptyVideo();
  fs::create_directories(dir / "no_models");
  const RunResult r = run(json::array({
                              {{"open", video.string()}},
                              {{"export_state", path("opened.json")}},
                              {{"expect_failure", {{"detect_video", video.string()}}}},
                              {{"export_state", path("asked.json")}},
                          }),
                          "1280x720", "EIGENWALKER_MODELS=" + quote((dir / "no_models").string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json opened = state("opened.json");
  ASSERT_TRUE(opened["video"].is_object());
  EXPECT_EQ(opened["mode"], "clip");
  ASSERT_TRUE(opened["notice"].is_object()) << opened["notice"];
  EXPECT_EQ(opened["notice"]["title"], "Detecting people needs the pose models");
  EXPECT_NE(opened["notice"]["detail"].get<std::string>().find("tools/pose_model/fetch_model.sh"), std::string::npos);
  EXPECT_FALSE(opened["video"]["detection"]["running"].get<bool>());
  expectLayoutHolds(opened, "the models missing, 1280x720", {});
  const json asked = state("asked.json");
  EXPECT_NE(asked["video"]["detection"]["error"].get<std::string>().find("fetch_model.sh"), std::string::npos);
}

// A video with nobody in it: detected, and said so in the banner; the video stays open.
TEST_F(GuiDetect, SaysSoWhenNobodyIsFound) {
  EW_REQUIRE_POSE_MODELS();
  const fs::path video = writeEmptyVideo();
  const RunResult r = run(json::array({
                              {{"expect_failure", {{"detect_video", {{"path", video.string()}, {"model", "lite"}}}}}},
                              {{"export_state", path("nobody.json")}},
                              {{"screenshot", path("nobody.png")}},
                          }),
                          "1280x720");
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json s = state("nobody.json");
  ASSERT_TRUE(s["video"].is_object());
  EXPECT_EQ(s["video"]["detection"]["done"]["people"], 0);
  EXPECT_EQ(s["video"]["detection"]["done"]["frames"], 12);
  EXPECT_EQ(s["notice"]["title"], "Nobody found in nobody.avi");
  EXPECT_TRUE(s["clip"].is_null());
  expectLayoutHolds(s, "nobody found, 1280x720", {});
}

}  // namespace
}  // namespace ew::test::gui

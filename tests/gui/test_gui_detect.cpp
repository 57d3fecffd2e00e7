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

// Keypoint clips in the viewer (issue 13): an OpenPose folder opens like any data; the 2D
// view shows the keypoints in image pixels with the 3D walker drawn back through the
// estimated camera (the reprojection overlay), the 3D view the walker and the camera glyph
// where the camera stands; the camera estimates are those `reconstruct --unknown-camera`
// finds, and holding the elevation or the focal length refits with that value.
//
// The clip: the model's mean walker crossing 6 m from a 1400 px camera 12° above at 40°
// (tests/camera/filmed_walk.h), with a second person standing beside the path the whole
// time (the tracker must follow the one who walks).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/videoio.hpp>
#include <string>

#include "tests/camera/filmed_walk.h"
#include "tests/gui/gui_run.h"
#include "tests/gui/layout_checks.h"
#include "tests/keypoints/yolo_run.h"

namespace ew::test::gui {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// The estimated camera's teal (palette::kCamera).
bool isTeal(int r, int g, int b) { return g > 170 && b > 140 && r < 150 && g - r > 80; }
// The people not fitted (palette::kOtherPerson, a khaki): red and green alike, well above
// blue (the amber's green is far below its red).
bool isKhaki(int r, int g, int b) { return r > 70 && g > 65 && r - b > 35 && g - b > 30 && std::abs(r - g) < 25; }

fs::path writeClip(const fs::path& dir) {
  const fs::path folder = dir / "clip_json";
  const Eigen::VectorXd t = frameTimes(150, 30.0);
  const Eigen::MatrixXd walk = synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * kFilmedStrideHz, 0.2, t);
  const Eigen::MatrixXd walker = projectWalk(walk, t, crossingPinhole(1400, 5.0));
  // Standing 500 px to the right of where the walker starts, still for the whole clip.
  Eigen::MatrixXd standing = walker.row(0).replicate(walker.rows(), 1);
  for (int j = 0; j < 15; ++j) standing.col(2 * j).array() += 500.0;
  writeOpenPoseBody25(folder, {{walker, Eigen::MatrixXd()}, {standing, Eigen::MatrixXd()}});
  return folder;
}

class GuiClip : public GuiTest {
 protected:
  json state(const std::string& name) const { return json::parse(readAll(dir / name)); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

TEST_F(GuiClip, OpenPoseFolderShowsTheReprojectionAndTheCamera) {
  const fs::path clip = writeClip(dir);
  const json script = json::array({
      {{"open", clip.string()}},
      // A fixed frame (playback ran while the fit did, further in a slow sanitizer build).
      {{"set_frame", 10}},
      {{"wait_frames", 2}},
      {{"export_state", path("opened.json")}},
      // The arrow keys step the clip's own frames (1/30 s here, not the walker's 1/60 s),
      // round its ends.
      {{"key", "right"}},
      {{"key", "right"}},
      {{"export_state", path("stepped.json")}},
      {{"set_frame", 150}},
      {{"key", "right"}},
      {{"export_state", path("wrapped.json")}},
      {{"key", "left"}},
      {{"export_state", path("wrapped_back.json")}},
      {{"set_frame", 10}},
      {{"export_png", {{"path", path("input.png")}, {"view", "input"}}}},
      {{"export_png", {{"path", path("recon.png")}, {"view", "reconstruction"}}}},
      {{"screenshot", path("window.png")}},
      {{"overlay", {"reprojection", false}}},
      {{"overlay", {"camera", false}}},
      {{"wait_frames", 2}},
      {{"export_png", {{"path", path("input_off.png")}, {"view", "input"}}}},
      {{"export_png", {{"path", path("recon_off.png")}, {"view", "reconstruction"}}}},
      {{"overlay", {"reprojection", true}}},
      {{"overlay", {"camera", true}}},
      // Near the clip's end the 3D view still shows the walker: it follows the walk.
      {{"set_frame", 140}},
      {{"wait_frames", 2}},
      {{"export_png", {{"path", path("recon_late.png")}, {"view", "reconstruction"}}}},
      // Hold the elevation 13° above the truth, then the true focal length.
      {{"set_clip", {{"elevation_deg", 25.0}}}},
      {{"export_state", path("elevation.json")}},
      {{"set_clip", {{"elevation_deg", nullptr}, {"focal_px", 1400.0}}}},
      {{"export_state", path("focal.json")}},
      // Issue 53: the viewer holds a focal length to the one rule (core/camera/focal_length.h).
      {{"expect_failure", {{"set_clip", {{"focal_px", 1e308}}}}}},
      {{"expect_failure", {{"set_clip", {{"focal_px", 49.0}}}}}},
      // A keypoint folder has no scene of its own: no horizon to hold the camera to.
      {{"expect_failure", {{"set_clip", {{"hold_to_horizon", true}}}}}},
      // The standing person does not walk: fitting it fails, and the walker's fit stays.
      {{"expect_failure", {{"set_clip", {{"person", 1}}}}}},
      {{"export_state", path("standing.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  const json opened = state("opened.json");
  EXPECT_EQ(opened["mode"], "clip");
  const json& fit = opened["clip"]["fit"];
  ASSERT_TRUE(fit.is_object()) << opened["clip"].dump(1);
  EXPECT_EQ(fit["format"], "OpenPose JSON");
  EXPECT_EQ(fit["frames"], 150);
  EXPECT_EQ(fit["people"], 2u);
  EXPECT_EQ(fit["people_in_frame"], json::array({0, 1}));
  EXPECT_EQ(fit["frame"], 10);
  EXPECT_EQ(state("stepped.json")["clip"]["fit"]["frame"], 12);
  EXPECT_EQ(state("wrapped.json")["clip"]["fit"]["frame"], 1);
  EXPECT_EQ(state("wrapped_back.json")["clip"]["fit"]["frame"], 150);
  // What `reconstruct --unknown-camera` measures on this walk (tests/camera): 1e-3-exact
  // is not expected, the detector's sternum is the shoulders' midpoint.
  EXPECT_NEAR(fit["alpha_deg"].get<double>(), 40.0, 2.0);
  EXPECT_NEAR(fit["elevation_deg"].get<double>(), 12.0, 2.0);
  EXPECT_NEAR(fit["focal_px"].get<double>(), 1400.0, 0.05 * 1400);
  EXPECT_NEAR(fit["distance_m"].get<double>(), 6.0, 0.05 * 6.0);
  EXPECT_NEAR(fit["speed_mps"].get<double>(), 1.3, 0.05 * 1.3);
  EXPECT_LT(fit["reprojection_rms_px"].get<double>(), 6.0);
  EXPECT_EQ(fit["residual_rms_px"].size(), 15u);

  // The reprojection (amber bones, magenta residuals) is drawn over the keypoints, and only
  // while its overlay is on; the camera glyph (teal) likewise in the 3D view.
  const cv::Mat input = load("input.png"), inputOff = load("input_off.png");
  const cv::Mat recon = load("recon.png"), reconOff = load("recon_off.png");
  EXPECT_GT(countPixels(input, isPointLight), 40);
  const int amber = countPixels(input, isAmber), amberOff = countPixels(inputOff, isAmber);
  EXPECT_GT(amber, 200);
  EXPECT_LT(amberOff, amber / 10) << amber;
  EXPECT_GT(countPixels(input, isMagenta), 10);
  // The standing person is drawn (khaki), left of the walker's first steps, labelled.
  EXPECT_GT(countPixels(input, isKhaki), 150);
  EXPECT_GT(countPixels(inputOff, isKhaki), 150);
  const int teal = countPixels(recon, isTeal), tealOff = countPixels(reconOff, isTeal);
  EXPECT_GT(teal, 150);
  EXPECT_LT(tealOff, teal / 3) << teal;  // the legend keeps its teal line
  EXPECT_GT(countPixels(recon, isAmber), 300);  // the 3D walker
  EXPECT_GT(countPixels(load("recon_late.png"), isAmber), 300);

  // Held values stay exactly where they were put; the wrong elevation fits worse.
  const json elevation = state("elevation.json");
  EXPECT_EQ(elevation["clip"]["elevation_deg_fixed"].get<double>(), 25.0);
  EXPECT_EQ(elevation["clip"]["fit"]["elevation_deg"].get<double>(), 25.0);
  EXPECT_TRUE(elevation["clip"]["fit"]["current"].get<bool>());
  EXPECT_GT(elevation["clip"]["fit"]["reprojection_rms_px"].get<double>(),
            fit["reprojection_rms_px"].get<double>());
  const json focal = state("focal.json");
  EXPECT_EQ(focal["clip"]["fit"]["focal_px"].get<double>(), 1400.0);
  EXPECT_NEAR(focal["clip"]["fit"]["elevation_deg"].get<double>(), 12.0, 2.0);
  EXPECT_NEAR(focal["clip"]["fit"]["distance_m"].get<double>(), 6.0, 0.05 * 6.0);

  const json standing = state("standing.json");
  EXPECT_NE(standing["clip"]["fit_error"].get<std::string>().find("not walking"), std::string::npos)
      << standing["clip"].dump(1);
  EXPECT_EQ(standing["clip"]["fit"]["person"], fit["person"]);
  EXPECT_FALSE(standing["clip"]["fit"]["current"].get<bool>());
}

// A walker on a treadmill: it stays in the picture, and the viewer fits it walking in place —
// the camera's azimuth from the body alone, the belt's speed from the stance feet — and says so.
TEST_F(GuiClip, ATreadmillClipIsFittedWalkingInPlace) {
  const fs::path folder = dir / "treadmill_json";
  const Eigen::VectorXd t = frameTimes(150, 30.0);
  const Eigen::MatrixXd walk = synthesizeFrames(defaultRealModel().mean, 2 * std::numbers::pi * kFilmedStrideHz, 0.2, t);
  WalkCamera camera = crossingPinhole(1400, 5.0);
  camera.speedMmS = camera.startOffsetMm = 0.0;
  writeOpenPoseBody25(folder, {{projectWalk(walk, t, camera), Eigen::MatrixXd()}});
  // And from a level camera, where the azimuth in place is weak (docs/TRACKING_DESIGN.md).
  const fs::path levelFolder = dir / "treadmill_level_json";
  WalkCamera level = camera;
  level.elevationDeg = 0.0;
  writeOpenPoseBody25(levelFolder, {{projectWalk(walk, t, level), Eigen::MatrixXd()}});
  const json script = json::array({{{"open", folder.string()}},
                                   {{"set_frame", 10}},
                                   {{"wait_frames", 2}},
                                   {{"export_state", path("treadmill.json")}},
                                   {{"screenshot", path("treadmill.png")}},
                                   {{"open", levelFolder.string()}},
                                   {{"export_state", path("level.json")}}});
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(writeScript(dir, script.dump(2)).string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json treadmill = state("treadmill.json");
  const json& fit = treadmill["clip"]["fit"];
  ASSERT_TRUE(fit.is_object()) << treadmill["clip"].dump(1);
  EXPECT_TRUE(fit["walking_in_place"].get<bool>());
  EXPECT_NEAR(fit["alpha_deg"].get<double>(), 40.0, 3.0);
  // The mean walker's stance feet move back at 1.2–1.3 m/s (its walkers' mean speed: 1.14 m/s).
  EXPECT_NEAR(fit["speed_mps"].get<double>(), 1.25, 0.15);
  EXPECT_LT(fit["reprojection_rms_px"].get<double>(), 6.0);
  // The level camera's fit says its azimuth is weak, in the state and the log.
  const json levelState = state("level.json");
  const json& cautions = levelState["clip"]["fit"]["cautions"];
  ASSERT_EQ(cautions.size(), 1u) << levelState["clip"]["fit"].dump(1);
  EXPECT_NE(cautions[0].get<std::string>().find("level camera"), std::string::npos);
  // In the amber banner, not only in the log.
  ASSERT_TRUE(levelState["notice"].is_object()) << levelState["notice"];
  EXPECT_EQ(levelState["notice"]["title"], "The fitted camera may be wrong (treadmill_level_json)");
  EXPECT_EQ(levelState["notice"]["level"], "warning");
  bool logged = false;
  for (const auto& line : levelState["log"])
    logged = logged || line["text"].get<std::string>().find("may be tens of degrees off") != std::string::npos;
  EXPECT_TRUE(logged) << levelState["log"].dump(1);
}

// Issue 18's layout in clip mode (issue 13): at the teaching sizes every drawer tab holds and
// the 2D view's caption and legend stay off the walker.
// A clip's 2D view frames the region the walker crosses, where a walker crossing the picture
// is small; it magnifies about a pixel as the video view does, and a new clip starts whole.
TEST_F(GuiClip, MagnifiesTheClipView) {
  const fs::path clip = writeClip(dir);
  const json centre = {700.0, 500.0};
  const RunResult r = runWholeZoomedWhole(dir, json::array({{{"open", clip.string()}}, {{"set_frame", 10}}}),
                                          "clip_zoom", 3.0, centre);
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json whole = state("whole.json"), zoomed = state("zoomed.json"), again = state("again.json");
  const auto walker = [](const json& st) { return st["layout"]["overlays"]["input.walker"]; };
  ASSERT_TRUE(walker(whole).is_array()) << whole["layout"];
  ASSERT_TRUE(walker(zoomed).is_array()) << zoomed["layout"];
  EXPECT_EQ(zoomed["view"]["clip_zoom"], 3.0);
  EXPECT_NEAR(walker(zoomed)[3].get<double>(), 3.0 * walker(whole)[3].get<double>(),
              0.05 * walker(whole)[3].get<double>())
      << "the walker three times as tall";
  EXPECT_EQ(walker(again), walker(whole));
}

TEST_F(GuiClip, ClipModeHoldsAtTheTeachingSizes) {
  const fs::path clip = writeClip(dir);
  for (const LayoutCell& c : teachingCells()) {
    const std::string cell = std::string(c.size) + " scale " + c.scale + " " + c.theme;
    json script = json::array({{{"set_theme", c.theme}}, {{"open", clip.string()}}, {{"set_frame", 10}}});
    for (const json& step : everyTabStates(dir, "clip")) script.push_back(step);
    const RunResult r = runViewer(dir, std::string("--size ") + c.size + " --ui-scale " + c.scale + " --script " +
                                           quote(writeScript(dir, script.dump()).string()));
    ASSERT_EQ(r.exitCode, 0) << cell << "\n" << r.err;
    for (const auto& tab : drawerTabs())
      expectLayoutHolds(state("clip_" + tab + ".json"), cell + ", clip, " + tab, {"input"});
  }
}

// A keypoint file that cannot be read is a failed open naming the file, and what was shown
// stays (the synthetic walkers).
// Issue 54: the viewer reads a calibration as the CLI's --camera does (one rule,
// core/camera/camera_knowledge.h). Dropped with the keypoint folder, the file's camera whose
// name the folder carries is taken ("clip" for clip_json, not "side"): its focal length is held,
// its principal point is the fit's prior. A focal length typed replaces it; another camera of
// the file can be chosen; a missing file or camera is refused and the fit stays.
TEST_F(GuiClip, AKeypointFolderOpensWithACalibrationFile) {
  const fs::path clip = writeClip(dir);
  const fs::path calibration = dir / "Calib_clip.toml";
  {
    std::ofstream out(calibration);
    out << "[clip]\nname = \"clip\"\nsize = [ 1920, 1080]\n"
           "matrix = [ [ 1400.0, 0.0, 960.0], [ 0.0, 1400.0, 540.0], [ 0.0, 0.0, 1.0]]\n"
           "distortions = [ 0.0, 0.0, 0.0, 0.0]\n\n"
           "[side]\nname = \"side\"\nsize = [ 1920, 1080]\n"
           "matrix = [ [ 900.0, 0.0, 960.0], [ 0.0, 900.0, 540.0], [ 0.0, 0.0, 1.0]]\n"
           "distortions = [ 0.0, 0.0, 0.0, 0.0]\n";
  }
  const json script = json::array({
      {{"drop", {clip.string(), calibration.string()}}},
      {{"set_frame", 10}},
      {{"wait_frames", 2}},
      {{"export_state", path("calibrated.json")}},
      {{"screenshot", path("calibrated.png")}},
      {{"set_clip", {{"focal_px", 1500.0}}}},
      {{"export_state", path("typed.json")}},
      {{"set_clip", {{"calibration", calibration.string()}, {"calibration_camera", "side"}}}},
      {{"export_state", path("side.json")}},
      {{"expect_failure", {{"set_clip", {{"calibration", (dir / "missing.toml").string()}}}}}},
      {{"expect_failure", {{"set_clip", {{"calibration", calibration.string()}, {"calibration_camera", "top"}}}}}},
      {{"export_state", path("kept.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  const json calibrated = state("calibrated.json")["clip"];
  EXPECT_EQ(calibrated["calibration"], calibration.string());
  EXPECT_EQ(calibrated["calibration_camera"], "clip");
  EXPECT_TRUE(calibrated["focal_px_fixed"].is_null());
  ASSERT_TRUE(calibrated["fit"].is_object()) << calibrated.dump(1);
  // Held at the calibration's focal length: the fit does not move it.
  EXPECT_EQ(calibrated["fit"]["focal_px"].get<double>(), 1400.0);
  EXPECT_NEAR(calibrated["fit"]["alpha_deg"].get<double>(), 40.0, 3.0);
  EXPECT_EQ(calibrated["fit"]["image_size_from"], "the calibration's");

  const json typed = state("typed.json")["clip"];
  EXPECT_TRUE(typed["calibration"].is_null());
  EXPECT_EQ(typed["focal_px_fixed"], 1500.0);
  EXPECT_EQ(typed["fit"]["focal_px"].get<double>(), 1500.0);

  const json side = state("side.json")["clip"];
  EXPECT_EQ(side["calibration_camera"], "side");
  EXPECT_EQ(side["fit"]["focal_px"].get<double>(), 900.0);
  const json kept = state("kept.json")["clip"];
  EXPECT_EQ(kept["calibration_camera"], "side");
  EXPECT_EQ(kept["fit"]["focal_px"].get<double>(), 900.0);
}

TEST_F(GuiClip, BrokenKeypointFileIsAFailedOpen) {
  const fs::path bad = dir / "broken.json";
  std::ofstream(bad) << R"({"people": [{"pose_keypoints_2d": [1, 2)";
  const json script = json::array({{{"open", nullptr}},
                                   {{"expect_failure", {{"open", bad.string()}}}},
                                   {{"export_state", path("state.json")}}});
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x800 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json s = state("state.json");
  EXPECT_NE(s["mode"], "clip");
  EXPECT_TRUE(s["clip"].is_null());
  ASSERT_TRUE(s["notice"].is_object());
  EXPECT_NE(s["notice"]["detail"].get<std::string>().find("broken.json"), std::string::npos) << s["notice"].dump(1);
  EXPECT_EQ(s["data"]["walkers"], 50);
}

// Ultralytics YOLO labels (fractions of the image): opened alone, the clip stays open and asks
// for the image's size, and fits once it is typed; with the annotated video Ultralytics writes
// beside them, the video's size and rate are taken and the fit needs nothing typed.
TEST_F(GuiClip, YoloLabelsTakeTheImageSizeTypedOrFromTheVideoBeside) {
  const fs::path run = writeYoloRun(filmedCoco({30, 31}), "gui_yolo_run");
  const json script = json::array({{{"expect_failure", {{"open", run.string()}}}},
                                   {{"export_state", path("needs_size.json")}},
                                   {{"screenshot", path("needs_size.png")}},
                                   {{"set_clip", {{"image_size", "1920x1080"}}}},
                                   {{"set_frame", 10}},
                                   {{"export_state", path("typed.json")}}});
  RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(writeScript(dir, script.dump(2)).string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json needs = state("needs_size.json");
  EXPECT_EQ(needs["mode"], "clip");
  ASSERT_TRUE(needs["clip"].is_object());
  EXPECT_NE(needs["clip"]["fit_error"].get<std::string>().find("fractions of the image"), std::string::npos);
  ASSERT_TRUE(needs["notice"].is_object());
  EXPECT_EQ(needs["notice"]["title"], "Give the image size of " + run.filename().string() + " (the Keypoint clip panel)");
  const json typed = state("typed.json");
  const json& fit = typed["clip"]["fit"];
  ASSERT_TRUE(fit.is_object()) << typed["clip"].dump(1);
  EXPECT_EQ(fit["format"], "YOLO pose labels");
  EXPECT_EQ(fit["layout"], "COCO-17");
  EXPECT_EQ(fit["frames"], 150);
  EXPECT_EQ(fit["image_size"], "1920x1080");
  EXPECT_EQ(fit["image_size_from"], "given");
  EXPECT_NEAR(fit["alpha_deg"].get<double>(), 40.0, 3.0);  // filmed at 40°, 12° down
  EXPECT_NEAR(fit["elevation_deg"].get<double>(), 12.0, 3.0);
  EXPECT_TRUE(typed["notice"].is_null()) << typed["notice"];

  // The annotated video beside the labels, at 25 fps: nothing to type, the rate is the video's.
  {
    cv::VideoWriter video((run / "walk.avi").string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0,
                          cv::Size(1920, 1080));
    ASSERT_TRUE(video.isOpened());
    for (int f = 0; f < 2; ++f) video.write(cv::Mat(1080, 1920, CV_8UC3, cv::Scalar(60, 60, 60)));
  }
  const json beside = json::array({{{"open", run.string()}}, {{"export_state", path("beside.json")}}});
  r = runViewer(dir, "--size 1280x720 --script " + quote(writeScript(dir, beside.dump(2)).string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const json withVideo = state("beside.json")["clip"]["fit"];
  const std::string video = "the video (" + (run / "walk.avi").string() + ")";
  EXPECT_EQ(withVideo["image_size"], "1920x1080");
  EXPECT_EQ(withVideo["image_size_from"], video);
  EXPECT_EQ(withVideo["rate_hz"], 25.0);
  EXPECT_EQ(withVideo["rate_from"], video);
}

}  // namespace
}  // namespace ew::test::gui

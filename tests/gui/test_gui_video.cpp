// Video in the viewer (issue 14): a clip opens with the keyframes marked on it, joints are
// marked on another frame by the script's clicks (with undo), the joints are tracked on a
// worker and the track is fitted through the unknown camera; the 2D view shows the footage
// with the 3D walker drawn back over it.
//
// The footage: a synthetic walker (known stride frequency) filmed 30° off the side view,
// 4.5 m away, 1280×720 at 30 fps, painted by video/synthetic_footage.h; keyframes with the
// true joints every 6 frames, as a user marking a clip every fifth of a second would.

#include <gtest/gtest.h>

#include <array>

#include <cmath>
#include <nlohmann/json.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <string>

#include "core/keypoints/openpose_writer.h"
#include "core/synth/population.h"
#include "core/tracking/keyframes.h"
#include "tests/gui/gui_run.h"
#include "tests/gui/layout_checks.h"
#include "video/synthetic_footage.h"

namespace ew::test::gui {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

struct Footage {
  fs::path video, keyframes;
  Eigen::MatrixXd truthPx;
  double strideHz = 0.0;
};

Footage writeWalkingFootage(const fs::path& dir) {
  PopulationOptions o;
  o.count = 1;
  o.simulation.rateHz = 30.0;
  const SynthWalker walker = generatePopulation(o).front();
  const Eigen::MatrixXd frames = walker.trial.positionsMm.topRows(
      std::min<Eigen::Index>(100, walker.trial.positionsMm.rows()));
  Footage f;
  f.video = dir / "walk.avi";
  f.truthPx = writeFootage(f.video, frames, cameraBeside(frames, 30.0, 4500.0), 30.0);
  f.strideHz = walker.attributes.at("cadence_spm") / 120.0;
  std::vector<int> marked;
  for (int k = 0; k < f.truthPx.rows(); k += 6)
    if (k != 30) marked.push_back(k);
  f.keyframes = dir / "walk_keyframes.json";
  writeKeyframes(f.keyframes, keyframesFromTrack(f.truthPx, marked, "walk.avi"));
  return f;
}

json jointsAt(const Eigen::MatrixXd& px, int frame) {
  json j = json::object();
  for (int k = 0; k < 15; ++k)
    j[std::string(kJointNames[k])] = {px(frame, 2 * k), px(frame, 2 * k + 1)};
  return j;
}

class GuiVideo : public GuiTest {
 protected:
  json state(const std::string& name) const { return json::parse(readAll(dir / name)); }
  std::string path(const std::string& name) const { return (dir / name).string(); }
};

// While the joints are being marked, Ctrl+Z and Ctrl+Shift+Z undo and redo the keyframe edits
// (as the marking panel's buttons do), not the settings; S skips a joint, Enter is Done. Before, the arrow keys step the
// video's own frames.
TEST_F(GuiVideo, WhileMarkingCtrlZUndoesTheKeyframes) {
  const Footage f = writeWalkingFootage(dir);
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"video_frame", 30}},
      // Before a track the arrow keys step the video's own frames.
      {{"key", "right"}},
      {{"export_state", path("stepped_untracked.json")}},
      {{"key", "left"}},
      {{"start_marking", true}},
      {{"mark_joints", {{"head", {10.0, 10.0}}}}},
      {{"export_state", path("marked.json")}},
      {{"key", "ctrl+z"}},
      {{"export_state", path("undone.json")}},
      {{"key", "ctrl+shift+z"}},
      {{"export_state", path("redone.json")}},
      // S skips the joint asked for (one hidden from view), Enter ends the marking.
      {{"key", "s"}},
      {{"export_state", path("skipped.json")}},
      {{"key", "enter"}},
      {{"export_state", path("done.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json marked = state("marked.json")["video"], undone = state("undone.json")["video"];
  const json redone = state("redone.json")["video"];
  ASSERT_TRUE(marked.is_object());
  EXPECT_EQ(state("stepped_untracked.json")["video"]["shown_frame"], 31);
  EXPECT_EQ(marked["frame"], 30) << "the left arrow stepped back";
  EXPECT_EQ(undone["undo_steps"].get<int>(), marked["undo_steps"].get<int>() - 1);
  EXPECT_EQ(undone["redo_steps"], 1);
  EXPECT_EQ(undone["keyframes"].size() + 1, marked["keyframes"].size())
      << "frame 30 was a new keyframe";
  EXPECT_EQ(redone["keyframes"], marked["keyframes"]);
  EXPECT_EQ(state("skipped.json")["video"]["mark_step"].get<int>(), redone["mark_step"].get<int>() + 1);
  EXPECT_TRUE(state("skipped.json")["video"]["marking"].get<bool>());
  EXPECT_FALSE(state("done.json")["video"]["marking"].get<bool>());
}

// Before a track, play plays the video's own frames (one at most per drawn frame, so none is
// skipped) and pause holds them; the transport's slider is the video's frame.
TEST_F(GuiVideo, PlaysTheVideosOwnFramesBeforeATrack) {
  const Footage f = writeWalkingFootage(dir);
  const json script = json::array({
      {{"detect_on_open", false}},
      {{"open", f.video.string()}},
      {{"video_frame", 10}},
      {{"play", true}},
      {{"wait_frames", 20}},
      {{"play", false}},
      {{"export_state", path("played.json")}},
      {{"wait_frames", 10}},
      {{"export_state", path("paused.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const int played = state("played.json")["video"]["shown_frame"].get<int>();
  EXPECT_GT(played, 10) << "play moved the video on";
  EXPECT_LE(played, 10 + 21) << "one video frame at most per drawn frame";
  EXPECT_EQ(state("paused.json")["video"]["shown_frame"].get<int>(), played) << "pause holds the frame";
}

// The 2D view magnifies the picture about a pixel (the wheel does so about the cursor) so
// that a walker a few hundred pixels tall can be marked; zoom 1 shows the whole picture again.
TEST_F(GuiVideo, MagnifiesThePictureToMarkTheWalker) {
  const Footage f = writeWalkingFootage(dir);
  const int pelvis = index(Joint::Pelvis);
  const json centre = {f.truthPx(0, 2 * pelvis), f.truthPx(0, 2 * pelvis + 1)};
  const RunResult r =
      runWholeZoomedWhole(dir, json::array({{{"detect_on_open", false}}, {{"open", f.video.string()}}}),
                          "video_zoom", 4.0, centre);
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json whole = state("whole.json"), zoomed = state("zoomed.json"), again = state("again.json");
  EXPECT_EQ(zoomed["video"]["zoom"], 4.0);
  const auto footage = [](const json& st) { return st["layout"]["overlays"]["input.footage"]; };
  ASSERT_TRUE(footage(whole).is_array()) << whole["layout"];
  EXPECT_NEAR(footage(zoomed)[2].get<double>(), 4.0 * footage(whole)[2].get<double>(), 2.0);
  const double input[4] = {zoomed["layout"]["input"][0], zoomed["layout"]["input"][1],
                           zoomed["layout"]["input"][2], zoomed["layout"]["input"][3]};
  // The pelvis at the view's middle: the footage's left edge as far left of it as the pelvis
  // is from the picture's left, four times magnified.
  const double scale = footage(zoomed)[2].get<double>() / 1280.0;  // screen px a video px
  EXPECT_NEAR(footage(zoomed)[0].get<double>() + scale * centre[0].get<double>(), input[0] + 0.5 * input[2], 2.0);
  EXPECT_EQ(again["video"]["zoom"], 1.0);
  EXPECT_EQ(footage(again), footage(whole));
}

// The magnifier by the mouse itself (a script's pointer): the wheel zooms about the pixel
// under the cursor, a right-drag moves the magnified picture with the pointer, a right double
// click shows the whole picture again.
TEST_F(GuiVideo, TheMouseMagnifiesAboutTheCursorAndDragsThePicture) {
  const Footage f = writeWalkingFootage(dir);
  const auto first = writeScript(dir, json::array({{{"detect_on_open", false}},
                                                   {{"open", f.video.string()}},
                                                   {{"wait_frames", 2}},
                                                   {{"export_state", path("layout.json")}}})
                                          .dump());
  ASSERT_EQ(runViewer(dir, "--size 1280x720 --script " + quote(first.string())).exitCode, 0);
  const json layout = state("layout.json")["layout"];
  const auto rect = [](const json& r) { return std::array<double, 4>{r[0], r[1], r[2], r[3]}; };
  const auto view = rect(layout["input"]);
  const auto whole = rect(layout["overlays"]["input.footage"]);
  // A point two fifths across the view and half-way down: on the picture, off its middle.
  const double px = view[0] + 0.4 * view[2], py = view[1] + 0.5 * view[3];
  const json script = json::array({
      {{"detect_on_open", false}},
      {{"open", f.video.string()}},
      {{"wait_frames", 2}},
      {{"mouse", {{"at", {px, py}}}}},
      {{"mouse", {{"wheel", 2}}}},
      {{"wait_frames", 1}},
      {{"export_state", path("wheeled.json")}},
      {{"mouse", {{"press", "right"}}}},
      {{"mouse", {{"at", {px - 100.0, py - 50.0}}}}},
      {{"mouse", {{"release", "right"}}}},
      {{"wait_frames", 1}},
      {{"export_state", path("dragged.json")}},
      {{"mouse", {{"press", "right"}}}},
      {{"mouse", {{"release", "right"}}}},
      {{"mouse", {{"press", "right"}}}},
      {{"mouse", {{"release", "right"}}}},
      {{"mouse", {{"away", true}}}},
      {{"wait_frames", 1}},
      {{"export_state", path("whole.json")}},
  });
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(writeScript(dir, script.dump(2)).string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;

  const json wheeled = state("wheeled.json");
  EXPECT_NEAR(wheeled["video"]["zoom"].get<double>(), 1.5625, 1e-9);  // two notches of 1.25
  const auto zoomed = rect(wheeled["layout"]["overlays"]["input.footage"]);
  // The video pixel under the cursor stays under it.
  const double u = (px - whole[0]) / whole[2], v = (py - whole[1]) / whole[3];
  EXPECT_NEAR(zoomed[2], 1.5625 * whole[2], 2.0);
  EXPECT_NEAR(zoomed[0] + u * zoomed[2], px, 2.0);
  EXPECT_NEAR(zoomed[1] + v * zoomed[3], py, 2.0);
  // Dragged: the picture went with the pointer, 100 px left and 50 px up.
  const auto dragged = rect(state("dragged.json")["layout"]["overlays"]["input.footage"]);
  EXPECT_NEAR(dragged[0], zoomed[0] - 100.0, 2.0);
  EXPECT_NEAR(dragged[1], zoomed[1] - 50.0, 2.0);
  const json again = state("whole.json");
  EXPECT_EQ(again["video"]["zoom"], 1.0);
  EXPECT_EQ(rect(again["layout"]["overlays"]["input.footage"]), whole);
}

// Dragging a marked joint with the mouse moves it on that frame (issue 14: "drag to correct").
TEST_F(GuiVideo, DraggingAMarkWithTheMouseMovesIt) {
  const Footage f = writeWalkingFootage(dir);
  const auto first = writeScript(dir, json::array({{{"open", json::array({f.video.string(), f.keyframes.string()})}},
                                                   {{"video_frame", 0}},
                                                   {{"wait_frames", 2}},
                                                   {{"export_state", path("layout.json")}}})
                                          .dump());
  ASSERT_EQ(runViewer(dir, "--size 1280x720 --script " + quote(first.string())).exitCode, 0);
  const json opened = state("layout.json");
  const json& footage = opened["layout"]["overlays"]["input.footage"];
  const double screenPerVideoPx = footage[2].get<double>() / opened["video"]["width_px"].get<double>();
  const int pelvis = index(Joint::Pelvis);
  const double sx = footage[0].get<double>() + screenPerVideoPx * f.truthPx(0, 2 * pelvis);
  const double sy = footage[1].get<double>() + screenPerVideoPx * f.truthPx(0, 2 * pelvis + 1);
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"video_frame", 0}},
      {{"wait_frames", 2}},
      {{"mouse", {{"at", {sx, sy}}}}},
      {{"mouse", {{"press", "left"}}}},
      {{"mouse", {{"at", {sx + 20.0, sy}}}}},
      {{"mouse", {{"at", {sx + 40.0, sy + 10.0}}}}},
      {{"mouse", {{"release", "left"}}}},
      {{"mouse", {{"away", true}}}},
      {{"save_keyframes", path("dragged_keyframes.json")}},
  });
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(writeScript(dir, script.dump(2)).string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const Keyframes saved = readKeyframes(dir / "dragged_keyframes.json");
  const Keyframe* k = nullptr;
  for (const auto& kf : saved.keyframes)
    if (kf.frame == 0) k = &kf;
  ASSERT_NE(k, nullptr);
  EXPECT_NEAR(k->jointsPx[2 * pelvis], f.truthPx(0, 2 * pelvis) + 40.0 / screenPerVideoPx, 1.0);
  EXPECT_NEAR(k->jointsPx[2 * pelvis + 1], f.truthPx(0, 2 * pelvis + 1) + 10.0 / screenPerVideoPx, 1.0);
  const int head = index(Joint::Head);  // the others stay where they were marked
  EXPECT_NEAR(k->jointsPx[2 * head], f.truthPx(0, 2 * head), 1e-6);
}

TEST_F(GuiVideo, MarkTrackAndSeeTheWalkerOverTheFootage) {
  const Footage f = writeWalkingFootage(dir);
  ASSERT_GE(f.truthPx.rows(), 90) << "three gait cycles at 30 fps";
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"video_frame", 30}},
      {{"start_marking", true}},
      // A wrong head, taken back; then every joint where it is.
      {{"mark_joints", {{"head", {10.0, 10.0}}}}},
      {{"undo_keyframes", true}},
      {{"mark_joints", jointsAt(f.truthPx, 30)}},
      {{"wait_frames", 2}},
      {{"export_state", path("marked.json")}},
      {{"screenshot", path("marking.png")}},
      {{"save_keyframes", path("saved_keyframes.json")}},
      {{"track_video", {{"first", 0}, {"last", -1}}}},
      {{"video_frame", 45}},
      {{"wait_frames", 2}},
      {{"export_state", path("tracked.json")}},
      {{"export_png", {{"path", path("input.png")}, {"view", "input"}}}},
      {{"screenshot", path("window.png")}},
      {{"key", "right"}},
      {{"key", "right"}},
      {{"export_state", path("stepped_tracked.json")}},
      // The gait report of the walker fitted through the camera.
      {{"show_panel", {"gait", true}}},
      {{"export_gait_report", path("gait.json")}},
      {{"expect_failure", {{"mark_joints", {{"l_knee", {5000.0, 10.0}}}}}}},
      {{"expect_failure", {{"mark_joints", {{"nose", {10.0, 10.0}}}}}}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;

  // Marking: the keyframes read, frame 30 marked with its 15 joints, the wrong head undone.
  const json marked = state("marked.json")["video"];
  ASSERT_TRUE(marked.is_object()) << marked;
  EXPECT_EQ(marked["frames"], f.truthPx.rows());
  EXPECT_EQ(marked["width_px"], 1280);
  EXPECT_EQ(marked["keyframes"].size(), 17u);
  EXPECT_EQ(marked["mark_step"], 15) << "every joint marked: nothing more asked for";
  const Keyframes saved = readKeyframes(dir / "saved_keyframes.json");
  const auto k30 = std::find_if(saved.keyframes.begin(), saved.keyframes.end(),
                                [](const Keyframe& k) { return k.frame == 30; });
  ASSERT_NE(k30, saved.keyframes.end());
  EXPECT_NEAR((k30->jointsPx - f.truthPx.row(30)).cwiseAbs().maxCoeff(), 0.0, 1e-6);

  // The track and its fit: the walker's own stride frequency, its joints reprojected within
  // a few pixels (the model's walker is not the synthetic one: the residual is not zero).
  const json tracked = state("tracked.json");
  ASSERT_TRUE(tracked["video"]["track"].is_object()) << tracked["video"];
  EXPECT_EQ(tracked["video"]["track"]["last_frame"], f.truthPx.rows() - 1);
  const json fit = tracked["clip"]["fit"];
  ASSERT_TRUE(fit.is_object()) << tracked["clip"];
  EXPECT_EQ(fit["format"], "tracked video");
  EXPECT_NEAR(fit["stride_hz"].get<double>(), f.strideHz, 0.05 * f.strideHz);
  EXPECT_LT(fit["reprojection_rms_px"].get<double>(), 12.0);
  EXPECT_EQ(tracked["video"]["shown_frame"], 45);
  // The gait report measures the fitted walker at the fit's own stride and speed: cadence is
  // two steps a stride (a two-harmonic walker's events come once a period), the speed is the
  // camera fit's, stance a walk's (docs/GAIT.md: 60–65 % in the shared walkers).
  const json gait = json::parse(readAll(dir / "gait.json"));
  EXPECT_EQ(gait["engine"], "eigenwalker through the estimated camera");
  EXPECT_EQ(gait["walker"], "walk.avi");
  const json& measures = gait["measures"];
  EXPECT_NEAR(measures["cadence_spm"]["reconstruction"].get<double>(), 120.0 * fit["stride_hz"].get<double>(), 0.5);
  EXPECT_NEAR(measures["speed_mps"]["reconstruction"].get<double>(), fit["speed_mps"].get<double>(), 0.01);
  EXPECT_TRUE(measures["speed_mps"]["motion_capture"].is_null());
  const double stance = measures["stance_pct"]["reconstruction"].get<double>();
  EXPECT_GT(stance, 55.0);
  EXPECT_LT(stance, 70.0);
  // One frame of the footage per arrow key (before a track: WhileMarkingCtrlZUndoesTheKeyframes).
  EXPECT_EQ(state("stepped_tracked.json")["video"]["shown_frame"], 47);

  // The 2D view shows the footage (its noise background is no flat dark panel) and the
  // reprojected walker's orange.
  const cv::Mat input = load("input.png");
  const int orange = countPixels(
      input, [](int rr, int g, int b) { return rr > 200 && g > 110 && g < 190 && b < 90; });
  EXPECT_GT(orange, 40) << "the reprojection drawn over the footage";
  cv::Mat grey;
  cv::cvtColor(input, grey, cv::COLOR_BGR2GRAY);
  cv::Scalar mean, sd;
  cv::meanStdDev(grey, mean, sd);
  EXPECT_GT(sd[0], 20.0) << "the footage's texture behind the joints";
}

// Issue 14's real footage: the sports2d demo (a woman walking right to left in profile, a man
// jumping behind her). Her joints are marked by the script on frame 120 only (the coordinates
// read off that frame by hand, tests/data/sports2d_demo_keyframes.json), frames 40–200 are
// tracked over the flattened still background, and the walk is fitted through the unknown
// camera: issue 14's bars, her stride frequency (counted by eye, about 0.80 Hz), a person's
// stature and a profile view; and the camera Sports2D estimated for its demo (Calib_demo.toml:
// level, focal about 2520 px), which the fit finds only when it knows the image's centre
// (before: 4046 px; docs/CAMERA.md, "The principal point").
TEST_F(GuiVideo, MarksTheSports2dWalkerOnceAndFindsHerStrideStatureAndProfile) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path clip = sharedDataDir() / "video" / "sports2d-demo" / "demo.mp4";
  const Keyframes marks =
      readKeyframes(sourceDir() / "tests" / "data" / "sports2d_demo_keyframes.json");
  const auto k120 = std::find_if(marks.keyframes.begin(), marks.keyframes.end(),
                                 [](const Keyframe& k) { return k.frame == 120; });
  ASSERT_NE(k120, marks.keyframes.end());
  const json script = json::array({
      {{"detect_on_open", false}},
      {{"open", json::array({clip.string()})}},
      {{"video_frame", 120}},
      {{"start_marking", true}},
      {{"mark_joints", jointsAt(k120->jointsPx, 0)}},
      {{"stop_marking", true}},
      {{"track_video", {{"first", 40}, {"last", 200}, {"flatten_background", true}}}},
      {{"video_frame", 100}},
      {{"wait_frames", 3}},
      {{"export_state", path("sports2d.json")}},
      {{"export_png", {{"path", path("sports2d_input.png")}, {"view", "input"}}}},
      {{"screenshot", path("sports2d.png")}},
      {{"set_clip", {{"hold_to_horizon", true}}}},
      {{"export_state", path("sports2d_held.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json s = state("sports2d.json");
  ASSERT_TRUE(s["video"]["track"].is_object()) << s["video"];
  EXPECT_EQ(s["video"]["keyframes"].size(), 1u);
  EXPECT_EQ(s["video"]["track"]["background"], "flattened");
  const json fit = s["clip"]["fit"];
  ASSERT_TRUE(fit.is_object()) << s["clip"];
  std::cout << "sports2d, one keyframe: alpha " << fit["alpha_deg"] << " deg, elevation "
            << fit["elevation_deg"] << " deg, stride " << fit["stride_hz"] << " Hz, head height "
            << fit["head_height_m"] << " m, stature " << fit["stature_m"] << " m, focal "
            << fit["focal_px"] << " px, " << fit["distance_m"] << " m away\n";
  EXPECT_GE(fit["stride_hz"].get<double>(), 0.7);  // issue 14's bars
  EXPECT_LE(fit["stride_hz"].get<double>(), 1.3);
  EXPECT_GE(fit["stature_m"].get<double>(), 1.45);
  EXPECT_LE(fit["stature_m"].get<double>(), 1.95);
  EXPECT_NEAR(fit["alpha_deg"].get<double>(), -90.0, 20.0) << "a profile view, walking left";
  // Its walk raises no caution (unflattened, the same track strides 1.6 times her stature
  // through a camera 67° down, and says so: docs/TRACKING_DESIGN.md). Its camera's height does:
  // the fit's horizon lies 7.5° below the scene's, which the track's fit is checked against, not
  // held to (held, it took a focal length of 3600 px: docs/CAMERA.md, "The scene's horizon").
  ASSERT_EQ(fit["cautions"].size(), 1u) << fit["cautions"];
  EXPECT_NE(fit["cautions"][0].get<std::string>().find("the scene's level lines put the horizon at row 567 px"),
            std::string::npos) << fit["cautions"];
  EXPECT_NEAR(fit["elevation_deg"].get<double>(), 0.0, 5.0) << "a level camera";
  EXPECT_NEAR(fit["focal_px"].get<double>(), 2520.0, 0.25 * 2520.0) << "Sports2D's own estimate";
  // The scene's horizon, read with the track.
  ASSERT_TRUE(s["video"]["track"]["horizon_row_px"].is_number()) << s["video"]["track"];
  EXPECT_NEAR(s["video"]["track"]["horizon_row_px"].get<double>(), 566.0, 10.0);
  EXPECT_EQ(s["clip"]["scene_horizon_row_px"], s["video"]["track"]["horizon_row_px"]);
  EXPECT_EQ(s["clip"]["scene_horizon_held"], false);
  EXPECT_GT(fit["horizon_off_deg"].get<double>(), 2.0) << "the camera's horizon beside the scene's";
  // Held to it when asked, as `track --reconstruct --scene-horizon prior` holds it (7.5° → 3.0°).
  const json held = state("sports2d_held.json")["clip"];
  EXPECT_EQ(held["scene_horizon_held"], true);
  EXPECT_LT(std::abs(held["fit"]["horizon_off_deg"].get<double>()), 0.6 * fit["horizon_off_deg"].get<double>());
}

// Issue 16: Zou et al.'s appearance tracker is chosen in the Track section (the script's
// "tracker") and the track says which tracker made it; the controls show the choice.
TEST_F(GuiVideo, TracksWithTheAppearanceTrackerWhenChosen) {
  const Footage f = writeWalkingFootage(dir);
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"track_video", {{"first", 0}, {"last", 59}, {"tracker", "appearance"}}}},
      {{"wait_frames", 2}},
      {{"export_state", path("appearance.json")}},
      {{"screenshot", path("appearance.png")}},
      {{"expect_failure", {{"track_video", {{"first", 0}, {"last", 59}, {"tracker", "sift"}}}}}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json video = state("appearance.json")["video"];
  ASSERT_TRUE(video["track"].is_object()) << video;
  EXPECT_EQ(video["tracker"], "appearance");
  EXPECT_EQ(video["track"]["tracker"], "appearance");
  EXPECT_EQ(video["track"]["last_frame"], 59);
  EXPECT_GT(video["track"]["mean_confidence"].get<double>(), 0.5);
}

// The flow tracker flattens the still background and holds the trunk when asked (the
// script's "flatten_background" and "hold_trunk", the Track section's checkboxes) and the track
// says it did; a wrong value fails the script.
TEST_F(GuiVideo, FlattensTheStillBackgroundAndHoldsTheTrunkWhenAsked) {
  const Footage f = writeWalkingFootage(dir);
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"track_video",
        {{"first", 0}, {"last", 59}, {"flatten_background", true}, {"hold_trunk", true}}}},
      {{"wait_frames", 2}},
      {{"export_state", path("flattened.json")}},
      {{"expect_failure",
        {{"track_video", {{"first", 0}, {"last", 59}, {"flatten_background", "yes"}}}}}},
      {{"expect_failure", {{"track_video", {{"first", 0}, {"last", 59}, {"hold_trunk", 1}}}}}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json video = state("flattened.json")["video"];
  ASSERT_TRUE(video["track"].is_object()) << video;
  EXPECT_EQ(video["flatten_background"], true);
  EXPECT_EQ(video["track"]["background"], "flattened");
  EXPECT_EQ(video["hold_trunk"], true);
  EXPECT_EQ(video["track"]["trunk_held"], true);
  // The Track section's two suggestions: tracked frames, and no keyframe.
  for (const char* suggestion : {"frame_to_mark_next", "least_sure_frame"}) {
    const int frame = video["track"][suggestion].get<int>();
    EXPECT_GE(frame, 0) << suggestion;
    EXPECT_LE(frame, 59) << suggestion;
    for (const json& k : video["keyframes"]) EXPECT_NE(k["frame"].get<int>(), frame) << suggestion;
  }
}

// A pose estimator's detections mark a frame (the Mark section's keypoint field, the script's
// "mark_from_keypoints"): every joint it found, one edit, and the track runs from it; a folder
// that is not there fails the script, naming it.
TEST_F(GuiVideo, MarksAFrameFromAPoseEstimatorsKeypoints) {
  const Footage f = writeWalkingFootage(dir);
  const fs::path detected = dir / "detected";
  writeOpenPoseBody25(detected, {{f.truthPx, Eigen::MatrixXd::Ones(f.truthPx.rows(), 15)}});
  const json script = json::array({
      {{"detect_on_open", false}},
      {{"open", f.video.string()}},
      {{"video_frame", 12}},
      {{"mark_from_keypoints", detected.string()}},
      {{"export_state", path("marked.json")}},
      {{"expect_failure", {{"mark_from_keypoints", path("nowhere")}}}},
      {{"track_video", {{"first", 0}, {"last", 59}}}},
      {{"wait_frames", 2}},
      {{"export_state", path("tracked.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json marked = state("marked.json")["video"];
  ASSERT_EQ(marked["keyframes"].size(), 1u) << marked;
  EXPECT_EQ(marked["keyframes"][0]["frame"], 12);
  EXPECT_EQ(marked["keyframes"][0]["joints"], 15);
  EXPECT_EQ(marked["undo_steps"], 1);
  EXPECT_NE(r.err.find("nowhere"), std::string::npos) << r.err;
  const json tracked = state("tracked.json")["video"];
  ASSERT_TRUE(tracked["track"].is_object()) << tracked;
  EXPECT_EQ(tracked["track"]["first_frame"], 0);
  EXPECT_EQ(tracked["track"]["last_frame"], 59);
}

// A keypoint clip opened while a video is open takes the views' place, as a video opened takes
// a clip's (the 2D view went on showing the video beside the clip's fit). Opened together
// with a video, the clip is refused, with the reason in the log.
TEST_F(GuiVideo, AKeypointClipOpenedAfterAVideoReplacesIt) {
  const Footage f = writeWalkingFootage(dir);
  const fs::path detected = dir / "detected";
  writeOpenPoseBody25(detected, {{f.truthPx, Eigen::MatrixXd::Ones(f.truthPx.rows(), 15)}});
  const json script = json::array({
      {{"detect_on_open", false}},
      {{"open", json::array({f.video.string(), detected.string()})}},
      {{"export_state", path("together.json")}},
      {{"open", detected.string()}},
      {{"wait_frames", 2}},
      {{"export_state", path("clip.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json together = state("together.json"), clip = state("clip.json");
  EXPECT_TRUE(together["video"].is_object());
  EXPECT_TRUE(together["clip"].is_null()) << together["clip"];
  EXPECT_NE(together["log"].dump().find("a video and a keypoint clip at a time"), std::string::npos)
      << together["log"];
  EXPECT_TRUE(clip["video"].is_null()) << "the clip closed the video";
  ASSERT_TRUE(clip["clip"].is_object());
  EXPECT_EQ(fs::path(clip["clip"]["path"].get<std::string>()), detected);
  EXPECT_EQ(clip["mode"], "clip");
}

// A tracked joint dragged on a frame that is no keyframe and let go (the script's "drag_joint",
// as the mouse does): the frame becomes a keyframe and the track is redone from the keyframes
// as they now are, with no button pressed.
TEST_F(GuiVideo, DraggingATrackedJointTracksAgainFromTheNewKeyframe) {
  const Footage f = writeWalkingFootage(dir);
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"track_video", {{"first", 0}, {"last", -1}}}},
      {{"wait_frames", 2}},
      {{"export_state", path("before.json")}},
      {{"video_frame", 30}},
      {{"drag_joint", {{"r_knee", {f.truthPx(30, 20), f.truthPx(30, 21)}}}}},
      {{"wait_frames", 2}},
      {{"export_state", path("after.json")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json before = state("before.json")["video"], after = state("after.json")["video"];
  ASSERT_TRUE(before["track"].is_object() && after["track"].is_object()) << after;
  EXPECT_EQ(after["keyframes"].size(), before["keyframes"].size() + 1);
  EXPECT_EQ(after["track"]["keyframes"], before["track"]["keyframes"].get<int>() + 1);
  EXPECT_EQ(after["undo_steps"], before["undo_steps"].get<int>() + 1);
}

// Pose2Sim's balancing man, marked from OpenPose's detections on frame 0 and tracked: no walk
// fits a balancing trial, and the viewer says so and keeps the video and its track on screen
// (before, it went back to the model's walkers and the track could not be seen).
TEST_F(GuiVideo, KeepsATrackNoWalkFitsOnScreenAndSaysWhy) {
  EW_REQUIRE_SHARED_DATA();
  const fs::path trial = sharedDataDir() / "pose2sim-balancing";
  const json script = json::array({
      {{"detect_on_open", false}},
      {{"open", (trial / "videos" / "cam01.mp4").string()}},
      {{"mark_from_keypoints", (trial / "pose" / "cam01_json").string()}},
      {{"expect_failure", {{"track_video", {{"first", 0}, {"last", 99}, {"hold_trunk", true}}}}}},
      {{"video_frame", 40}},
      {{"wait_frames", 2}},
      {{"export_state", path("balancing.json")}},
      {{"screenshot", path("balancing.png")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json s = state("balancing.json");
  EXPECT_EQ(s["mode"], "clip");
  EXPECT_EQ(s["video"]["keyframes"][0]["joints"], 15) << s["video"];
  ASSERT_TRUE(s["video"]["track"].is_object()) << s["video"];
  EXPECT_EQ(s["video"]["track"]["trunk_held"], true);
  ASSERT_TRUE(s["notice"].is_object()) << s;
  EXPECT_EQ(s["notice"]["title"], "No walk fits the track of cam01.mp4");
  EXPECT_NE(s["notice"]["detail"].get<std::string>().find("not walking"), std::string::npos)
      << s["notice"];
}

// Footage filmed with a phone held upright stands beside a column with the caption and the
// legend, at nearly the view's full height, rather than between them at three quarters of it.
TEST_F(GuiVideo, UprightFootageStandsBesideItsCaptionAtFullHeight) {
  const fs::path video = dir / "upright.avi";
  {
    cv::VideoWriter writer(video.string(), cv::CAP_FFMPEG, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 30.0,
                           cv::Size(360, 640));
    ASSERT_TRUE(writer.isOpened());
    for (int k = 0; k < 10; ++k) {
      cv::Mat image(640, 360, CV_8UC3, cv::Scalar(60, 90, 120));
      cv::circle(image, cv::Point(180, 100 + 40 * k), 30, cv::Scalar(230, 230, 230), cv::FILLED);
      writer.write(image);
    }
  }
  const json script = json::array({
      {{"detect_on_open", false}},
      {{"open", video.string()}},
      {{"video_frame", 3}},
      {{"wait_frames", 2}},
      {{"export_state", path("upright.json")}},
      {{"screenshot", path("upright.png")}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1920x1080 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json layout = state("upright.json")["layout"];
  const json& o = layout["overlays"];
  ASSERT_TRUE(o.contains("input.footage") && o.contains("input.caption")) << o;
  const double panelHeight = layout["input"][3], footageWidth = o["input.footage"][2],
               footageHeight = o["input.footage"][3];
  EXPECT_GE(footageHeight, 0.9 * panelHeight) << o;
  EXPECT_NEAR(footageWidth / footageHeight, 360.0 / 640.0, 0.01) << o;
  EXPECT_FALSE(overlap(o["input.caption"], o["input.footage"])) << o;
}

// The model loop (Howe, Leventon & Freeman's feedback; the Track section's slider, the
// script's "model_loop"): the track says how many rounds it ran and the controls say so; an
// out-of-range count fails the script.
TEST_F(GuiVideo, RunsTheModelLoopWhenAsked) {
  const Footage f = writeWalkingFootage(dir);
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"track_video", {{"first", 0}, {"last", -1}, {"model_loop", 2}}}},
      {{"wait_frames", 2}},
      {{"export_state", path("looped.json")}},
      {{"screenshot", path("looped.png")}},
      {{"expect_failure", {{"track_video", {{"first", 0}, {"last", -1}, {"model_loop", 11}}}}}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  const json s = state("looped.json");
  ASSERT_TRUE(s["video"]["track"].is_object()) << s["video"];
  EXPECT_EQ(s["video"]["model_loop"], 2);
  EXPECT_EQ(s["video"]["track"]["model_loop"], 2);
  EXPECT_EQ(s["video"]["track"]["model_loop_fits"], 2) << s["video"]["track"]["model_loop_stopped"];
  EXPECT_GT(s["video"]["track"]["model_loop_hidden_joint_frames"].get<int>(), 0);
  const json fit = s["clip"]["fit"];
  ASSERT_TRUE(fit.is_object()) << s["clip"];
  EXPECT_NEAR(fit["stride_hz"].get<double>(), f.strideHz, 0.05 * f.strideHz);
}

// Issue 14: the exported video of a tracked clip has the footage under the track and the
// walker drawn back, with the captions (the video's name and frame) burnt in.
TEST_F(GuiVideo, TheExportedVideoHasTheFootageUnderTheTrackAndCaptions) {
  const Footage f = writeWalkingFootage(dir);
  const json script = json::array({
      {{"open", json::array({f.video.string(), f.keyframes.string()})}},
      {{"track_video", {{"first", 0}, {"last", -1}}}},
      {{"wait_frames", 3}},
      {{"export_video",
        {{"path", path("tracked.avi")}, {"cycles", 0.5}, {"width", 1280}, {"height", 720}}}},
  });
  const auto file = writeScript(dir, script.dump(2));
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(file.string()));
  ASSERT_EQ(r.exitCode, 0) << r.out << r.err;
  cv::VideoCapture cap(path("tracked.avi"));
  cv::Mat frame;
  ASSERT_TRUE(cap.read(frame));
  // The footage's mid-grey noise (values 40-200, mean 120; dimmed under the track) fills the
  // middle of the left half, where the views' background is near black (about 20).
  cv::Mat grey;
  cv::cvtColor(frame(cv::Rect(80, 250, 480, 220)), grey, cv::COLOR_BGR2GRAY);
  EXPECT_GT(cv::mean(grey)[0], 60.0) << "the footage under the track";
  const int title = countPixels(frame(cv::Rect(10, 10, 220, 40)), [](int rr, int g, int b) {
    return rr > 200 && g > 200 && b > 200;
  });
  EXPECT_GT(title, 150) << "the caption \"2D input (video)\"";
}

// Issue 18's layout in video mode (issue 14): at the teaching sizes, with a track and its fit,
// every drawer tab holds (nothing cut), and the 2D view's caption and legend stay off the
// walker: the footage is framed between them, or they give way (the subtitle to a tooltip,
// the legend to its tab).
TEST_F(GuiVideo, VideoModeHoldsAtTheTeachingSizes) {
  const Footage f = writeWalkingFootage(dir);
  for (const LayoutCell& c : teachingCells()) {
    const std::string cell = std::string(c.size) + " scale " + c.scale + " " + c.theme;
    json script = json::array({{{"set_theme", c.theme}},
                               {{"open", json::array({f.video.string(), f.keyframes.string()})}},
                               {{"track_video", {{"first", 0}, {"last", -1}}}},
                               {{"video_frame", 45}}});
    for (const json& step : everyTabStates(dir, "video")) script.push_back(step);
    const RunResult r =
        runViewer(dir, std::string("--size ") + c.size + " --ui-scale " + c.scale + " --script " +
                           quote(writeScript(dir, script.dump()).string()));
    ASSERT_EQ(r.exitCode, 0) << cell << "\n" << r.err;
    for (const auto& tab : drawerTabs())
      expectLayoutHolds(state("video_" + tab + ".json"), cell + ", video, " + tab, {"input"});
  }
}

}  // namespace
}  // namespace ew::test::gui

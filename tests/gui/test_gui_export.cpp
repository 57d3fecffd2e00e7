// Exports from the viewer, end to end: PNG of the window and of each view, a video of both
// views (reopened with cv::VideoCapture), the displayed walker as CSV and BVH (read back
// through core's loaders), the leave-one-out model (loaded back), and failures reported
// as script errors.

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <opencv2/videoio.hpp>
#include <regex>

#include "core/eigenwalker/model_file.h"
#include "core/io/bvh_reader.h"
#include "core/io/joint_csv.h"
#include "core/mapping/joint_mapping.h"
#include "tests/common/test_support.h"
#include "tests/gui/gui_run.h"

namespace ew::test::gui {
namespace {

using GuiExport = GuiTest;

// Frames of one video (decoded one by one) and its size.
struct VideoFacts {
  int frames = 0, width = 0, height = 0;
  double meanIntensity = 0.0;
};

VideoFacts decode(const std::filesystem::path& file) {
  VideoFacts f;
  cv::VideoCapture cap(file.string());
  if (!cap.isOpened()) return f;
  cv::Mat frame;
  double sum = 0.0;
  while (cap.read(frame)) {
    ++f.frames;
    f.width = frame.cols;
    f.height = frame.rows;
    const cv::Scalar m = cv::mean(frame);
    sum += (m[0] + m[1] + m[2]) / 3.0;
  }
  if (f.frames > 0) f.meanIntensity = sum / f.frames;
  return f;
}

int loggedVideoFrames(const std::string& err) {
  std::smatch m;
  const std::regex re("Exporting ([0-9]+) frames");
  return std::regex_search(err, m, re) ? std::stoi(m[1]) : -1;
}

TEST_F(GuiExport, ScriptExportsPngVideoCsvBvhAndModel) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"play": false},
    {"set_phase": 0.25},
    {"export_png": {"path": ")" + d + R"(/window.png", "view": "window"}},
    {"export_png": {"path": ")" + d + R"(/input.png", "view": "input"}},
    {"export_png": {"path": ")" + d + R"(/recon.png", "view": "reconstruction"}},
    {"export_video": {"path": ")" + d + R"(/walk.avi", "cycles": 1.5, "fps": 24, "width": 480, "height": 270}},
    {"export_csv": {"path": ")" + d + R"(/walker.csv", "cycles": 2}},
    {"export_bvh": ")" + d + R"(/walker.bvh"},
    {"export_model": ")" + d + R"(/model.ewm"}
  ])");
  const RunResult r = runViewer(dir, "--size 1600x900 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;

  // PNG: the whole window, and each view alone (smaller, with its figure).
  const cv::Mat window = cv::imread(d + "/window.png"), input = cv::imread(d + "/input.png"),
                recon = cv::imread(d + "/recon.png");
  ASSERT_FALSE(window.empty() || input.empty() || recon.empty());
  EXPECT_EQ(window.cols, 1600);
  EXPECT_EQ(window.rows, 900);
  EXPECT_LT(input.cols, 800);
  EXPECT_GT(input.cols, 200);
  EXPECT_LT(recon.cols, 800);
  EXPECT_GT(countPixels(input, isPointLight), 60) << "no point-lights in the 2D view PNG";
  EXPECT_GT(countPixels(recon, isAmber), 400) << "no reconstruction in the 3D view PNG";
  EXPECT_LT(countPixels(recon, isPointLight), countPixels(input, isPointLight));

  // Video: decodable, the requested size, the frame count the log announced.
  const VideoFacts v = decode(dir / "walk.avi");
  const int announced = loggedVideoFrames(r.err);
  std::printf("video: %d frames (announced %d), %dx%d, mean intensity %.1f\n", v.frames, announced, v.width,
              v.height, v.meanIntensity);
  EXPECT_EQ(v.width, 480);
  EXPECT_EQ(v.height, 270);
  EXPECT_EQ(v.frames, announced);
  EXPECT_GT(v.meanIntensity, 5.0) << "black video";
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_NE(entry.path().filename().string().rfind(".walk", 0), 0u) << "temporary file left: " << entry.path();

  // CSV: 15 joints, 2 cycles at 120 Hz; its length gives the stride frequency, which
  // must agree with the video's frame count = round(cycles · fps / strideHz).
  const RawTrial csv = readJointCsv(dir / "walker.csv");
  ASSERT_EQ(csv.pointCount(), 15);
  EXPECT_NEAR(csv.rateHz, 120.0, 1e-6);
  const double strideHz = 2.0 * 120.0 / csv.frameCount();
  EXPECT_NEAR(announced, 1.5 * 24.0 / strideHz, 1.0);
  EXPECT_GT(strideHz, 0.5);
  EXPECT_LT(strideHz, 1.5);
  // Plausible: the head is above the ankles by a person's height, in mm.
  const double headZ = csv.positionsMm.col(2).mean(), ankleZ = csv.positionsMm.col(3 * 14 + 2).mean();
  EXPECT_GT(headZ - ankleZ, 1200.0);
  EXPECT_LT(headZ - ankleZ, 2000.0);

  // BVH: read back and mapped to the 15 joints; same head height as the CSV.
  const JointTrial bvh = mapSkeletonJoints(readBvh(dir / "walker.bvh"));
  ASSERT_EQ(bvh.positionsMm.cols(), 45);
  EXPECT_GT(bvh.frameCount(), 100);
  EXPECT_TRUE(bvh.positionsMm.allFinite());

  // Model: the leave-one-out model of SYN005 (every walker but its own).
  const EigenwalkerModel model = loadModel(dir / "model.ewm");
  EXPECT_GT(model.walkerCount(), 3);
  for (const auto& id : model.walkerIds) EXPECT_EQ(id.find("SYN005"), std::string::npos) << id;
}

// Issue 14: the exported video says what the viewer says: each view's title and subtitle, the
// metrics, and each legend, burnt into every frame (ui/app/export_captions.h); "captions":
// false leaves the views bare. Text is counted as near-white pixels in the caption's corner
// (the title), under the 3D view's title (the metrics) and in the bottom-left corner (the legend).
TEST_F(GuiExport, VideoCaptionsAreBurntIntoTheFrames) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"select_subject": "SYN005"},
    {"export_video": {"path": ")" + d + R"(/captioned.avi", "cycles": 0.3, "fps": 24, "width": 1280, "height": 720}},
    {"export_video": {"path": ")" + d + R"(/bare.avi", "cycles": 0.3, "fps": 24, "width": 1280, "height": 720, "captions": false}}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  ASSERT_EQ(r.exitCode, 0) << r.err;
  const auto firstFrame = [&](const char* name) {
    cv::VideoCapture cap((dir / name).string());
    cv::Mat frame;
    cap.read(frame);
    return frame;
  };
  const cv::Mat captioned = firstFrame("captioned.avi"), bare = firstFrame("bare.avi");
  ASSERT_FALSE(captioned.empty() || bare.empty());
  const auto text = [](const cv::Mat& frame, cv::Rect where) {
    return countPixels(frame(where), [](int rr, int g, int b) { return rr > 200 && g > 200 && b > 200; });
  };
  const cv::Rect title(10, 10, 200, 40), metrics(650, 60, 500, 40), legend(10, 640, 220, 70);
  std::printf("near-white pixels captioned / bare: title %d / %d, metrics %d / %d, legend %d / %d\n",
              text(captioned, title), text(bare, title), text(captioned, metrics), text(bare, metrics),
              text(captioned, legend), text(bare, legend));
  EXPECT_GT(text(captioned, title), 150);
  EXPECT_GT(text(captioned, metrics), 150);
  EXPECT_GT(text(captioned, legend), 20);  // the input joints' white disc and dim labels
  EXPECT_LT(text(bare, title), 20);
  EXPECT_LT(text(bare, metrics), 20);
}

TEST_F(GuiExport, Mp4IsWrittenOrClearlyRefused) {
  const auto d = dir.string();
  const auto script = writeScript(dir, R"([
    {"export_video": {"path": ")" + d + R"(/walk.mp4", "cycles": 1, "fps": 15, "width": 320, "height": 180}}
  ])");
  const RunResult r = runViewer(dir, "--size 1280x720 --script " + quote(script.string()));
  if (r.exitCode == 0) {
    const VideoFacts v = decode(dir / "walk.mp4");
    EXPECT_EQ(v.width, 320);
    EXPECT_EQ(v.height, 180);
    EXPECT_EQ(v.frames, loggedVideoFrames(r.err));
  } else {
    EXPECT_NE(r.err.find("cannot write .mp4"), std::string::npos) << r.err;
    EXPECT_FALSE(std::filesystem::exists(dir / "walk.mp4"));
  }
}

TEST_F(GuiExport, FailuresAreScriptErrorsNotCrashes) {
  const auto script1 = writeScript(dir, R"([{"export_video": {"path": "/tmp/x.mkv"}}])");
  RunResult r = runViewer(dir, "--size 800x600 --script " + quote(script1.string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find(".avi"), std::string::npos) << r.err;

  const auto script2 = writeScript(dir, R"([{"export_png": "/proc/nonexistent/x.png"}])");
  r = runViewer(dir, "--size 800x600 --script " + quote(script2.string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("export_png"), std::string::npos) << r.err;

  const auto script3 = writeScript(dir, R"([{"export_csv": "/proc/nonexistent/x.csv"}])");
  r = runViewer(dir, "--size 800x600 --script " + quote(script3.string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("x.csv"), std::string::npos) << r.err;

  const auto script4 = writeScript(dir, R"([{"export_png": {"path": "a.png", "view": "sideways"}}])");
  r = runViewer(dir, "--size 800x600 --script " + quote(script4.string()));
  EXPECT_EQ(r.exitCode, 1) << r.err;
  EXPECT_NE(r.err.find("sideways"), std::string::npos) << r.err;
}

}  // namespace
}  // namespace ew::test::gui

// The video a pose estimator's output was made from, found beside it (video/video_beside.h):
// Ultralytics' run folder, a MediaPipe CSV beside its video, Pose2Sim's pose/ and videos/;
// and `eigenwalker-cli` taking YOLO labels' image size from that video.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <opencv2/videoio.hpp>

#include "tests/common/test_support.h"
#include "tests/keypoints/yolo_run.h"
#include "video/video_beside.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// Two grey MJPG frames of width x height: enough to open.
void writeVideo(const fs::path& file, int width, int height, double fps = 30.0) {
  fs::create_directories(file.parent_path());
  cv::VideoWriter out(file.string(), cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), fps, cv::Size(width, height));
  ASSERT_TRUE(out.isOpened()) << file;
  for (int f = 0; f < 2; ++f) out.write(cv::Mat(height, width, CV_8UC3, cv::Scalar(90, 90, 90)));
}

void writeText(const fs::path& file, const std::string& text) {
  fs::create_directories(file.parent_path());
  std::ofstream(file) << text;
}

TEST(VideoBeside, FoundWhereTheToolsPutIt) {
  const fs::path root = test::makeTempDir("video_beside");
  // Ultralytics: runs/pose/predict/{walk.avi, labels/walk_<frame>.txt}.
  const std::string label = test::labelLine(test::filmedCoco({}).frames[0]);
  writeText(root / "predict" / "labels" / "walk_1.txt", label);
  writeText(root / "predict" / "labels" / "walk_2.txt", label);
  writeVideo(root / "predict" / "walk.avi", 320, 240);
  for (const fs::path& p : {root / "predict", root / "predict" / "labels", root / "predict" / "labels" / "",
                            root / "predict" / "labels" / "walk_2.txt"}) {
    SCOPED_TRACE(p.string());
    const auto found = videoBesideKeypoints(p);
    ASSERT_TRUE(found.has_value());
    EXPECT_EQ(fs::path(found->file).filename(), "walk.avi");
    EXPECT_EQ(found->size.width, 320);
    EXPECT_EQ(found->size.height, 240);
  }
  // A MediaPipe CSV beside its video; Pose2Sim's pose/cam01_json beside videos/cam01.
  writeText(root / "mp" / "trial.csv", "frame,nose_x\n");
  writeVideo(root / "mp" / "trial.avi", 640, 360);
  EXPECT_EQ(videoBesideKeypoints(root / "mp" / "trial.csv")->size.width, 640);
  fs::create_directories(root / "p2s" / "pose" / "cam01_json");
  writeVideo(root / "p2s" / "videos" / "cam01.avi", 400, 600, 60.0);
  const auto p2s = videoBesideKeypoints(root / "p2s" / "pose" / "cam01_json");
  ASSERT_TRUE(p2s.has_value());
  EXPECT_EQ(p2s->file, (root / "p2s" / "videos" / "cam01.avi").string());
  EXPECT_EQ(p2s->size.height, 600);
  EXPECT_DOUBLE_EQ(p2s->fps, 60.0);
  // A file named like a video that is none is passed over; nothing else is guessed.
  writeText(root / "fake" / "walk.mp4", "not a video");
  writeText(root / "fake" / "walk.csv", "frame,nose_x\n");
  EXPECT_FALSE(videoBesideKeypoints(root / "fake" / "walk.csv").has_value());
  EXPECT_FALSE(videoBesideKeypoints(root / "elsewhere.csv").has_value());
}

// `reconstruct --unknown-camera` on Ultralytics' run folder: the labels' fractions become
// pixels by the annotated video's size, which the report says; without that video, the
// error says what is missing.
TEST(VideoBeside, TheCliReadsYoloLabelsByTheirVideosSize) {
  const fs::path run = test::writeYoloRun(test::filmedCoco({70, 71}), "yolo_cli_run");
  writeVideo(run / "walk.avi", test::kImage.width, test::kImage.height, 25.0);
  const fs::path out = run.parent_path() / (run.filename().string() + "_walk3d.csv");
  const test::ShellRun r = test::runCli("reconstruct --unknown-camera --input " + run.string() + " --out " +
                                            out.string() + " --json",
                                        run);
  ASSERT_EQ(r.exitCode, 0) << r.err;
  EXPECT_NE(r.err.find("the video beside " + run.string() + ": " + (run / "walk.avi").string() + " (1920x1080, 25 fps)"),
            std::string::npos)
      << r.err;
  const json report = json::parse(r.out.substr(r.out.find("\n{") + 1));
  EXPECT_EQ(report["format"], "YOLO pose labels");
  EXPECT_EQ(report["image_size_px"], json::array({1920, 1080}));
  EXPECT_EQ(report["image_size_from"], "the video (" + (run / "walk.avi").string() + ")");
  // The labels store no rate: the video's, not an assumed 30 fps.
  EXPECT_EQ(report["rate_hz"], 25.0);
  EXPECT_EQ(report["rate_from"], "the video (" + (run / "walk.avi").string() + ")");
  EXPECT_NEAR(report["alpha_deg"].get<double>(), 40.0, 5.0);  // filmed at 40°
  fs::remove(out);

  fs::remove(run / "walk.avi");
  const test::ShellRun missing = test::runCli("info " + run.string(), run);
  EXPECT_NE(missing.exitCode, 0);
  EXPECT_NE((missing.out + missing.err).find("fractions of the image"), std::string::npos) << missing.out << missing.err;
  const test::ShellRun given = test::runCli("info " + run.string() + " --image-size 1920x1080", run);
  EXPECT_EQ(given.exitCode, 0) << given.err;
  EXPECT_NE(given.out.find("YOLO pose labels"), std::string::npos) << given.out;
}

}  // namespace
}  // namespace ew

// Ultralytics YOLO pose labels (core/keypoints/yolo_pose_labels.cpp): a folder of per-frame
// .txt files, points as fractions of the image, placed by the frame numbers in the names;
// and the frames other per-frame formats leave out (OpenPose files, AlphaPose images with
// nobody) kept as frames with nobody. The labels are written here the way Ultralytics
// writes them (results.save_txt: "%g" numbers, a keypoint under 0.5 visibility at 0, 0).

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <sstream>
#include <string>
#include <vector>

#include "core/camera/clip_reconstruction.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"
#include "tests/keypoints/yolo_run.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

using test::FilmedCoco;
using test::filmedCoco;
using test::kImage;
using test::labelLine;
using test::writeYoloRun;

// The same detections in pixels as AlphaPose writes them ("<frame>.jpg", none for an image
// with nobody).
fs::path writeAlphaPose(const FilmedCoco& clip, const std::string& stem) {
  json list = json::array();
  for (std::size_t f = 0; f < clip.frames.size(); ++f) {
    if (!clip.seen[f]) continue;
    json flat = json::array();
    for (Eigen::Index i = 0; i < 17; ++i) flat.insert(flat.end(), {clip.frames[f](i, 0), clip.frames[f](i, 1), 0.93});
    list.push_back({{"image_id", std::to_string(f) + ".jpg"}, {"category_id", 1}, {"keypoints", flat}, {"score", 2.9}});
  }
  const fs::path file = test::makeTempDir(stem) / "alphapose-results.json";
  std::ofstream(file) << list.dump();
  return file;
}

// `line` with its numbers from the `fromEnd`-th last on replaced by `with`.
std::string replacedFromEnd(const std::string& line, std::size_t fromEnd, const std::vector<std::string>& with) {
  std::vector<std::string> words;
  std::istringstream in(line);
  for (std::string w; in >> w;) words.push_back(w);
  std::copy(with.begin(), with.end(), words.end() - static_cast<std::ptrdiff_t>(fromEnd));
  std::string out;
  for (const auto& w : words) out += (out.empty() ? "" : " ") + w;
  return out + "\n";
}

fs::path writeLabels(const std::string& stem, const std::vector<std::pair<std::string, std::string>>& files) {
  const fs::path dir = test::makeTempDir(stem);
  for (const auto& [name, text] : files) std::ofstream(dir / name) << text;
  return dir;
}

KeypointOptions sized(std::optional<double> fps = 30.0) {
  KeypointOptions k;
  k.fps = fps;
  k.imageSize = kImage;
  return k;
}

double jointU(const KeypointTrial& t, int frame, Joint j) { return t.jointsPx(frame, 2 * index(j)); }

// [SECTION] Reading ------------------------------------------------------------------------

// Ultralytics' run folder (labels/ beside the annotated video) opens as the clip; the
// fractions come back as the pixels they were, frames with no file are frames with nobody,
// and the walk reads and fits exactly as the same detections in pixels (AlphaPose) do.
TEST(YoloPoseLabels, ARunFolderReadsAsTheSameClipAsPixels) {
  const FilmedCoco clip = filmedCoco({0, 1, 60, 61, 62});
  const fs::path run = writeYoloRun(clip, "yolo_run");
  ASSERT_TRUE(yoloLabelsFolder(run).has_value());
  EXPECT_EQ(*yoloLabelsFolder(run), run / "labels");
  EXPECT_TRUE(looksLikeKeypointInput(run));
  EXPECT_TRUE(looksLikeKeypointInput(run / "labels"));

  const KeypointTrial yolo = readKeypointTrial(run, sized());
  EXPECT_EQ(yolo.format, "YOLO pose labels");
  EXPECT_EQ(yolo.layout->name, "COCO-17");
  // 150 frames: walk_1.txt is frame 0; frames 0, 1 and 60-62 have no file.
  EXPECT_EQ(yolo.frameCount, 150);
  ASSERT_TRUE(yolo.imageSize.has_value());
  EXPECT_EQ(yolo.imageSize->width, 1920);
  EXPECT_TRUE(std::isnan(jointU(yolo, 61, Joint::Pelvis)));
  EXPECT_TRUE(std::isnan(jointU(yolo, 0, Joint::Pelvis)));
  EXPECT_NEAR(jointU(yolo, 63, Joint::RKnee), clip.frames[63](14, 0), 1e-5);  // %.9g of a fraction
  const KeypointFrames raw = readKeypointFrames(run, kImage);
  ASSERT_EQ(raw.warnings.size(), 1u);
  EXPECT_NE(raw.warnings[0].find("5 of the 150 frames have no label file"), std::string::npos) << raw.warnings[0];

  const KeypointTrial alpha = readKeypointTrial(writeAlphaPose(clip, "yolo_alpha"), sized());
  EXPECT_EQ(alpha.frameCount, 148);  // AlphaPose's numbers start at its first image, "2.jpg"
  ASSERT_EQ(alpha.jointsPx.rows() + 2, yolo.jointsPx.rows());
  const Eigen::MatrixXd a = alpha.jointsPx, y = yolo.jointsPx.bottomRows(148);
  EXPECT_TRUE((a.array().isNaN() == y.array().isNaN()).all());
  EXPECT_LT((a - y).array().isNaN().select(0.0, (a - y).array().abs()).maxCoeff(), 1e-5);

  CameraFitOptions o;
  const ClipReconstruction fromYolo = reconstructKeypointClip(defaultRealModel(), run, sized(), o);
  const ClipReconstruction fromPixels = reconstructKeypointClip(defaultRealModel(), writeAlphaPose(clip, "yolo_alpha2"), sized(), o);
  EXPECT_NEAR(fromYolo.fit.camera.alphaDeg, fromPixels.fit.camera.alphaDeg, 0.01);
  EXPECT_NEAR(fromYolo.fit.camera.elevationDeg, fromPixels.fit.camera.elevationDeg, 0.01);
  EXPECT_NEAR(fromYolo.fit.camera.focalPx, fromPixels.fit.camera.focalPx, 0.5);
  // And the camera it was filmed with (azimuth 40°, 12° down; the face and the trunk are a
  // detector's points, not the model's joints, so not exactly).
  EXPECT_NEAR(fromYolo.fit.camera.alphaDeg, 40.0, 5.0);
  EXPECT_NEAR(fromYolo.fit.camera.elevationDeg, 12.0, 5.0);
}

// What follows the keypoints: a whole number in every line is the track id (`yolo track`),
// a fraction the box confidence (save_conf); both: confidence then id. A keypoint Ultralytics
// zeroed (visibility under 0.5) or of visibility 0 is absent; x, y without visibility read.
TEST(YoloPoseLabels, TrackIdsConfidencesAndAbsentPoints) {
  const FilmedCoco clip = filmedCoco({});
  const auto line = [&](int f, const std::string& extra) { return labelLine(clip.frames[static_cast<std::size_t>(f)], extra); };
  const fs::path tracked = writeLabels("yolo_track", {{"a_1.txt", line(0, " 3") + line(1, " 7")}, {"a_2.txt", line(2, " 3")}});
  KeypointFrames f = readKeypointFrames(tracked, kImage);
  ASSERT_EQ(f.frames.size(), 2u);
  ASSERT_EQ(f.frames[0].size(), 2u);
  EXPECT_EQ(f.frames[0][0].trackId, 3);
  EXPECT_EQ(f.frames[0][1].trackId, 7);

  const fs::path confident = writeLabels("yolo_conf", {{"a_1.txt", line(0, " 0.91")}, {"a_2.txt", line(1, " 1")}});
  f = readKeypointFrames(confident, kImage);
  EXPECT_EQ(f.frames[0][0].trackId, -1);
  EXPECT_EQ(f.pointCount, 17);

  const fs::path both = writeLabels("yolo_both", {{"a_1.txt", line(0, " 0.91 12")}});
  f = readKeypointFrames(both, kImage);
  EXPECT_EQ(f.frames[0][0].trackId, 12);

  // The right ankle (point 17) zeroed, the left (16) visibility 0; numbers from frame 0.
  const std::string zeroed = replacedFromEnd(replacedFromEnd(line(0, ""), 3, {"0", "0", "0.31"}), 6, {"0.4", "0.9", "0"});
  f = readKeypointFrames(writeLabels("yolo_zero", {{"b_000.txt", zeroed}, {"b_001.txt", line(1, "")}}), kImage);
  ASSERT_EQ(f.frames.size(), 2u);
  EXPECT_TRUE(std::isnan(f.frames[0][0].points(16, 0)));
  EXPECT_EQ(f.frames[0][0].points(16, 2), 0.0);
  EXPECT_TRUE(std::isnan(f.frames[0][0].points(15, 0)));
  EXPECT_NEAR(f.frames[0][0].points(14, 0), clip.frames[0](14, 0), 1e-5);
  EXPECT_NEAR(f.frames[0][0].points(14, 2), 0.93, 1e-12);

  // x y only (a model trained with kpt_shape [17, 2]): 5 + 34 numbers.
  std::string xy = "0 0.5 0.5 0.2 0.6";
  for (int i = 0; i < 17; ++i) xy += " 0.25 0.5";
  f = readKeypointFrames(writeLabels("yolo_xy", {{"c_1.txt", xy + "\n"}}), kImage);
  EXPECT_EQ(f.pointCount, 17);
  EXPECT_DOUBLE_EQ(f.frames[0][0].points(3, 0), 480.0);
  EXPECT_DOUBLE_EQ(f.frames[0][0].points(3, 1), 540.0);
  EXPECT_DOUBLE_EQ(f.frames[0][0].points(3, 2), 1.0);
}

// [SECTION] Bad input ----------------------------------------------------------------------

TEST(YoloPoseLabels, BadLabelsNameTheFileAndTheProblem) {
  const FilmedCoco clip = filmedCoco({});
  const std::string good = labelLine(clip.frames[0]);
  const fs::path ok = writeLabels("yolo_nosize", {{"w_1.txt", good}, {"w_2.txt", good}});
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(ok); }, ErrorKind::BadArgument,
                                {ok.string(), "fractions of the image", "size"}));
  EXPECT_TRUE(test::throwsError([&] { readKeypointTrial(ok); }, ErrorKind::BadArgument, {"size"}));

  // Pixels written where fractions belong.
  std::string pixels = "0 960 540 200 600";
  for (int i = 0; i < 17; ++i) pixels += " 900 500 0.9";
  const fs::path px = writeLabels("yolo_px", {{"w_1.txt", good}, {"w_2.txt", pixels + "\n"}});
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(px, kImage); }, ErrorKind::Malformed,
                                {"w_2.txt", "share of the image's side", "not pixels"}));

  const fs::path shorter = writeLabels("yolo_short", {{"w_1.txt", good}, {"w_2.txt", "0 0.5 0.5 0.2 0.6 0.1 0.2 0.9\n"}});
  // A line of 8 numbers is no label: the folder is still read as labels from its first file.
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(shorter, kImage); }, ErrorKind::Malformed,
                                {"w_2.txt", "line 1", "8 numbers where the first line had 56"}));

  const fs::path word = writeLabels("yolo_word", {{"w_1.txt", good}, {"w_2.txt", good + "0 0.5 zero" + good.substr(9)}});
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(word, kImage); }, ErrorKind::Malformed,
                                {"w_2.txt", "line 2", "'zero'", "not a finite number"}));

  const fs::path twice = writeLabels("yolo_twice", {{"a_1.txt", good}, {"b_1.txt", good}});
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(twice, kImage); }, ErrorKind::Malformed,
                                {"frame 1 has two label files", "a_1.txt", "b_1.txt"}));

  const fs::path unnumbered = writeLabels("yolo_unnumbered", {{"a_1.txt", good}, {"walk.txt", good}});
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(unnumbered, kImage); }, ErrorKind::Malformed,
                                {"walk.txt", "no frame number"}));

  // A frame number beyond the bounds allocates nothing.
  const fs::path far = writeLabels("yolo_far", {{"a_1.txt", good}, {"a_999999999.txt", good}});
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(far, kImage); }, ErrorKind::Malformed,
                                {"a_999999999.txt", "more than 216000 frames"}));

  // Text files that are no labels are not taken for them.
  const fs::path notes = writeLabels("yolo_notes", {{"readme.txt", "Trial 3, subject walked twice\n"}});
  EXPECT_FALSE(yoloLabelsFolder(notes).has_value());
  EXPECT_FALSE(looksLikeKeypointInput(notes));
  const fs::path detections = writeLabels("yolo_detect", {{"a_1.txt", "0 0.5 0.5 0.2 0.6\n"}});
  EXPECT_FALSE(yoloLabelsFolder(detections).has_value());  // a detector's boxes, no keypoints
}

// [SECTION] Frames other formats leave out -------------------------------------------------

// An OpenPose folder missing some files (deleted, or never written) keeps its timing: the
// missing frames are frames with nobody, said in a warning. Files without distinct numbers
// are taken in order, as before.
TEST(YoloPoseLabels, OpenPoseFilesMissingFromAFolderAreFramesWithNobody) {
  const KeypointLayout& body25 = keypointLayoutNamed("BODY_25");
  const fs::path dir = test::makeTempDir("op_gaps");
  for (int f : {0, 1, 2, 5, 6}) {
    json flat = json::array();
    for (std::size_t i = 0; i < body25.points.size(); ++i) flat.insert(flat.end(), {100.0 + f, 200.0 + static_cast<double>(i), 0.9});
    char name[64];
    std::snprintf(name, sizeof name, "clip_%012d_keypoints.json", f);
    std::ofstream(dir / name) << json{{"people", json::array({{{"pose_keypoints_2d", flat}}})}}.dump();
  }
  const KeypointFrames f = readKeypointFrames(dir);
  ASSERT_EQ(f.frames.size(), 7u);
  EXPECT_TRUE(f.frames[3].empty());
  EXPECT_TRUE(f.frames[4].empty());
  EXPECT_DOUBLE_EQ(f.frames[5][0].points(0, 0), 105.0);
  ASSERT_EQ(f.warnings.size(), 1u);
  EXPECT_NE(f.warnings[0].find("2 of the 7 frames have no file"), std::string::npos) << f.warnings[0];
}

}  // namespace
}  // namespace ew

// 2D TRC files (core/keypoints/planar_trc.cpp): points in the plane Z = 0 are a view of the
// walker, read as a keypoint clip. The files are written here the way Sports2D writes them
// (make_trc_with_XYZ: "Units m" whatever the numbers are; Pose2Sim's point names): its 0.5
// pixel files (X = u / 1000, Y = -v / 1000), its later ones (pixels as they are, Y down) and
// its metre files (Y up).

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

#include "core/camera/clip_reconstruction.h"
#include "core/common/errors.h"
#include "core/eigenwalker/default_model.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_summary.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"
#include "tests/keypoints/yolo_run.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// COCO-17's points as Pose2Sim names them (its TRC files' marker names).
const std::vector<std::string> kNames = {"Nose",      "LEye",      "REye",   "LEar",   "REar",  "LShoulder",
                                         "RShoulder", "LElbow",    "RElbow", "LWrist", "RWrist", "LHip",
                                         "RHip",      "LKnee",     "RKnee",  "LAnkle", "RAnkle"};

// (u, v) in pixels -> the file's (X, Y).
using ToFile = std::function<std::pair<double, double>(double u, double v)>;

fs::path writeTrc(const test::FilmedCoco& clip, const std::string& stem, const ToFile& toFile,
                  const std::function<double(int frame)>& z = [](int) { return 0.0; }) {
  const fs::path file = test::makeTempDir(stem) / "walk_Sports2D_px_person00.trc";
  std::ofstream out(file);
  out << "PathFileType\t4\t(X/Y/Z)\t" << file.filename().string() << "\n"
      << "DataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\tOrigDataRate\tOrigDataStartFrame\tOrigNumFrames\n"
      << "30\t30\t" << clip.frames.size() << "\t" << kNames.size() << "\tm\t30\t0\t" << clip.frames.size() << "\n"
      << "Frame#\tTime";
  for (const auto& n : kNames) out << "\t" << n << "\t\t";
  out << "\n\t";
  for (std::size_t i = 0; i < kNames.size(); ++i) out << "\tX" << i + 1 << "\tY" << i + 1 << "\tZ" << i + 1;
  out << "\n";
  out.precision(12);
  for (std::size_t f = 0; f < clip.frames.size(); ++f) {
    out << f << "\t" << static_cast<double>(f) / 30.0;
    for (Eigen::Index i = 0; i < 17; ++i) {
      const auto [x, y] = clip.seen[f] ? toFile(clip.frames[f](i, 0), clip.frames[f](i, 1)) : std::pair{0.0, 0.0};
      out << "\t" << x << "\t" << y << "\t" << z(static_cast<int>(f));
    }
    out << "\n";
  }
  return file;
}

// The same detections as pixels (AlphaPose JSON), read with no detector offsets: the joints
// a keypoint file gives, to compare with.
KeypointTrial asPixels(const test::FilmedCoco& clip) {
  nlohmann::json list = nlohmann::json::array();
  for (std::size_t f = 0; f < clip.frames.size(); ++f) {
    nlohmann::json flat = nlohmann::json::array();
    for (Eigen::Index i = 0; i < 17; ++i) flat.insert(flat.end(), {clip.frames[f](i, 0), clip.frames[f](i, 1), 0.9});
    list.push_back({{"image_id", std::to_string(f) + ".jpg"}, {"keypoints", flat}});
  }
  const fs::path file = test::makeTempDir("planar_alpha") / "alphapose-results.json";
  std::ofstream(file) << list.dump();
  KeypointOptions k;
  k.fps = 30.0;
  k.detectorOffsets = false;
  return readKeypointTrial(file, k);
}

double largestDifference(const Eigen::MatrixXd& a, const Eigen::MatrixXd& b) {
  EXPECT_TRUE((a.array().isNaN() == b.array().isNaN()).all());
  return (a - b).array().isNaN().select(0.0, (a - b).array().abs()).maxCoeff();
}

// Each of Sports2D's three ways gives the walker's joints in the image as the pixels did (the
// metre file up to its scale), and fits the camera the clip was filmed with.
TEST(PlanarTrc, SportsTwoDsFilesReadAsTheViewTheyHold) {
  const test::FilmedCoco clip = test::filmedCoco({});
  const KeypointTrial pixels = asPixels(clip);
  const fs::path old = writeTrc(clip, "planar_px05", [](double u, double v) { return std::pair{u / 1000, -v / 1000}; });
  const fs::path later = writeTrc(clip, "planar_px", [](double u, double v) { return std::pair{u, v}; });
  const fs::path metres = writeTrc(clip, "planar_m", [](double u, double v) { return std::pair{u / 500, (1080 - v) / 500}; });
  for (const fs::path& f : {old, later, metres}) {
    SCOPED_TRACE(f.parent_path().filename().string());
    EXPECT_TRUE(isPlanarTrc(f));
    EXPECT_TRUE(looksLikeKeypointInput(f));
  }
  const KeypointTrial fromOld = readKeypointTrial(old);
  EXPECT_EQ(fromOld.format, "TRC (2D)");
  EXPECT_EQ(fromOld.frameCount, 150);
  EXPECT_DOUBLE_EQ(fromOld.rateHz, 30.0);
  EXPECT_EQ(fromOld.rateSource, "the file");
  EXPECT_LT(largestDifference(fromOld.jointsPx, pixels.jointsPx), 1e-6);
  const KeypointTrial fromLater = readKeypointTrial(later);
  EXPECT_LT(largestDifference(fromLater.jointsPx, pixels.jointsPx), 1e-6);
  EXPECT_NE(std::find_if(fromLater.warnings.begin(), fromLater.warnings.end(),
                         [](const std::string& w) { return w.find("read as pixels") != std::string::npos; }),
            fromLater.warnings.end());
  // Metres: 2 mm a pixel, the image upside up.
  const KeypointTrial fromMetres = readKeypointTrial(metres);
  Eigen::MatrixXd inPixels = fromMetres.jointsPx / 2.0;
  for (int j = 0; j < kJointCount; ++j) inPixels.col(2 * j + 1).array() += 1080.0;
  EXPECT_LT(largestDifference(inPixels, pixels.jointsPx), 1e-6);

  CameraFitOptions o;
  const ClipReconstruction c = reconstructKeypointTrial(defaultRealModel(), fromOld, o);
  EXPECT_NEAR(c.fit.camera.alphaDeg, 40.0, 3.0);  // filmed at 40°, 12° down
  EXPECT_NEAR(c.fit.camera.elevationDeg, 12.0, 3.0);

  const TrialSummary s = summarizeKeypoints(old);
  EXPECT_TRUE(s.error.empty()) << s.error;
  EXPECT_EQ(s.format, "TRC (2D)");
  EXPECT_NEAR(s.strideHz, test::kFilmedStrideHz, 0.05);
}

// A 3D TRC is no view; a file whose points leave the plane after the first frames says where.
TEST(PlanarTrc, ThreeDimensionalFilesAreNotViews) {
  const test::FilmedCoco clip = test::filmedCoco({});
  const auto mm = [](double u, double v) { return std::pair{u, -v}; };
  EXPECT_FALSE(isPlanarTrc(writeTrc(clip, "planar_3d", mm, [](int f) { return 100.0 + f; })));
  EXPECT_FALSE(looksLikeKeypointInput(writeTrc(clip, "planar_3d_input", mm, [](int f) { return 100.0 + f; })));
  const fs::path leaves = writeTrc(clip, "planar_leaves", mm, [](int f) { return f < 149 ? 0.0 : 0.25; });
  EXPECT_TRUE(isPlanarTrc(leaves));  // the first 64 KiB are in the plane
  EXPECT_TRUE(test::throwsError([&] { readKeypointTrial(leaves); }, ErrorKind::BadData,
                                {leaves.string(), "frame 150", "Nose", "neither a 2D view nor a 3D walk"}));
  // A 3D TRC given where keypoints are expected says what it is.
  const fs::path deep = writeTrc(clip, "planar_deep", mm, [](int f) { return 100.0 + f; });
  EXPECT_TRUE(test::throwsError([&] { readKeypointTrial(deep); }, ErrorKind::BadArgument,
                                {deep.string(), "3D points", "not a pose estimator's 2D keypoints"}));
  // Missing points written as 0, 0, 0 (Sports2D's gaps) are absent, not in the plane; a joint
  // built from one of them (the pelvis, between the hips) too.
  test::FilmedCoco gappy = clip;
  for (int f = 40; f < 45; ++f) gappy.seen[static_cast<std::size_t>(f)] = false;
  gappy.frames[50].row(11).setZero();  // the left hip
  const KeypointTrial t = readKeypointTrial(writeTrc(gappy, "planar_gaps", mm));
  EXPECT_TRUE(std::isnan(t.jointsPx(42, 2 * index(Joint::Pelvis))));
  EXPECT_FALSE(std::isnan(t.jointsPx(45, 2 * index(Joint::Pelvis))));
  EXPECT_TRUE(std::isnan(t.jointsPx(50, 2 * index(Joint::LHip))));
  EXPECT_TRUE(std::isnan(t.jointsPx(50, 2 * index(Joint::Pelvis))));
  EXPECT_FALSE(std::isnan(t.jointsPx(50, 2 * index(Joint::RHip))));
}

}  // namespace
}  // namespace ew

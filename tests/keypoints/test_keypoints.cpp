// Pose-estimator keypoint files (core/keypoints): the layout tables, the OpenPose, AlphaPose
// and MMPose readers on fixtures written here, following the walker among several people,
// guessing BODY_25 from BODY_25B, confidence, malformed input, and the real Pose2Sim files.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/keypoints/keypoint_frames.h"
#include "core/keypoints/keypoint_layout.h"
#include "core/keypoints/keypoint_trial.h"
#include "tests/common/error_matchers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

// [SECTION] Fixtures ----------------------------------------------------------------------

// A stick figure facing the camera, in pixels (y down): head 100, shoulders 200, hips 400,
// knees 550, ankles 700; its right on the image's left. Named points of every layout
// (BODY_25's "RShoulder", COCO's "right_shoulder", MediaPipe's "right_foot_index" …).
std::pair<double, double> figurePoint(std::string name) {
  for (const auto& [from, to] : {std::pair{"right_", "R"}, std::pair{"left_", "L"}}) {
    if (name.rfind(from, 0) == 0) {
      name = to + name.substr(std::string(from).size());
      name[1] = static_cast<char>(std::toupper(static_cast<unsigned char>(name[1])));
    }
  }
  const double side = name[0] == 'R' ? -1 : name[0] == 'L' ? 1 : 0;
  const std::string part = side != 0 ? name.substr(1) : name;
  static const std::map<std::string, std::pair<double, double>> at = {
      {"Nose", {0, 110}},     {"Eye", {8, 95}},        {"Ear", {16, 100}},     {"Neck", {0, 200}},
      {"UpperNeck", {0, 170}}, {"HeadTop", {0, 60}},   {"Shoulder", {40, 200}}, {"Elbow", {50, 300}},
      {"Wrist", {55, 390}},   {"MidHip", {0, 400}},    {"Hip", {20, 400}},     {"Knee", {22, 550}},
      {"Ankle", {22, 700}},   {"BigToe", {25, 730}},   {"SmallToe", {35, 730}}, {"Heel", {20, 715}},
      {"head", {0, 80}},      {"neck", {0, 190}},      {"hip", {0, 400}}};
  for (const auto& [key, p] : at) {
    if (part == key || part.find(key) != std::string::npos) return {side * p.first, p.second};
  }
  return {side * 30, 150};  // MediaPipe's eye corners, mouth, fingers: near the head
}

// The layout's points for a figure whose centre is at x0, as a flat x, y, c list.
json figure(const KeypointLayout& layout, double x0, double confidence = 0.9) {
  json flat = json::array();
  for (const auto& name : layout.points) {
    const auto [x, y] = figurePoint(name);
    flat.push_back(x0 + x);
    flat.push_back(y);
    flat.push_back(confidence);
  }
  return flat;
}

// A clip of `frames`: a walker crossing from x 200 at 12 px a frame, and (when `bystander`)
// a person standing at x 1500.
fs::path openPoseFolder(const std::string& stem, const KeypointLayout& layout, int frames, bool bystander) {
  const fs::path dir = test::makeTempDir(stem);
  for (int f = 0; f < frames; ++f) {
    json people = json::array();
    if (bystander) people.push_back({{"person_id", {-1}}, {"pose_keypoints_2d", figure(layout, 1500)}});
    people.push_back({{"person_id", {-1}}, {"pose_keypoints_2d", figure(layout, 200 + 12.0 * f)}});
    char name[64];
    std::snprintf(name, sizeof name, "clip_%012d_keypoints.json", f);
    std::ofstream(dir / name) << json{{"version", 1.3}, {"people", people}}.dump();
  }
  return dir;
}

fs::path writeText(const std::string& stem, const std::string& name, const std::string& text) {
  const fs::path file = test::makeTempDir(stem) / name;
  std::ofstream(file) << text;
  return file;
}

KeypointOptions options(std::optional<std::string> layout, std::optional<double> fps = {},
                        double minConfidence = 0.3) {
  KeypointOptions o;
  o.layout = std::move(layout);
  o.fps = fps;
  o.minConfidence = minConfidence;
  return o;
}

double jointU(const KeypointTrial& t, int frame, Joint j) { return t.jointsPx(frame, 2 * index(j)); }
double jointV(const KeypointTrial& t, int frame, Joint j) { return t.jointsPx(frame, 2 * index(j) + 1); }

// [SECTION] Layouts -------------------------------------------------------------------------

// The orders as the tools document them (OpenPose doc/02_output.md; openpose_train
// BODY_25B; COCO; Halpe; MediaPipe Pose).
TEST(KeypointLayouts, PointsAreInTheToolsOrder) {
  const auto at = [](const char* layout, int i) { return keypointLayoutNamed(layout).points.at(static_cast<std::size_t>(i)); };
  EXPECT_EQ(at("BODY_25", 1), "Neck");
  EXPECT_EQ(at("BODY_25", 8), "MidHip");
  EXPECT_EQ(at("BODY_25", 14), "LAnkle");
  EXPECT_EQ(at("BODY_25", 24), "RHeel");
  EXPECT_EQ(at("BODY_25B", 5), "LShoulder");
  EXPECT_EQ(at("BODY_25B", 17), "UpperNeck");
  EXPECT_EQ(at("BODY_25B", 18), "HeadTop");
  EXPECT_EQ(at("COCO-18", 8), "RHip");
  EXPECT_EQ(at("COCO-17", 0), "nose");
  EXPECT_EQ(at("COCO-17", 16), "right_ankle");
  EXPECT_EQ(at("Halpe-26", 19), "hip");
  EXPECT_EQ(at("MediaPipe-33", 23), "left_hip");
  EXPECT_EQ(at("MediaPipe-33", 32), "right_foot_index");
  EXPECT_EQ(keypointLayoutsWithPoints(25).size(), 2u);
  EXPECT_EQ(&keypointLayoutNamed("body25b"), &keypointLayoutNamed("BODY_25B"));
  EXPECT_TRUE(test::throwsError([] { keypointLayoutNamed("BODY_99"); }, ErrorKind::BadArgument,
                                {"BODY_99", "BODY_25B", "MediaPipe-33"}));
}

TEST(KeypointLayouts, MalformedTablesNameTheFileAndKey) {
  const auto key = [](const std::string& text) {
    try {
      parseKeypointLayout(text, "l.json");
    } catch (const Error& e) {
      EXPECT_EQ(e.file(), "l.json");
      return e.position();
    }
    return std::string("accepted");
  };
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {"pelvis": [["A"]]}})"), "accepted");
  EXPECT_EQ(key("["), "");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A", "A"], "joints": {}})"), "points");
  // A text field of another type: once nlohmann's own type_error, no Error naming the key.
  EXPECT_EQ(key(R"({"name": "x", "about": 5, "points": ["A"], "joints": {"pelvis": [["A"]]}})"), "about");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {"tail": [["A"]]}})"), "joints.tail");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {"pelvis": [["B"]]}})"), "joints.pelvis[0]");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {"pelvis": [[]]}})"), "joints.pelvis[0]");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {}, "feet": {"r_heel": [["A"]]}})"), "accepted");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {}, "feet": [1]})"), "feet");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {}, "feet": {"r_knee": [["A"]]}})"), "feet.r_knee");
  EXPECT_EQ(key(R"({"name": "x", "points": ["A"], "joints": {}, "feet": {"l_toe": [["B"]]}})"), "feet.l_toe[0]");
}

// [SECTION] Readers and cleaning ------------------------------------------------------------

TEST(Keypoints, OpenPoseFolderFollowsTheWalkerAndGuessesBody25) {
  const fs::path dir = openPoseFolder("op_body25", keypointLayoutNamed("BODY_25"), 40, true);
  const KeypointTrial t = readKeypointTrial(dir, options({}, 25.0));
  EXPECT_EQ(t.format, "OpenPose JSON");
  EXPECT_EQ(t.frameCount, 40);
  EXPECT_EQ(t.maxPeople, 2);
  ASSERT_EQ(t.people.size(), 2u);
  EXPECT_NEAR(t.people[static_cast<std::size_t>(t.chosen)].travelPx, 12.0 * 39, 1e-9);
  EXPECT_EQ(t.layout->name, "BODY_25");
  EXPECT_NE(t.layoutSource.find("guessed: upright in 100 % of checks as BODY_25 (BODY_25B"), std::string::npos)
      << t.layoutSource;
  EXPECT_DOUBLE_EQ(t.rateHz, 25.0);
  EXPECT_FALSE(t.rateAssumed);
  // Frame 10: the walker's centre at x 320. Pelvis is BODY_25's MidHip, sternum the
  // shoulders' midpoint, head the ears' midpoint; right joints on the image's left.
  EXPECT_DOUBLE_EQ(jointU(t, 10, Joint::Pelvis), 320);
  EXPECT_DOUBLE_EQ(jointV(t, 10, Joint::Pelvis), 400);
  EXPECT_DOUBLE_EQ(jointV(t, 10, Joint::Sternum), 200);
  EXPECT_DOUBLE_EQ(jointV(t, 10, Joint::Head), 100);
  EXPECT_DOUBLE_EQ(jointU(t, 10, Joint::RKnee), 298);
  EXPECT_DOUBLE_EQ(jointU(t, 10, Joint::LAnkle), 342);
  EXPECT_TRUE(t.derived[static_cast<std::size_t>(index(Joint::Head))]);
  EXPECT_FALSE(t.derived[static_cast<std::size_t>(index(Joint::RKnee))]);
  for (double s : t.seenShare) EXPECT_DOUBLE_EQ(s, 1.0);
  // The bystander keeps his joints too (what the viewer draws of the people not chosen):
  // the same layout's reading, one row per frame he is in.
  const PersonTrack& bystander = t.people[static_cast<std::size_t>(1 - t.chosen)];
  ASSERT_EQ(bystander.jointsPx.rows(), 40);
  EXPECT_EQ(personRowAt(bystander, 10), 10);
  EXPECT_EQ(personRowAt(bystander, 40), -1);
  EXPECT_DOUBLE_EQ(bystander.jointsPx(10, 2 * index(Joint::Pelvis)), 1500);
  EXPECT_DOUBLE_EQ(bystander.jointsPx(10, 2 * index(Joint::Head) + 1), 100);
  const PersonTrack& walker = t.people[static_cast<std::size_t>(t.chosen)];
  EXPECT_TRUE(walker.jointsPx.row(10).isApprox(t.jointsPx.row(10)));
}

// The feet beside the joints: BODY_25's heel, and the mean of its big and small toes (the big toe
// alone where the small one is not seen); a layout without feet has none.
TEST(Keypoints, HeelsAndToesAreCarriedBesideTheJoints) {
  const KeypointLayout& body25 = keypointLayoutNamed("BODY_25");
  const fs::path dir = openPoseFolder("op_feet", body25, 30, false);
  // Frame 12: the left small toe under the confidence threshold.
  json frame = json::parse(test::readTextFile(dir / "clip_000000000012_keypoints.json"));
  const auto smallToe = std::find(body25.points.begin(), body25.points.end(), "LSmallToe") - body25.points.begin();
  frame["people"][0]["pose_keypoints_2d"][3 * smallToe + 2] = 0.1;
  std::ofstream(dir / "clip_000000000012_keypoints.json") << frame.dump();
  const KeypointTrial t = readKeypointTrial(dir, options("BODY_25", 25.0));
  ASSERT_EQ(t.feetPx.rows(), 30);
  ASSERT_EQ(t.feetPx.cols(), 2 * kFootPointCount);
  const auto at = [&](int f, FootPoint p) { return Eigen::Vector2d(t.feetPx.row(f).segment<2>(2 * index(p)).transpose()); };
  // Frame 10: the walker's centre at x 320, its right on the image's left.
  EXPECT_TRUE(at(10, FootPoint::RHeel).isApprox(Eigen::Vector2d(300, 715)));
  EXPECT_TRUE(at(10, FootPoint::RToe).isApprox(Eigen::Vector2d(290, 730)));  // big toe 295, small 285
  EXPECT_TRUE(at(10, FootPoint::LToe).isApprox(Eigen::Vector2d(350, 730)));
  EXPECT_TRUE(at(12, FootPoint::LToe).isApprox(Eigen::Vector2d(344 + 25, 730)));  // the big toe alone
  // COCO-18 has no foot points: no feet, the joints as before.
  const KeypointTrial coco = readKeypointTrial(openPoseFolder("op_nofeet", keypointLayoutNamed("COCO-18"), 30, false),
                                               options("COCO-18", 25.0));
  EXPECT_EQ(coco.feetPx.size(), 0);
  EXPECT_FALSE(keypointLayoutNamed("COCO-17").hasFeet());
  for (const char* withFeet : {"BODY_25", "BODY_25B", "Halpe-26", "MediaPipe-33"})
    EXPECT_TRUE(keypointLayoutNamed(withFeet).hasFeet()) << withFeet;
}

TEST(Keypoints, Body25bIsToldFromBody25AndLayoutOverrides) {
  const fs::path dir = openPoseFolder("op_body25b", keypointLayoutNamed("BODY_25B"), 20, false);
  const KeypointTrial t = readKeypointTrial(dir);
  EXPECT_EQ(t.layout->name, "BODY_25B");
  EXPECT_TRUE(t.rateAssumed);
  EXPECT_DOUBLE_EQ(t.rateHz, kDefaultKeypointFps);
  EXPECT_DOUBLE_EQ(jointV(t, 0, Joint::RShoulder), 200);
  // Read as BODY_25 on the user's word: no guess, and the figure comes out scrambled.
  const KeypointTrial forced = readKeypointTrial(dir, options("body_25"));
  EXPECT_EQ(forced.layout->name, "BODY_25");
  EXPECT_EQ(forced.layoutSource, "given (--layout)");
  EXPECT_NE(jointV(forced, 0, Joint::RShoulder), 200);
  EXPECT_TRUE(test::throwsError([&] { readKeypointTrial(dir, options("COCO-17")); }, ErrorKind::BadArgument,
                                {"COCO-17 has 17 points, the file 25"}));
}

TEST(Keypoints, AlphaPoseCoco17ListGroupsDetectionsByImage) {
  const KeypointLayout& coco = keypointLayoutNamed("COCO-17");
  json list = json::array();
  for (int f = 0; f < 12; ++f) {
    list.push_back({{"image_id", std::to_string(f) + ".jpg"}, {"category_id", 1},
                    {"keypoints", figure(coco, 100 + 10.0 * f)}, {"score", 2.9}});
  }
  const KeypointTrial t = readKeypointTrial(writeText("alphapose", "alphapose-results.json", list.dump()));
  EXPECT_EQ(t.format, "AlphaPose JSON");
  EXPECT_EQ(t.frameCount, 12);
  EXPECT_EQ(t.layout->name, "COCO-17");
  EXPECT_EQ(t.layoutSource, "the only layout with 17 points");
  EXPECT_DOUBLE_EQ(jointU(t, 11, Joint::Pelvis), 210);  // the hips' midpoint
  EXPECT_TRUE(t.derived[static_cast<std::size_t>(index(Joint::Pelvis))]);
}

// Issue 53: AlphaPose writes `[]` for a video with nobody in it. Its reader took the first
// and last image of none (begin()/rbegin() of an empty map) and the command line called the
// file "not a keypoint file": it is "no person detected", from the reader and the file alike.
TEST(Keypoints, AnEmptyAlphaPoseListIsNoPersonDetected) {
  EXPECT_TRUE(test::throwsError([] { parseAlphaPoseJson("[]", "alphapose-results.json"); }, ErrorKind::BadData,
                                {"alphapose-results.json", "no person detected"}));
  EXPECT_TRUE(test::throwsError([] { parseAlphaPoseJson(" [ ]\n", "a.json"); }, ErrorKind::BadData, {"no person detected"}));
  const fs::path file = writeText("alphapose_nobody", "alphapose-results.json", "[]\n");
  EXPECT_TRUE(looksLikeKeypointInput(file));
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(file); }, ErrorKind::BadData,
                                {file.string(), "no person detected (an empty list of detections)"}));
  // The other formats' empty results say the same.
  EXPECT_TRUE(test::throwsError([] { parseMmposeJson("[]", "m.json"); }, ErrorKind::BadData, {"no person detected"}));
  EXPECT_TRUE(test::throwsError([] { parseOpenPoseFrames({{"f_0.json", R"({"people": []})"}}, "op"); },
                                ErrorKind::BadData, {"no person detected"}));
}

TEST(Keypoints, MmposeVideoResultsStateTheirLayout) {
  const KeypointLayout& coco = keypointLayoutNamed("COCO-17");
  json frames = json::array();
  for (int f = 0; f < 10; ++f) {
    const json flat = figure(coco, 300 + 5.0 * f);
    json kp = json::array(), scores = json::array();
    for (std::size_t i = 0; i < flat.size(); i += 3) {
      kp.push_back({flat[i], flat[i + 1]});
      scores.push_back(0.8);
    }
    frames.push_back({{"frame_id", f + 1}, {"instances", {{{"keypoints", kp}, {"keypoint_scores", scores}}}}});
  }
  const json doc = {{"meta_info", {{"dataset_name", "coco"}}}, {"instance_info", frames}};
  const KeypointTrial t = readKeypointTrial(writeText("mmpose", "results_walk.json", doc.dump()));
  EXPECT_EQ(t.format, "MMPose JSON");
  EXPECT_EQ(t.layoutSource, "stated by the file");
  EXPECT_DOUBLE_EQ(jointV(t, 9, Joint::LKnee), 550);
}

TEST(Keypoints, PointsBelowTheConfidenceAreMissing) {
  const KeypointLayout& coco = keypointLayoutNamed("COCO-17");
  json list = json::array();
  for (int f = 0; f < 10; ++f) {
    json kp = figure(coco, 100 + 10.0 * f);
    kp[3 * 10 + 2] = 0.1;  // right_wrist, never confident
    list.push_back({{"image_id", f}, {"keypoints", kp}});
  }
  const KeypointTrial t = readKeypointTrial(writeText("conf", "a.json", list.dump()));
  EXPECT_TRUE(t.missing[static_cast<std::size_t>(index(Joint::RWrist))]);
  EXPECT_FALSE(t.missing[static_cast<std::size_t>(index(Joint::LWrist))]);
  ASSERT_FALSE(t.warnings.empty());
  EXPECT_NE(t.warnings.back().find("never seen above confidence 0.30: r_wrist"), std::string::npos)
      << t.warnings.back();
  // Lowering the threshold lets it in.
  EXPECT_FALSE(readKeypointTrial(writeText("conf2", "a.json", list.dump()), options({}, {}, 0.05))
                   .missing[static_cast<std::size_t>(index(Joint::RWrist))]);
}

TEST(Keypoints, MalformedInputNamesTheFileAndTheFrame) {
  const auto expectError = [](const fs::path& p, ErrorKind kind, std::initializer_list<std::string_view> parts) {
    EXPECT_TRUE(test::throwsError([&] { readKeypointTrial(p); }, kind, parts)) << p;
  };
  expectError(writeText("bad1", "x.json", "{\"people\": [ {"), ErrorKind::Malformed, {"x.json", "not JSON"});
  expectError(writeText("bad2", "x.json", R"({"people": [{"pose_keypoints_2d": [1, 2]}]})"), ErrorKind::Malformed,
              {"x.json", "people[0]", "triples"});
  expectError(writeText("bad3", "x.json", R"({"people": [{"pose_keypoints_2d": [1, "a", 1]}]})"),
              ErrorKind::Malformed, {"numbers"});
  expectError(writeText("bad4", "x.json", R"({"people": []})"), ErrorKind::BadData, {"x.json", "no person detected"});
  expectError(writeText("bad5", "x.json", R"({"frames": 3})"), ErrorKind::Malformed, {"not a keypoint file"});
  expectError(writeText("bad6", "x.json", R"([{"image_id": 0, "keypoints": [1, 2, 1, 3, 4, 1]},
                                             {"image_id": 1, "keypoints": [1, 2, 1]}])"),
              ErrorKind::Malformed, {"detection 1", "1 keypoints where earlier detections had 2"});
  // 20 points: no layout has that many.
  json twenty = json::array();
  for (int i = 0; i < 60; ++i) twenty.push_back(10.0 + i);
  expectError(writeText("bad7", "x.json", json{{"people", {{{"pose_keypoints_2d", twenty}}}}}.dump()),
              ErrorKind::BadData, {"20 keypoints per person", "BODY_25"});
  // A folder whose frame 3 is broken: the file is named.
  const fs::path dir = openPoseFolder("bad8", keypointLayoutNamed("BODY_25"), 6, false);
  std::ofstream(dir / "clip_000000000003_keypoints.json") << "{\"people\": 7}";
  expectError(dir, ErrorKind::Malformed, {"clip_000000000003_keypoints.json", "\"people\" list"});
  expectError(test::makeTempDir("empty_kp"), ErrorKind::BadData, {"no .json files"});
}

TEST(Keypoints, WalkNeedsPelvisKneesAndAnkles) {
  const KeypointLayout& coco = keypointLayoutNamed("COCO-17");
  json list = json::array();
  for (int f = 0; f < 10; ++f) {
    json kp = figure(coco, 100 + 10.0 * f);
    for (int ankle : {15, 16}) kp[static_cast<std::size_t>(3 * ankle + 2)] = 0.0;  // a clip cut at the shins
    list.push_back({{"image_id", f}, {"keypoints", kp}});
  }
  EXPECT_TRUE(test::throwsError([&] { readKeypointTrial(writeText("noankles", "a.json", list.dump())); },
                                ErrorKind::BadData, {"a.json", "r_ankle", "never seen", "pelvis, knees and ankles"}));
}

// [SECTION] Real data --------------------------------------------------------------------------

// Pose2Sim's balancing trial: OpenPose BODY_25B from four cameras, 100 frames each; cam01
// shows a second person in the background and a one-frame false detection. Measured: BODY_25
// reads 66-77 % upright, BODY_25B 98-100 %.
TEST(Keypoints, Pose2SimFoldersAreBody25bWithTheSubjectFollowed) {
  EW_REQUIRE_SHARED_DATA();
  for (int cam = 1; cam <= 4; ++cam) {
    const fs::path dir = test::sharedDataDir() / "pose2sim-balancing" / "pose" /
                         ("cam0" + std::to_string(cam) + "_json");
    SCOPED_TRACE(dir.string());
    const KeypointTrial t = readKeypointTrial(dir);
    EXPECT_EQ(t.frameCount, 100);
    EXPECT_EQ(t.layout->name, "BODY_25B");
    const PersonTrack& subject = t.people[static_cast<std::size_t>(t.chosen)];
    EXPECT_EQ(subject.frames.size(), 100u);
    EXPECT_GT(subject.sizePx, 600.0);  // the subject fills the portrait frame; the bystander ~460 px
    for (Joint j : {Joint::Pelvis, Joint::RKnee, Joint::LKnee, Joint::RAnkle, Joint::LAnkle})
      EXPECT_GT(t.seenShare[static_cast<std::size_t>(index(j))], 0.95) << jointName(j);
    // Not a walk: nobody crosses the image, and the program says so.
    EXPECT_NE(std::find_if(t.warnings.begin(), t.warnings.end(),
                           [](const std::string& w) { return w.find("nobody in the clip moves") == 0; }),
              t.warnings.end());
  }
  const KeypointTrial cam1 = readKeypointTrial(test::sharedDataDir() / "pose2sim-balancing/pose/cam01_json");
  EXPECT_EQ(cam1.maxPeople, 3);
  EXPECT_EQ(cam1.people.size(), 3u);
}

}  // namespace
}  // namespace ew

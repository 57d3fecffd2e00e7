// CSV keypoint files (core/keypoints/keypoint_csv.cpp): MediaPipe Pose exports (normalised
// coordinates, image size, time column) and DeepLabCut analyses (user-named body parts, a
// joint mapping file, multi-animal individuals), on fixtures written here; malformed rows;
// the project's own joint CSVs not taken for keypoints.

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <tuple>
#include <utility>
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

// [SECTION] Fixtures ----------------------------------------------------------------------

constexpr double kImageW = 1920, kImageH = 1080;

// A stick figure facing the camera centred at x0, in pixels (y down), by body-part name:
// MediaPipe's "left_hip", COCO's "right_knee", our DeepLabCut names "hip_l", "knee_r".
// Right on the image's left; the right hip 10 px lower than the left, so a pelvis that is
// their mean is told from either.
std::pair<double, double> bodyPoint(std::string name, double x0) {
  for (char& c : name) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const bool left = name.find("left") != std::string::npos || name.ends_with("_l");
  const bool right = name.find("right") != std::string::npos || name.ends_with("_r");
  const double side = left ? 1 : right ? -1 : 0;
  const std::vector<std::tuple<std::string, double, double>> parts = {
      {"hip", 20, 400},      {"knee", 22, 550},  {"ankle", 22, 700}, {"heel", 20, 715},
      {"foot", 30, 730},     {"shoulder", 40, 200}, {"elbow", 50, 300}, {"wrist", 55, 390}};
  for (const auto& [part, dx, y] : parts) {
    if (name.find(part) != std::string::npos) return {x0 + side * dx, y + (part == "hip" && right ? 10 : 0)};
  }
  return {x0 + side * 10, 100};  // the head's points (nose, eyes, ears, mouth) and fingers
}

fs::path writeText(const std::string& stem, const std::string& name, const std::string& text) {
  const fs::path file = test::makeTempDir(stem) / name;
  std::ofstream(file) << text;
  return file;
}

// MediaPipe's export: frame, time_s at 25 fps, x, y, z, visibility per landmark, a walker
// crossing from x 200 at 12 px a frame. Frame 3 lacks the left wrist (empty cells) and the
// right wrist (nan).
std::string mediaPipeCsv(int frames) {
  std::ostringstream out;
  out.precision(17);
  out << "frame,time_s";
  const auto& names = keypointLayoutNamed("MediaPipe-33").points;
  for (const auto& n : names) out << "," << n << "_x," << n << "_y," << n << "_z," << n << "_visibility";
  out << "\n";
  for (int f = 0; f < frames; ++f) {
    out << f << "," << f / 25.0;
    for (const auto& n : names) {
      const auto [x, y] = bodyPoint(n, 200 + 12.0 * f);
      if (f == 3 && n == "left_wrist") out << ",,,,";
      else if (f == 3 && n == "right_wrist") out << ",nan,nan,nan,nan";
      else out << "," << x / kImageW << "," << y / kImageH << ",-0.1,0.9";
    }
    out << "\n";
  }
  return out.str();
}

// A DeepLabCut analysis CSV. `groups`: (individual, body parts); one group with an empty
// individual is a single-animal file. `centre(group, frame)` places each group's figure.
std::string dlcCsv(const std::vector<std::pair<std::string, std::vector<std::string>>>& groups, int frames,
                   const std::function<double(int, int)>& centre) {
  const bool multi = !groups.front().first.empty();
  std::ostringstream scorer, individuals, parts, coords, rows;
  scorer << "scorer";
  individuals << "individuals";
  parts << "bodyparts";
  coords << "coords";
  for (const auto& [individual, names] : groups) {
    for (const auto& n : names) {
      for (int k = 0; k < 3; ++k) {
        scorer << ",DLC_resnet50_walkOct1shuffle1_100000";
        individuals << "," << individual;
        parts << "," << n;
      }
      coords << ",x,y,likelihood";
    }
  }
  for (int f = 0; f < frames; ++f) {
    rows << f;
    for (std::size_t g = 0; g < groups.size(); ++g) {
      for (const auto& n : groups[g].second) {
        const auto [x, y] = bodyPoint(n, centre(static_cast<int>(g), f));
        rows << "," << x << "," << y << ",0.95";
      }
    }
    rows << "\n";
  }
  return scorer.str() + "\n" + (multi ? individuals.str() + "\n" : "") + parts.str() + "\n" + coords.str() + "\n" +
         rows.str();
}

const std::vector<std::string> kDlcParts = {"snout",  "shoulder_l", "shoulder_r", "hip_l",  "hip_r",
                                            "knee_l", "knee_r",     "ankle_l",    "ankle_r"};

double walking(int, int frame) { return 200 + 12.0 * frame; }

// Every joint named, the arms absent: as mapping_file.h asks.
std::string mappingJson(const std::string& leftKnee = "knee_l") {
  return R"({"eigenwalker_joint_mapping": 1, "joints": {
    "head": "snout", "sternum": ["shoulder_l", "shoulder_r"], "pelvis": ["hip_l", "hip_r"],
    "r_shoulder": "shoulder_r", "r_elbow": null, "r_wrist": null,
    "l_shoulder": "shoulder_l", "l_elbow": null, "l_wrist": null,
    "r_hip": "hip_r", "r_knee": "knee_r", "r_ankle": "ankle_r",
    "l_hip": "hip_l", "l_knee": ")" +
         leftKnee + R"(", "l_ankle": "ankle_l"}})";
}

KeypointOptions withMapping(const fs::path& mapping) {
  KeypointOptions o;
  o.mappingFile = mapping;
  return o;
}

double jointU(const KeypointTrial& t, int frame, Joint j) { return t.jointsPx(frame, 2 * index(j)); }
double jointV(const KeypointTrial& t, int frame, Joint j) { return t.jointsPx(frame, 2 * index(j) + 1); }
bool flag(const std::array<bool, kJointCount>& flags, Joint j) { return flags[static_cast<std::size_t>(index(j))]; }

// The lines of `text`, line `number` (1-based) replaced by what `edit` makes of it.
std::string editLine(const std::string& text, int number, const std::function<std::string(std::string)>& edit) {
  std::istringstream in(text);
  std::string line, out;
  for (int n = 1; std::getline(in, line); ++n) out += (n == number ? edit(line) : line) + "\n";
  return out;
}

// [SECTION] MediaPipe ---------------------------------------------------------------------

TEST(KeypointCsv, MediaPipeWithImageSizeIsInPixelsWithItsRate) {
  const fs::path file = writeText("mp_csv", "pose.csv", "# MediaPipe Pose\n# image_size=1920x1080\n" + mediaPipeCsv(20));
  const KeypointFrames frames = readKeypointFrames(file);
  EXPECT_EQ(frames.format, "MediaPipe CSV");
  EXPECT_EQ(frames.layoutHint, "MediaPipe-33");
  EXPECT_EQ(frames.pointCount, 33);
  EXPECT_TRUE(frames.pointNames.empty());
  ASSERT_EQ(frames.frameCount(), 20);
  ASSERT_EQ(frames.frames[5].size(), 1u);
  const Eigen::MatrixX3d& p5 = frames.frames[5][0].points;
  EXPECT_NEAR(p5(23, 0), 260 + 20, 1e-9);  // left_hip
  EXPECT_NEAR(p5(24, 1), 410, 1e-9);       // right_hip
  EXPECT_DOUBLE_EQ(p5(23, 2), 0.9);
  const Eigen::MatrixX3d& p3 = frames.frames[3][0].points;
  for (int wrist : {15, 16}) {
    EXPECT_TRUE(std::isnan(p3(wrist, 0)) && std::isnan(p3(wrist, 1))) << wrist;
    EXPECT_EQ(p3(wrist, 2), 0.0);
  }
  ASSERT_TRUE(frames.rateHz.has_value());
  EXPECT_NEAR(*frames.rateHz, 25.0, 1e-6);

  const KeypointTrial t = cleanKeypoints(frames);
  EXPECT_EQ(t.layout->name, "MediaPipe-33");
  EXPECT_EQ(t.layoutSource, "stated by the file");
  EXPECT_NEAR(t.rateHz, 25.0, 1e-6);
  EXPECT_FALSE(t.rateAssumed);
  EXPECT_NEAR(jointU(t, 10, Joint::Pelvis), 320, 1e-9);
  EXPECT_NEAR(jointV(t, 10, Joint::Pelvis), 405, 1e-9);
  EXPECT_NEAR(jointU(t, 10, Joint::RKnee), 298, 1e-9);
  // --fps is the user's word over the file's times.
  KeypointOptions fps;
  fps.fps = 50.0;
  EXPECT_DOUBLE_EQ(cleanKeypoints(frames, fps).rateHz, 50.0);
  // The size given by the caller instead of the comment.
  const KeypointFrames given = parseMediaPipeCsv(mediaPipeCsv(4), "given.csv", KeypointImageSize{960, 540});
  EXPECT_NEAR(given.frames[1][0].points(23, 0), (212 + 20) / 2.0, 1e-9);
}

TEST(KeypointCsv, MediaPipeWithoutImageSizeIsRefused) {
  const fs::path file = writeText("mp_nosize", "pose.csv", mediaPipeCsv(5));
  EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(file); }, ErrorKind::BadArgument,
                                {"pose.csv", "give the image size", "image_size=1920x1080"}));
  EXPECT_TRUE(test::throwsError([&] { parseMediaPipeCsv("# image_size=1920 by 1080\n" + mediaPipeCsv(5), "s.csv"); },
                                ErrorKind::Malformed, {"s.csv", "line 1", "WIDTHxHEIGHT"}));
  EXPECT_TRUE(test::throwsError([&] { parseMediaPipeCsv(mediaPipeCsv(5), "z.csv", KeypointImageSize{0, 1080}); },
                                ErrorKind::BadArgument, {"z.csv", "0x1080"}));
}

// The size given as an option (the CLI's --image-size) reaches the reader through the
// trial path; "WxH" is checked.
TEST(KeypointCsv, ImageSizeOptionReachesTheReader) {
  const fs::path file = writeText("mp_option", "pose.csv", mediaPipeCsv(5));
  KeypointOptions o;
  o.imageSize = parseKeypointImageSize("1280x720", "--image-size");
  EXPECT_EQ(readKeypointFrames(file, o.imageSize).format, "MediaPipe CSV");
  EXPECT_TRUE(test::throwsError([] { parseKeypointImageSize("1280 by 720", "--image-size"); }, ErrorKind::BadArgument,
                                {"--image-size", "like 1920x1080"}));
  EXPECT_TRUE(test::throwsError([] { parseKeypointImageSize("0x720", "--image-size"); }, ErrorKind::BadArgument,
                                {"each side must be 1-100000 px"}));
}

// [SECTION] DeepLabCut --------------------------------------------------------------------

TEST(KeypointCsv, DeepLabCutWithMappingFileBuildsTheJoints) {
  const fs::path dir = test::makeTempDir("dlc_mapping");
  std::ofstream(dir / "dlc.csv") << dlcCsv({{"", kDlcParts}}, 20, walking);
  std::ofstream(dir / "map.json") << mappingJson();
  const KeypointFrames frames = readKeypointFrames(dir / "dlc.csv");
  EXPECT_EQ(frames.format, "DeepLabCut CSV");
  EXPECT_EQ(frames.pointNames, kDlcParts);
  EXPECT_EQ(frames.pointCount, 9);
  EXPECT_FALSE(frames.rateHz.has_value());

  const KeypointTrial t = cleanKeypoints(frames, withMapping(dir / "map.json"));
  EXPECT_EQ(t.layout->points, kDlcParts);
  EXPECT_NE(t.layoutSource.find("joint mapping file"), std::string::npos) << t.layoutSource;
  EXPECT_TRUE(t.rateAssumed);
  EXPECT_DOUBLE_EQ(jointU(t, 10, Joint::Pelvis), 320);  // mean of hip_l (340, 400) and hip_r (300, 410)
  EXPECT_DOUBLE_EQ(jointV(t, 10, Joint::Pelvis), 405);
  EXPECT_DOUBLE_EQ(jointV(t, 10, Joint::Sternum), 200);
  EXPECT_DOUBLE_EQ(jointU(t, 10, Joint::Head), 320);
  EXPECT_DOUBLE_EQ(jointU(t, 10, Joint::RKnee), 298);
  EXPECT_DOUBLE_EQ(jointV(t, 10, Joint::LAnkle), 700);
  EXPECT_TRUE(flag(t.derived, Joint::Pelvis));
  EXPECT_FALSE(flag(t.derived, Joint::RKnee));
  EXPECT_TRUE(flag(t.missing, Joint::RElbow));
  EXPECT_FALSE(flag(t.missing, Joint::LKnee));
  // A name the file does not have: the mapping file and the joint are named.
  std::ofstream(dir / "map_bad.json") << mappingJson("knee_left");
  EXPECT_TRUE(test::throwsError([&] { cleanKeypoints(frames, withMapping(dir / "map_bad.json")); },
                                ErrorKind::BadArgument, {"map_bad.json", "joints.l_knee", "knee_left", "knee_l"}));
}

TEST(KeypointCsv, DeepLabCutWithoutMappingListsTheBodyParts) {
  const fs::path file = writeText("dlc_nomap", "dlc.csv", dlcCsv({{"", kDlcParts}}, 10, walking));
  EXPECT_TRUE(test::throwsError([&] { readKeypointTrial(file); }, ErrorKind::BadData,
                                {"dlc.csv", "snout", "hip_l", "ankle_r", "mapping file"}));
}

TEST(KeypointCsv, DeepLabCutNamesOfAKnownLayoutNeedNoMapping) {
  // COCO-17's names in another order and case: its joints, re-indexed.
  std::vector<std::string> names = keypointLayoutNamed("COCO-17").points;
  std::reverse(names.begin(), names.end());
  names[0] = "RIGHT_ANKLE";
  const KeypointTrial t = readKeypointTrial(writeText("dlc_coco", "dlc.csv", dlcCsv({{"", names}}, 12, walking)));
  EXPECT_EQ(t.layout->name, "COCO-17");
  EXPECT_EQ(t.layout->points, names);
  EXPECT_EQ(t.layoutSource, "the file's point names are COCO-17's");
  EXPECT_DOUBLE_EQ(jointV(t, 5, Joint::Pelvis), 405);
  EXPECT_DOUBLE_EQ(jointU(t, 5, Joint::RAnkle), 260 - 22);
  EXPECT_DOUBLE_EQ(jointU(t, 5, Joint::LAnkle), 260 + 22);
}

TEST(KeypointCsv, MultiAnimalDeepLabCutFollowsTheWalker) {
  const fs::path dir = test::makeTempDir("dlc_multi");
  // ind1 stands at x 1500, ind2 walks; "single" holds a unique body part (nobody's).
  const auto centre = [](int group, int frame) { return group == 0 ? 1500.0 : 200 + 12.0 * frame; };
  std::ofstream(dir / "multi.csv") << dlcCsv({{"ind1", kDlcParts}, {"ind2", kDlcParts}, {"single", {"ball"}}}, 30, centre);
  std::ofstream(dir / "map.json") << mappingJson();
  const KeypointFrames frames = readKeypointFrames(dir / "multi.csv");
  ASSERT_EQ(frames.frames[0].size(), 2u);
  EXPECT_EQ(frames.frames[0][1].trackId, 1);
  EXPECT_EQ(frames.pointNames, kDlcParts);
  ASSERT_EQ(frames.warnings.size(), 1u);
  EXPECT_NE(frames.warnings[0].find("unique body parts not used (no individual's): ball"), std::string::npos);

  const KeypointTrial t = cleanKeypoints(frames, withMapping(dir / "map.json"));
  EXPECT_EQ(t.maxPeople, 2);
  ASSERT_EQ(t.people.size(), 2u);
  EXPECT_NEAR(t.people[static_cast<std::size_t>(t.chosen)].travelPx, 12.0 * 29, 1e-9);
  EXPECT_DOUBLE_EQ(jointU(t, 10, Joint::Pelvis), 320);
  EXPECT_DOUBLE_EQ(jointU(t, 29, Joint::LKnee), 200 + 12.0 * 29 + 22);
}

// [SECTION] Malformed input and sniffing ----------------------------------------------------

TEST(KeypointCsv, MalformedRowsNameTheFileAndLine) {
  const auto expectMalformed = [](const std::string& name, const std::string& text,
                                  std::initializer_list<std::string_view> parts) {
    const fs::path file = writeText("csv_bad", name, text);
    EXPECT_TRUE(test::throwsError([&] { readKeypointFrames(file); }, ErrorKind::Malformed, parts)) << name;
  };
  const std::string mp = "# image_size=640x480\n" + mediaPipeCsv(4);
  expectMalformed("mp_text.csv", editLine(mp, 4, [](std::string l) { return l.replace(l.find(",0.9"), 4, ",abc"); }),
                  {"mp_text.csv", "line 4", "'abc' is not a finite number"});
  expectMalformed("mp_short.csv", editLine(mp, 5, [](std::string l) { return l.substr(0, l.rfind(',')); }),
                  {"mp_short.csv", "line 5", "short row"});
  expectMalformed("mp_header.csv", editLine(mp, 2, [](std::string l) { return l.replace(l.find("left_knee_x"), 11, "lknee_x"); }),
                  {"mp_header.csv", "line 2", "left_knee_x/_y"});
  const std::string dlc = dlcCsv({{"", kDlcParts}}, 4, walking);
  expectMalformed("dlc_short.csv", editLine(dlc, 6, [](std::string l) { return l.substr(0, l.rfind(',')); }),
                  {"dlc_short.csv", "line 6", "short row: 27 fields where the header has 28"});
  expectMalformed("dlc_inf.csv", editLine(dlc, 5, [](std::string l) { return l.replace(l.rfind(','), 5, ",inf"); }),
                  {"dlc_inf.csv", "line 5", "'inf' is not a finite number"});
  expectMalformed("dlc_index.csv", editLine(dlc, 4, [](std::string l) { return "img0" + l.substr(1); }),
                  {"dlc_index.csv", "line 4", "frame index 'img0'"});
  expectMalformed("dlc_coords.csv", editLine(dlc, 3, [](std::string l) { return l.replace(l.find(",y,"), 3, ",z,"); }),
                  {"dlc_coords.csv", "line 3", "x, y, likelihood"});
  expectMalformed("dlc_parts.csv", editLine(dlc, 2, [](std::string l) { return l.replace(l.find(",snout"), 6, ",nose"); }),
                  {"dlc_parts.csv", "line 2", "three columns"});
  expectMalformed("other.csv", "time,a,b\n0,1,2\n", {"other.csv", "not a keypoint CSV"});
  std::string tooLong = "scorer,s,s,s\nbodyparts,p,p,p\ncoords,x,y,likelihood\n";
  for (int f = 0; f <= kMaxKeypointFrames; ++f) tooLong += std::to_string(f) + ",1,2,0.9\n";
  expectMalformed("long.csv", tooLong, {"long.csv", "more than 216000 frames"});
}

TEST(KeypointCsv, OnlyMediaPipeAndDeepLabCutCsvsAreKeypoints) {
  std::string joints3d = "frame,time_s", joints2d = "frame,time_s";
  for (const auto name : kJointNames) {
    joints3d += "," + std::string(name) + "_x," + std::string(name) + "_y," + std::string(name) + "_z";
    joints2d += "," + std::string(name) + "_u," + std::string(name) + "_v";
  }
  EXPECT_FALSE(looksLikeKeypointInput(writeText("own3d", "walk.csv", joints3d + "\n0,0" + std::string(45, ',') + "\n")));
  EXPECT_FALSE(looksLikeKeypointInput(writeText("own2d", "walk2d.csv", joints2d + "\n")));
  EXPECT_FALSE(looksLikeKeypointInput(test::makeTempDir("nocsv") / "absent.csv"));
  EXPECT_TRUE(looksLikeKeypointInput(writeText("mp_sniff", "pose.CSV", "# image_size=10x10\n\n" + mediaPipeCsv(2))));
  EXPECT_TRUE(looksLikeKeypointInput(writeText("dlc_sniff", "dlc.csv", "\xEF\xBB\xBF" + dlcCsv({{"", kDlcParts}}, 2, walking))));
  EXPECT_EQ(keypointCsvKind("frame,time_s,head_x,head_y,head_z\n"), KeypointCsvKind::NotKeypoints);
  EXPECT_EQ(keypointCsvKind("# nose_x\nframe,nose_x,nose_y,left_eye_inner_x\n"), KeypointCsvKind::MediaPipe);
  // A joint CSV whose columns are misnamed "nose" is not MediaPipe: its own reader says why.
  EXPECT_EQ(keypointCsvKind("frame,time_s,nose_x,nose_y,nose_z\n"), KeypointCsvKind::NotKeypoints);
  EXPECT_EQ(keypointCsvKind("Scorer,a,a,a\n"), KeypointCsvKind::DeepLabCut);
  EXPECT_EQ(keypointCsvKind(""), KeypointCsvKind::NotKeypoints);
  // A MediaPipe file cut down to a few landmarks is still one (issue 53).
  EXPECT_EQ(keypointCsvKind("nose_x,nose_y,nose_z,nose_visibility\n"), KeypointCsvKind::MediaPipe);
  EXPECT_EQ(keypointCsvKind("frame,left_hip_x,left_hip_y,right_hip_x,right_hip_y\n"), KeypointCsvKind::MediaPipe);
}

// Issue 53: a MediaPipe CSV of one landmark holding a NaN was taken for a 15-joint CSV ("header
// has 4 columns, expected 47"); it is read as MediaPipe's and refused naming what it lacks.
TEST(KeypointCsv, AFewLandmarksHoldingANaNAreAMediaPipeFileThatLacksTheRest) {
  const fs::path file = writeText("mp_few", "few.csv", "nose_x,nose_y,nose_z,nose_visibility\nNaN,NaN,NaN,NaN\n");
  ASSERT_TRUE(looksLikeKeypointInput(file));
  try {
    readKeypointFrames(file, KeypointImageSize{640, 480});
    FAIL() << "accepted";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed);
    EXPECT_EQ(e.file(), file.string());
    EXPECT_NE(std::string(e.what()).find("MediaPipe landmark columns missing: left_eye_inner_x/_y"), std::string::npos)
        << e.what();
    EXPECT_EQ(std::string(e.what()).find("expected 47"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ew

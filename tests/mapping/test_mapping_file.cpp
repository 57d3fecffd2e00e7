// User joint mapping files (core/mapping/mapping_file.h): parse, typed errors naming the
// file and the key, write and read back, apply to a trial (absent joints missing), the
// Data window's label table with a suggestion, and `info --mapping` end to end.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "core/common/errors.h"
#include "core/io/load_trial.h"
#include "core/mapping/mapping_file.h"
#include "core/mapping/marker_sets.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// [SECTION] Fixtures ----------------------------------------------------------------------

// The 15 joints as JSON with `overrides` replacing entries ("null" for all others).
std::string mappingText(const std::vector<std::pair<std::string, std::string>>& overrides,
                        const std::string& version = "1") {
  std::ostringstream out;
  out << "{\"eigenwalker_joint_mapping\": " << version << ", \"joints\": {";
  for (int j = 0; j < kJointCount; ++j) {
    const std::string name(kJointNames[static_cast<std::size_t>(j)]);
    std::string value = "null";
    for (const auto& [k, v] : overrides) {
      if (k == name) value = v;
    }
    out << (j ? ", " : "") << "\"" << name << "\": " << value;
  }
  out << "}}";
  return out.str();
}

const std::vector<std::pair<std::string, std::string>> kLowerBody = {
    {"pelvis", R"(["A_PELV", "P_PELV"])"},
    {"l_hip", "\"LHIPC\""},
    {"r_hip", "\"RHIPC\""},
    {"l_knee", "\"LKNEEC\""},
    {"r_knee", "\"RKNEEC\""},
    {"l_ankle", "\"LANKC\""},
    {"r_ankle", "\"RANKC\""}};

// Markers a lab named its own way, moving forward at 1.2 m/s (100 Hz, 150 frames).
RawTrial ownLabTrial() {
  RawTrial raw;
  raw.file = "own.c3d";
  raw.format = "C3D";
  raw.rateHz = 100;
  raw.units = "mm";
  const std::vector<std::pair<std::string, Eigen::Vector3d>> points = {
      {"A_PELV", {40, 0, 950}},   {"P_PELV", {-120, 0, 950}}, {"LHIPC", {-40, 85, 910}},
      {"RHIPC", {-40, -85, 910}}, {"LKNEEC", {0, 90, 520}},   {"RKNEEC", {0, -90, 520}},
      {"LANKC", {0, 80, 90}},     {"RANKC", {0, -80, 90}},    {"HEADTOP", {0, 0, 1750}}};
  raw.positionsMm.resize(150, 3 * static_cast<int>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    raw.labels.push_back(points[k].first);
    for (int f = 0; f < 150; ++f) {
      Eigen::Vector3d p = points[k].second;
      p.x() += 12.0 * f;
      raw.positionsMm.block<1, 3>(f, 3 * static_cast<int>(k)) = p.transpose();
    }
  }
  return raw;
}

void expectMalformed(const std::string& text, const std::string& key, const std::string& what) {
  try {
    parseJointMapping(text, "map.json");
    ADD_FAILURE() << "accepted: " << text;
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Malformed) << e.what();
    EXPECT_EQ(e.file(), "map.json");
    EXPECT_EQ(e.position(), key) << e.what();
    EXPECT_NE(std::string(e.what()).find(what), std::string::npos) << e.what();
  }
}

// [SECTION] Parsing -------------------------------------------------------------------------

TEST(MappingFile, ParsesNamesMeansAndAbsentJoints) {
  const JointMapping m = parseJointMapping(mappingText(kLowerBody), "map.json");
  EXPECT_EQ(m.joints[index(Joint::Pelvis)], (std::vector<std::string>{"A_PELV", "P_PELV"}));
  EXPECT_EQ(m.joints[index(Joint::LKnee)], (std::vector<std::string>{"LKNEEC"}));
  EXPECT_TRUE(m.joints[index(Joint::Head)].empty());
}

TEST(MappingFile, MalformedFilesNameTheFileAndTheKey) {
  expectMalformed("{\"eigenwalker_joint_mapping\": 1, ", "", "not JSON");
  expectMalformed("[1, 2]", "", "JSON object");
  expectMalformed(R"({"joints": {}})", "eigenwalker_joint_mapping", "missing");
  expectMalformed(mappingText(kLowerBody, "2"), "eigenwalker_joint_mapping", "version 2");
  expectMalformed(mappingText(kLowerBody, "\"1\""), "eigenwalker_joint_mapping", "version");
  expectMalformed(R"({"eigenwalker_joint_mapping": 1})", "joints", "missing");
  expectMalformed(mappingText({{"l_knee", "42"}}), "joints.l_knee", "a label, a list");
  expectMalformed(mappingText({{"l_knee", "[]"}}), "joints.l_knee", "empty list");
  expectMalformed(mappingText({{"l_knee", "\"\""}}), "joints.l_knee", "empty label");
  expectMalformed(mappingText({{"pelvis", R"(["LASI", 3])"}}), "joints.pelvis", "strings");
  expectMalformed(mappingText({{"pelvis", R"(["LASI", "lasi"])"}}), "joints.pelvis", "twice");
  std::string unknown = mappingText({});
  unknown.insert(unknown.find("\"head\""), "\"left_knee\": \"LKNE\", ");
  expectMalformed(unknown, "joints.left_knee", "unknown joint name");
  std::string dropped = mappingText({});
  dropped.replace(dropped.find("\"l_ankle\": null"), 15, "\"l_ankle_x\": null");
  expectMalformed(dropped, "joints.l_ankle_x", "unknown joint name");
  const std::string missingOne = R"({"eigenwalker_joint_mapping": 1, "joints": {"pelvis": "A"}})";
  expectMalformed(missingOne, "joints.head", "every joint must be listed");
}

TEST(MappingFile, WritesWhatItReads) {
  const fs::path dir = test::makeTempDir("mapping_roundtrip");
  const JointMapping m = parseJointMapping(mappingText(kLowerBody), "map.json");
  writeJointMappingFile(dir / "m.json", m);
  const JointMapping back = readJointMappingFile(dir / "m.json");
  EXPECT_EQ(back.joints, m.joints);
  EXPECT_NE(jointMappingToJson(m).find("\"head\": null"), std::string::npos);
  EXPECT_NE(jointMappingToJson(m).find("\"l_knee\": \"LKNEEC\""), std::string::npos);
  try {
    readJointMappingFile(dir / "absent.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
  }
}

// [SECTION] Applying ------------------------------------------------------------------------

TEST(MappingFile, AppliesMeansAndLeavesAbsentJointsMissing) {
  const JointMapping m = parseJointMapping(mappingText(kLowerBody), "map.json");
  const JointTrial t = applyJointMapping(ownLabTrial(), m, "map.json");
  EXPECT_EQ(t.source, "joint mapping map.json");
  EXPECT_LT((jointAt(t.positionsMm, 0, Joint::Pelvis) - Eigen::Vector3d(-40, 0, 950)).norm(), 1e-9);
  EXPECT_LT((jointAt(t.positionsMm, 10, Joint::RKnee) - Eigen::Vector3d(120, -90, 520)).norm(),
            1e-9);
  for (Joint j : {Joint::Head, Joint::Sternum, Joint::LShoulder, Joint::RWrist}) {
    EXPECT_TRUE(t.missing[index(j)]) << jointName(j);
    EXPECT_TRUE(std::isnan(t.positionsMm(0, 3 * index(j))));
  }
  EXPECT_FALSE(t.missing[index(Joint::LAnkle)]);
}

TEST(MappingFile, LabelsNotInTheTrialAndTooFewJointsAreTypedErrors) {
  auto withTypo = kLowerBody;
  withTypo[3].second = "\"LKNEE_C\"";
  try {
    applyJointMapping(ownLabTrial(), parseJointMapping(mappingText(withTypo), "m.json"), "m.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadArgument);
    EXPECT_EQ(e.file(), "m.json");
    EXPECT_EQ(e.position(), "joints.l_knee");
    EXPECT_NE(std::string(e.what()).find("'LKNEE_C' is not in own.c3d"), std::string::npos);
  }
  auto noAnkles = kLowerBody;
  noAnkles.resize(5);
  try {
    applyJointMapping(ownLabTrial(), parseJointMapping(mappingText(noAnkles), "m.json"), "m.json");
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::UnknownMarkerSet);
    EXPECT_NE(std::string(e.what()).find("missing l_ankle, r_ankle"), std::string::npos)
        << e.what();
  }
}

// [SECTION] The Data window's label table ------------------------------------------------------

TEST(MappingFile, LabelTableSuggestsFromTheRecognisedSetOrByName) {
  RawTrial pig = ownLabTrial();
  pig.labels = {"LASI", "RASI", "SACR", "LHJC", "RHJC", "LKNE", "RKNE", "LANK", "RANK"};
  const LabelTable t = labelTable(pig);
  EXPECT_EQ(t.labels, pig.labels);
  EXPECT_EQ(t.suggestedFrom, "Plug-in Gait / Helen Hayes");
  EXPECT_EQ(t.suggested.joints[index(Joint::LHip)], (std::vector<std::string>{"LHJC"}));
  EXPECT_EQ(t.suggested.joints[index(Joint::LKnee)], (std::vector<std::string>{"LKNE"}));
  EXPECT_TRUE(t.suggested.joints[index(Joint::Head)].empty());
  // The suggestion is itself a valid mapping file for the trial.
  const JointMapping back = parseJointMapping(jointMappingToJson(t.suggested), "s.json");
  EXPECT_NO_THROW(applyJointMapping(pig, back, "s.json"));

  RawTrial named = ownLabTrial();
  named.labels = {"pelvis",  "left_hip",   "right_hip", "Left_Knee", "r_knee",
                  "l_ankle", "RightAnkle", "neck",      "head"};
  const LabelTable n = labelTable(named);
  EXPECT_EQ(n.suggestedFrom, "label names");
  EXPECT_EQ(n.suggested.joints[index(Joint::LKnee)], (std::vector<std::string>{"Left_Knee"}));
  EXPECT_EQ(n.suggested.joints[index(Joint::RAnkle)], (std::vector<std::string>{"RightAnkle"}));
  EXPECT_EQ(n.suggested.joints[index(Joint::Head)], (std::vector<std::string>{"head"}));
  EXPECT_TRUE(n.suggested.joints[index(Joint::Sternum)].empty());
}

// European labs' C3D labels are often Latin-1 ("GENOU_\xE9"): the mapping file (JSON, so
// UTF-8) holds them as UTF-8 and still matches the file's bytes.
TEST(MappingFile, Latin1LabelsRoundTripThroughTheJsonFile) {
  RawTrial raw = ownLabTrial();
  raw.labels[4] = "GENOU_G\xE9";  // the left knee marker, Latin-1
  auto mapping = parseJointMapping(mappingText(kLowerBody), "m.json");
  mapping.joints[index(Joint::LKnee)] = {raw.labels[4]};
  const std::string text = jointMappingToJson(mapping);
  EXPECT_NE(text.find("GENOU_G\xC3\xA9"), std::string::npos) << text;
  const JointTrial t = applyJointMapping(raw, parseJointMapping(text, "m.json"), "m.json");
  EXPECT_LT((jointAt(t.positionsMm, 0, Joint::LKnee) - Eigen::Vector3d(0, 90, 520)).norm(), 1e-9);
  EXPECT_EQ(normaliseMarkerLabel("genou_g\xE9"), "GENOU_G\xC3\xA9");
  EXPECT_EQ(labelAsUtf8("GENOU_G\xC3\xA9"), "GENOU_G\xC3\xA9");  // already UTF-8: kept
}

// [SECTION] Through the loader and the CLI
// ---------------------------------------------------------

TEST(MappingFile, LoadOptionsCarryTheMappingAndSkeletonFilesRefuseIt) {
  RawTrial skeleton = ownLabTrial();
  skeleton.kind = PointKind::SkeletonJoints;
  LoadOptions options;
  options.mappingFile = "m.json";
  try {
    mapRawTrial(skeleton, options);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::BadArgument);
    EXPECT_EQ(e.file(), "m.json");
  }
}

TEST(MappingFile, InfoWithMappingMapsAnUnknownLabSet) {
  const fs::path dir = test::makeTempDir("mapping_cli");
  const RawTrial raw = ownLabTrial();
  std::ostringstream trc;
  trc << "PathFileType\t4\t(X/Y/Z)\town.trc\nDataRate\tCameraRate\tNumFrames\tNumMarkers\tUnits\n"
      << "100\t100\t" << raw.frameCount() << "\t" << raw.pointCount() << "\tmm\nFrame#\tTime";
  for (const auto& l : raw.labels) trc << "\t" << l << "\t\t";
  trc << "\n\t";
  for (int k = 0; k < raw.pointCount(); ++k)
    trc << "\tX" << k + 1 << "\tY" << k + 1 << "\tZ" << k + 1;
  trc << "\n";
  for (int f = 0; f < raw.frameCount(); ++f) {
    trc << f + 1 << "\t" << f / 100.0;
    for (int c = 0; c < raw.positionsMm.cols(); ++c) trc << "\t" << raw.positionsMm(f, c);
    trc << "\n";
  }
  std::ofstream(dir / "own.trc") << trc.str();
  std::ofstream(dir / "map.json") << mappingText(kLowerBody);
  const auto without =
      test::runProgram(EW_CLI_PATH, {"info", "--json", (dir / "own.trc").string()}, dir);
  EXPECT_NE(without.output.find("no known marker set"), std::string::npos) << without.output;
  EXPECT_NE(without.output.find("--mapping"), std::string::npos);
  const auto with = test::runProgram(
      EW_CLI_PATH,
      {"info", "--json", "--mapping", (dir / "map.json").string(), (dir / "own.trc").string()},
      dir);
  EXPECT_NE(with.output.find("joint mapping"), std::string::npos) << with.output;
  EXPECT_EQ(with.output.find("no known marker set"), std::string::npos) << with.output;
  // The other commands that load trials take it too: the stiff fixture does not walk, so
  // they fail past the joint stage, never on the markers.
  const std::vector<std::vector<std::string>> others = {
      {"joints", (dir / "own.trc").string(), "--out", (dir / "j.csv").string()},
      {"reconstruct", "--input", (dir / "own.trc").string(), "--project-angle", "30", "--angle",
       "30", "--out", (dir / "r.csv").string()},
      {"build", "--data", (dir / "own.trc").string(), "--out", (dir / "m.ewm").string()}};
  for (auto args : others) {
    SCOPED_TRACE(args.front());
    const auto plain = test::runProgram(EW_CLI_PATH, args, dir);
    EXPECT_NE(plain.output.find("no known marker set"), std::string::npos) << plain.output;
    args.insert(args.end(), {"--mapping", (dir / "map.json").string()});
    const auto mapped = test::runProgram(EW_CLI_PATH, args, dir);
    EXPECT_EQ(mapped.output.find("no known marker set"), std::string::npos) << mapped.output;
    EXPECT_EQ(mapped.output.find("--mapping"), std::string::npos) << mapped.output;
  }
  std::ofstream(dir / "bad.json") << mappingText({{"l_knee", "[]"}});
  const auto bad = test::runProgram(
      EW_CLI_PATH,
      {"info", "--json", "--mapping", (dir / "bad.json").string(), (dir / "own.trc").string()},
      dir);
  EXPECT_NE(bad.exitCode, 0);
  EXPECT_NE(bad.output.find("joints.l_knee"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace ew

// Marker-set tables (assets/marker-sets/*.json) on small fixtures written here, one per set
// and name family; the lower-body sets leave the upper body `missing`; the minimum a set
// must give; "not walking" before marker complaints; and the ISB / Plug-in Gait joints
// are those the hand-coded mapping gave before the tables (regression on real trials).

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/assets/embedded_assets.h"
#include "core/common/errors.h"
#include "core/gait/canonical_frame.h"
#include "core/io/c3d_reader.h"
#include "core/io/trc_reader.h"
#include "core/mapping/functional_centre.h"
#include "core/mapping/joint_mapping.h"
#include "core/mapping/marker_set_table.h"
#include "core/mapping/marker_sets.h"
#include "core/mapping/raw_motion.h"
#include "tests/common/marker_tracks.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

using Eigen::Vector3d;
using Labelled = std::vector<std::pair<std::string, Vector3d>>;

// [SECTION] Fixtures ----------------------------------------------------------------------

// A body standing upright, z up, facing +x, its left on +y (mm, relative to the floor under
// mid-ASIS), carried forward at 1.2 m/s for 2 s at 100 Hz (or held still, with 3 mm sway,
// when `walking` is false). Every label keeps its offset: the mapping only needs geometry.
RawTrial trialOf(const Labelled& points, bool walking = true, const std::string& file = "f.c3d") {
  RawTrial raw;
  raw.file = file;
  raw.format = "C3D";
  raw.rateHz = 100.0;
  raw.units = "mm";
  const int frames = 200;
  raw.positionsMm.resize(frames, 3 * static_cast<int>(points.size()));
  for (std::size_t k = 0; k < points.size(); ++k) {
    raw.labels.push_back(points[k].first);
    for (int f = 0; f < frames; ++f) {
      Vector3d p = points[k].second;
      if (walking)
        p.x() += 12.0 * f;
      else
        p += 3.0 * Vector3d(std::sin(0.3 * f), std::cos(0.2 * f), 0);
      raw.positionsMm.block<1, 3>(f, 3 * static_cast<int>(k)) = p.transpose();
    }
  }
  return raw;
}

// One side's lateral landmarks; `s` is +1 for left (+y), -1 for right.
Labelled pigSide(const std::string& p, double s) {
  return {{p + "ASI", {0, s * 120, 1000}},  {p + "KNE", {0, s * 140, 520}},
          {p + "ANK", {0, s * 120, 90}},    {p + "SHO", {0, s * 180, 1450}},
          {p + "ELB", {0, s * 230, 1150}},  {p + "WRA", {20, s * 210, 900}},
          {p + "WRB", {-20, s * 190, 900}}, {p + "THI", {0, s * 150, 760}},
          {p + "TIB", {0, s * 130, 300}}};
}

Labelled concat(std::vector<Labelled> parts) {
  Labelled out;
  for (auto& p : parts) out.insert(out.end(), p.begin(), p.end());
  return out;
}

Labelled pigFull() {
  return concat({pigSide("L", 1),
                 pigSide("R", -1),
                 {{"LPSI", {-160, 50, 1010}},
                  {"RPSI", {-160, -50, 1010}},
                  {"C7", {-80, 0, 1480}},
                  {"CLAV", {60, 0, 1440}},
                  {"LFHD", {80, 70, 1650}},
                  {"RFHD", {80, -70, 1650}},
                  {"LBHD", {-80, 70, 1650}},
                  {"RBHD", {-80, -70, 1650}}}});
}

Labelled pigLowerWithSacrum() {
  Labelled out;
  for (const auto& [label, p] : pigFull()) {
    for (const char* keep : {"ASI", "KNE", "ANK", "THI", "TIB"}) {
      if (label.size() == 4 && label.substr(1) == keep) out.push_back({label, p});
    }
  }
  out.push_back({"SACR", {-160, 0, 1010}});
  return out;
}

Vector3d jointAt0(const JointTrial& t, Joint j) { return jointAt(t.positionsMm, 0, j); }

bool anyWarning(const JointTrial& t, const std::string& text) {
  for (const auto& w : t.warnings) {
    if (w.find(text) != std::string::npos) return true;
  }
  return false;
}

void expectAllMeasured(const JointTrial& t) {
  for (int j = 0; j < kJointCount; ++j) {
    EXPECT_FALSE(t.missing[static_cast<std::size_t>(j)])
        << kJointNames[static_cast<std::size_t>(j)];
    EXPECT_TRUE(t.positionsMm.col(3 * j).array().isFinite().all())
        << kJointNames[static_cast<std::size_t>(j)];
  }
}

const std::vector<Joint> kUpperBody = {Joint::Head,   Joint::Sternum, Joint::RShoulder,
                                       Joint::RElbow, Joint::RWrist,  Joint::LShoulder,
                                       Joint::LElbow, Joint::LWrist};

// [SECTION] The tables themselves -----------------------------------------------------------

TEST(MarkerSetTables, EveryEmbeddedTableParsesAndNamesAllItsRules) {
  const auto names = embeddedAssetNames("marker-sets/");
  ASSERT_GE(names.size(), 7u);
  ASSERT_EQ(markerSetTables().size(), names.size());
  for (const auto& t : markerSetTables()) {
    SCOPED_TRACE(t.file);
    EXPECT_FALSE(t.name.empty());
    EXPECT_FALSE(t.identify.empty());
    EXPECT_FALSE(t.joints[static_cast<std::size_t>(index(Joint::Pelvis))].empty());
  }
}

TEST(MarkerSetTables, MalformedTablesNameTheFileAndKey) {
  const auto expectKey = [](const std::string& text, const std::string& key) {
    try {
      parseMarkerSetTable(text, "t.json");
      ADD_FAILURE() << "accepted: " << text;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Malformed);
      EXPECT_EQ(e.file(), "t.json");
      EXPECT_EQ(e.position(), key) << e.what();
    }
  };
  expectKey("{", "");
  expectKey(R"({"identify": ["A"], "joints": {}})", ".name");
  expectKey(R"({"name": "x", "identify": ["A"], "joints": {"knee": []}})", "joints.knee");
  expectKey(R"({"name": "x", "identify": ["A"], "joints": {"pelvis": [{"op": "magic"}]}})",
            "joints.pelvis[0].op");
  expectKey(R"({"name": "x", "identify": ["A"], "joints": {"pelvis": [{"op": "mean"}]}})",
            "joints.pelvis[0].markers");
  // The feet: known point names, "mean" rules only.
  expectKey(R"({"name": "x", "identify": ["A"], "joints": {}, "feet": []})", "feet");
  expectKey(R"({"name": "x", "identify": ["A"], "joints": {}, "feet": {"r_ankle": []}})", "feet.r_ankle");
  expectKey(R"({"name": "x", "identify": ["A"], "joints": {}, "feet": {"r_heel": [{"op": "head_above_sternum"}]}})",
            "feet.r_heel[0].op");
}

// [SECTION] The feet beside the joints -----------------------------------------------------------

TEST(MarkerSetTables, HeelAndToeMarkersBecomeTheFeet) {
  Labelled withFeet = pigLowerWithSacrum();
  const Labelled feet = {{"RHEE", {-60, -90, 40}}, {"RTOE", {130, -100, 40}},
                         {"LHEE", {-60, 90, 40}}, {"LTOE", {130, 100, 40}}};
  withFeet.insert(withFeet.end(), feet.begin(), feet.end());
  const RawTrial raw = trialOf(withFeet);
  const JointTrial t = mapMarkerSet(raw);
  ASSERT_TRUE(t.hasFeet());
  // Each foot point is its marker, frame for frame (the markers are the raw trial's last four).
  const Eigen::Index first = raw.positionsMm.cols() - kFootDims3;
  for (int p = 0; p < kFootPointCount; ++p) {
    const auto k = static_cast<Eigen::Index>(p);
    EXPECT_TRUE(t.feetMm.middleCols(3 * k, 3).isApprox(raw.positionsMm.middleCols(first + 3 * k, 3)))
        << kFootPointNames[static_cast<std::size_t>(p)];
  }
  EXPECT_FALSE(anyWarning(t, "foot points not measured"));
  // A toe never seen: that point is NaN, the others measured, and a warning names it.
  RawTrial noToe = raw;
  noToe.positionsMm.rightCols(3).setConstant(NAN);  // LTOE
  const JointTrial half = mapMarkerSet(noToe);
  ASSERT_TRUE(half.hasFeet());
  EXPECT_TRUE(half.feetMm.middleCols(3 * index(FootPoint::LToe), 3).array().isNaN().all());
  EXPECT_TRUE(half.feetMm.middleCols(3 * index(FootPoint::LHeel), 3).allFinite());
  EXPECT_TRUE(anyWarning(half, "foot points not measured by Plug-in Gait / Helen Hayes: l_toe"));
  // No foot marker at all: no feet, and no warning about them.
  const JointTrial none = mapMarkerSet(trialOf(pigLowerWithSacrum()));
  EXPECT_FALSE(none.hasFeet());
  EXPECT_EQ(none.feetMm.size(), 0);
  EXPECT_FALSE(anyWarning(none, "foot points"));
}

TEST(MarkerSetTables, SchreiberTrialsHaveTheirFeet) {
  EW_REQUIRE_SHARED_DATA();
  const JointTrial t = mapMarkerSet(readC3d(test::sharedDataDir() / "schreiber-moissenet-2019/2014001/2014001_C4_05.c3d"));
  ASSERT_TRUE(t.hasFeet());
  EXPECT_TRUE(t.feetMm.allFinite());
  // The heel behind the ankle and the toe ahead of it, along the foot (mm): a foot's length.
  for (Side side : {Side::Right, Side::Left}) {
    const Eigen::MatrixXd heel = t.feetMm.middleCols(3 * index(heelOf(side)), 3);
    const Eigen::MatrixXd toe = t.feetMm.middleCols(3 * index(toeOf(side)), 3);
    const double length = (toe - heel).rowwise().norm().mean();
    EXPECT_GT(length, 120.0);
    EXPECT_LT(length, 250.0);
  }
}

// [SECTION] Plug-in Gait: full, lower body, model outputs ------------------------------------

TEST(MarkerSetTables, PlugInGaitFullBodyMeasuresAllFifteen) {
  const JointTrial t = mapMarkerSet(trialOf(pigFull()));
  EXPECT_EQ(t.source, "Plug-in Gait / Helen Hayes");
  expectAllMeasured(t);
  EXPECT_FALSE(t.estimated[index(Joint::Head)]);     // four head markers
  EXPECT_FALSE(t.estimated[index(Joint::Sternum)]);  // C7 + CLAV
  EXPECT_FALSE(t.estimated[index(Joint::LWrist)]);   // WRA + WRB
  EXPECT_TRUE(t.estimated[index(Joint::LKnee)]);     // lateral marker only
  EXPECT_TRUE((jointAt0(t, Joint::Head) - Vector3d(0, 0, 1650)).norm() < 1e-9);
  EXPECT_TRUE((jointAt0(t, Joint::Sternum) - Vector3d(-10, 0, 1460)).norm() < 1e-9);
  // Harrington: hips below, behind and inside the ASIS; knee 66 mm medial of LKNE.
  EXPECT_LT(jointAt0(t, Joint::LHip).z(), 1000);
  EXPECT_LT(jointAt0(t, Joint::LHip).y(), 120);
  EXPECT_NEAR(jointAt0(t, Joint::LKnee).y(), 140 - kKneeHalfWidthMm, 5);
}

TEST(MarkerSetTables, LowerBodySetWithSacrumLeavesTheUpperBodyMissing) {
  const JointTrial t = mapMarkerSet(trialOf(pigLowerWithSacrum()));
  EXPECT_EQ(t.source, "Plug-in Gait / Helen Hayes");
  for (Joint j : kUpperBody) {
    EXPECT_TRUE(t.missing[index(j)]) << jointName(j);
    EXPECT_TRUE(t.positionsMm.middleCols(3 * index(j), 3).array().isNaN().all()) << jointName(j);
  }
  for (Joint j : {Joint::Pelvis, Joint::LHip, Joint::RHip, Joint::LKnee, Joint::RKnee,
                  Joint::LAnkle, Joint::RAnkle}) {
    EXPECT_FALSE(t.missing[index(j)]) << jointName(j);
    EXPECT_TRUE(t.positionsMm.middleCols(3 * index(j), 3).array().isFinite().all());
  }
  EXPECT_TRUE(anyWarning(t, "not measured by Plug-in Gait / Helen Hayes: head"));
  // SACR stands in for the mid-PSIS: the same hips as LPSI/RPSI at the same place.
  Labelled withPsis = pigLowerWithSacrum();
  withPsis.pop_back();
  withPsis.push_back({"LPSI", {-160, 50, 1010}});
  withPsis.push_back({"RPSI", {-160, -50, 1010}});
  const JointTrial p = mapMarkerSet(trialOf(withPsis));
  EXPECT_LT((jointAt0(p, Joint::LHip) - jointAt0(t, Joint::LHip)).norm(), 1e-9);
}

TEST(MarkerSetTables, ModelOutputsWinIncludingSuffixedCgmNames) {
  for (const std::string suffix : {"", "_CGM_2.4"}) {
    SCOPED_TRACE("suffix '" + suffix + "'");
    Labelled points = pigLowerWithSacrum();
    points.push_back({"LHJC" + suffix, {-50, 85, 910}});
    points.push_back({"RHJC" + suffix, {-50, -85, 910}});
    points.push_back({"LKJC" + suffix, {0, 90, 520}});
    points.push_back({"RKJC" + suffix, {0, -90, 520}});
    points.push_back({"LAJC" + suffix, {0, 80, 90}});
    points.push_back({"RAJC" + suffix, {0, -80, 90}});
    const JointTrial t = mapMarkerSet(trialOf(points));
    EXPECT_LT((jointAt0(t, Joint::LHip) - Vector3d(-50, 85, 910)).norm(), 1e-9);
    EXPECT_LT((jointAt0(t, Joint::RKnee) - Vector3d(0, -90, 520)).norm(), 1e-9);
    EXPECT_LT((jointAt0(t, Joint::LAnkle) - Vector3d(0, 80, 90)).norm(), 1e-9);
    EXPECT_LT((jointAt0(t, Joint::Pelvis) - Vector3d(-50, 0, 910)).norm(), 1e-9);
    EXPECT_FALSE(t.estimated[index(Joint::LKnee)]);
  }
}

// Markers labelled but never seen (NaN in every frame) count as absent: the set is still
// recognised, and the joints they would give are missing.
TEST(MarkerSetTables, MarkersWithNoPositionCountAsAbsent) {
  RawTrial raw = trialOf(pigFull());
  for (std::size_t k = 0; k < raw.labels.size(); ++k) {
    const std::string& l = raw.labels[k];
    if (l == "LSHO" || l == "RSHO" || l == "C7" || l == "CLAV")
      raw.positionsMm.middleCols(3 * static_cast<int>(k), 3).setConstant(NAN);
  }
  const JointTrial t = mapMarkerSet(raw);
  EXPECT_TRUE(t.missing[index(Joint::Sternum)]);
  EXPECT_TRUE(t.missing[index(Joint::LShoulder)]);
  EXPECT_TRUE(t.missing[index(Joint::LElbow)]);  // its rule reads the shoulder
  EXPECT_FALSE(t.missing[index(Joint::Head)]);   // its own four markers still make it
  EXPECT_FALSE(t.missing[index(Joint::LWrist)]);
}

// [SECTION] Other vendors' sets ---------------------------------------------------------------

TEST(MarkerSetTables, MotionAnalysisHelenHayesNames) {
  Labelled points;
  for (const auto& [label, p] : pigFull()) {
    if (label == "LASI")
      points.push_back({"LHIP", p});
    else if (label == "RASI")
      points.push_back({"RHIP", p});
    else if (label == "LWRA")
      points.push_back({"LWRI", p});
    else if (label == "RWRA")
      points.push_back({"RWRI", p});
    else if (label.size() == 4 && (label.substr(1) == "KNE" || label.substr(1) == "ANK" ||
                                   label.substr(1) == "SHO" || label.substr(1) == "ELB"))
      points.push_back({label, p});
  }
  points.push_back({"VSAC", {-160, 0, 1010}});
  const JointTrial t = mapMarkerSet(trialOf(points));
  EXPECT_EQ(t.source, "Motion Analysis Helen Hayes");
  expectAllMeasured(t);
  EXPECT_TRUE(t.estimated[index(Joint::Sternum)]);
  EXPECT_TRUE(t.estimated[index(Joint::LWrist)]);
  EXPECT_TRUE(t.estimated[index(Joint::Head)]);
}

TEST(MarkerSetTables, QualisysHybridIsRecognisedButLacksKneesAndAnkles) {
  const Labelled points = {{"R_ASIS", {0, -120, 1000}},  {"L_ASIS", {0, 120, 1000}},
                           {"SACRUM", {-160, 0, 1010}},  {"R_THIGH_1", {0, -150, 760}},
                           {"L_THIGH_1", {0, 150, 760}}, {"R_HEEL", {-60, -90, 40}}};
  try {
    mapMarkerSet(trialOf(points, true, "q.c3d"));
    ADD_FAILURE() << "mapped without knees";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::UnknownMarkerSet);
    const std::string msg = e.what();
    EXPECT_NE(msg.find("q.c3d"), std::string::npos);
    EXPECT_NE(msg.find("Qualisys hybrid"), std::string::npos) << msg;
    EXPECT_NE(msg.find("at least pelvis, both knees and both ankles"), std::string::npos) << msg;
    EXPECT_NE(msg.find("missing l_knee, r_knee, l_ankle, r_ankle"), std::string::npos) << msg;
    EXPECT_EQ(msg.find("not walking"), std::string::npos) << msg;
  }
}

// [SECTION] Markerless name families ---------------------------------------------------------

Labelled openPoseKeypoints() {
  return {{"Nose", {90, 0, 1600}},     {"Neck", {0, 0, 1450}},     {"RShoulder", {0, -170, 1440}},
          {"RElbow", {0, -200, 1150}}, {"RWrist", {0, -200, 900}}, {"LShoulder", {0, 170, 1440}},
          {"LElbow", {0, 200, 1150}},  {"LWrist", {0, 200, 900}},  {"MidHip", {-40, 0, 920}},
          {"RHip", {-40, -85, 910}},   {"RKnee", {0, -90, 520}},   {"RAnkle", {0, -80, 90}},
          {"LHip", {-40, 85, 910}},    {"LKnee", {0, 90, 520}},    {"LAnkle", {0, 80, 90}},
          {"REar", {0, -75, 1620}},    {"LEar", {0, 75, 1620}},    {"LBigToe", {180, 90, 10}}};
}

TEST(MarkerSetTables, OpenPoseBody25KeypointsAreTheJoints) {
  const JointTrial t = mapMarkerSet(trialOf(openPoseKeypoints()));
  EXPECT_EQ(t.source, "OpenPose / COCO / Halpe keypoints");
  expectAllMeasured(t);
  EXPECT_LT((jointAt0(t, Joint::Pelvis) - Vector3d(-40, 0, 920)).norm(), 1e-9);  // MidHip
  EXPECT_LT((jointAt0(t, Joint::Head) - Vector3d(0, 0, 1620)).norm(), 1e-9);     // ears
  EXPECT_LT((jointAt0(t, Joint::Sternum) - Vector3d(0, 0, 1450)).norm(), 1e-9);  // Neck
  EXPECT_LT((jointAt0(t, Joint::RKnee) - Vector3d(0, -90, 520)).norm(), 1e-9);
  for (int j = 0; j < kJointCount; ++j) EXPECT_FALSE(t.estimated[static_cast<std::size_t>(j)]);
}

TEST(MarkerSetTables, CocoWithoutMidHipAndHalpeHeadTopAreHandled) {
  Labelled coco;
  for (const auto& kp : openPoseKeypoints()) {
    if (kp.first != "MidHip" && kp.first != "Neck") coco.push_back(kp);
  }
  const JointTrial c = mapMarkerSet(trialOf(coco));
  EXPECT_LT((jointAt0(c, Joint::Pelvis) - Vector3d(-40, 0, 910)).norm(), 1e-9);  // mid-hips
  EXPECT_TRUE(c.estimated[index(Joint::Sternum)]);  // from the shoulders
  Labelled halpe;
  for (const auto& kp : openPoseKeypoints()) {
    if (kp.first != "REar" && kp.first != "LEar") halpe.push_back(kp);
  }
  halpe.push_back({"Head", {0, 0, 1760}});
  const JointTrial h = mapMarkerSet(trialOf(halpe));
  EXPECT_TRUE(h.estimated[index(Joint::Head)]);
  EXPECT_LT((jointAt0(h, Joint::Head) - Vector3d(45, 0, 1680)).norm(), 1e-9);
}

TEST(MarkerSetTables, OpenCapStudyMarkersWinOverItsVideoKeypoints) {
  Labelled points = openPoseKeypoints();
  const Labelled study = {
      {"r.ASIS_study", {0, -120, 1000}},     {"L.ASIS_study", {0, 120, 1000}},
      {"r.PSIS_study", {-160, -50, 1010}},   {"L.PSIS_study", {-160, 50, 1010}},
      {"RHJC_study", {-50, -86, 905}},       {"LHJC_study", {-50, 86, 905}},
      {"r_knee_study", {0, -140, 520}},      {"r_mknee_study", {0, -40, 520}},
      {"L_knee_study", {0, 140, 520}},       {"L_mknee_study", {0, 40, 520}},
      {"r_ankle_study", {0, -120, 90}},      {"r_mankle_study", {0, -40, 90}},
      {"L_ankle_study", {0, 120, 90}},       {"L_mankle_study", {0, 40, 90}},
      {"r_shoulder_study", {0, -180, 1450}}, {"L_shoulder_study", {0, 180, 1450}},
      {"r_lelbow_study", {0, -230, 1150}},   {"r_melbow_study", {0, -170, 1150}},
      {"L_lelbow_study", {0, 230, 1150}},    {"L_melbow_study", {0, 170, 1150}},
      {"r_lwrist_study", {20, -210, 900}},   {"r_mwrist_study", {-20, -190, 900}},
      {"L_lwrist_study", {20, 210, 900}},    {"L_mwrist_study", {-20, 190, 900}},
      {"C7_study", {-80, 0, 1480}}};
  points.insert(points.end(), study.begin(), study.end());
  const JointTrial t = mapMarkerSet(trialOf(points));
  EXPECT_EQ(t.source, "OpenCap (*_study markers)");
  expectAllMeasured(t);
  EXPECT_LT((jointAt0(t, Joint::RHip) - Vector3d(-50, -86, 905)).norm(), 1e-9);
  EXPECT_LT((jointAt0(t, Joint::LKnee) - Vector3d(0, 90, 520)).norm(), 1e-9);
  EXPECT_LT((jointAt0(t, Joint::RAnkle) - Vector3d(0, -80, 90)).norm(), 1e-9);
  EXPECT_LT((jointAt0(t, Joint::LElbow) - Vector3d(0, 200, 1150)).norm(), 1e-9);
}

// Pose2Sim's own demo output: Halpe-26 names in a TRC, metres, Y up.
TEST(MarkerSetTables, Pose2SimTrcMapsInMillimetresWithYUp) {
  EW_REQUIRE_SHARED_DATA();
  const auto file =
      test::sharedDataDir() / "pose2sim-balancing/pose-3d/S00_P00_T01_BalancingTrial_0-100.trc";
  const RawTrial raw = readTrc(file);
  EXPECT_EQ(raw.units, "m");
  const JointTrial t = mapMarkerSet(raw);
  EXPECT_EQ(t.source, "OpenPose / COCO / Halpe keypoints");
  for (int j = 0; j < kJointCount; ++j) EXPECT_FALSE(t.missing[static_cast<std::size_t>(j)]);
  // Y is up: the head is ~0.8 m above the pelvis and the ankles ~0.75 m below it, in mm.
  const double head = jointAt0(t, Joint::Head).y() - jointAt0(t, Joint::Pelvis).y();
  const double ankle = jointAt0(t, Joint::Pelvis).y() - jointAt0(t, Joint::LAnkle).y();
  EXPECT_GT(head, 500);
  EXPECT_LT(head, 1000);
  EXPECT_GT(ankle, 600);
  EXPECT_LT(ankle, 1000);
  // What the canonical frame will take as up (the file states none): +Y.
  EXPECT_EQ(detectUpAxis(t.positionsMm), (SignedAxis{1, 1}));
}

// [SECTION] Not walking, and the minimum ------------------------------------------------------

TEST(MarkerSetTables, UnknownLabelsThatDoNotWalkSayNotWalkingFirst) {
  Labelled channels;
  for (int k = 0; k < 8; ++k)
    channels.push_back({"Channel" + std::to_string(100 + k), {40.0 * k, 10.0 * k, 900.0 + 60 * k}});
  try {
    mapMarkerSet(trialOf(channels, false, "swing.c3d"));
    ADD_FAILURE() << "mapped";
  } catch (const Error& e) {
    const std::string problem = e.problem();
    EXPECT_EQ(problem.rfind("not walking: ", 0), 0u) << problem;
    EXPECT_NE(problem.find("no known marker set"), std::string::npos) << problem;
  }
  try {
    mapMarkerSet(trialOf(channels, true, "walk.c3d"));
    ADD_FAILURE() << "mapped";
  } catch (const Error& e) {
    EXPECT_EQ(std::string(e.problem()).rfind("no known marker set", 0), 0u) << e.problem();
  }
}

TEST(MarkerSetTables, RawMotionMeasuresTravelAndSpeed) {
  const RawMotion m = measureRawMotion(trialOf(pigFull()));
  EXPECT_NEAR(m.durationS, 1.99, 1e-9);
  EXPECT_NEAR(m.travelM, 2.388, 1e-9);
  EXPECT_NEAR(m.straightness(), 1.0, 1e-9);
  EXPECT_FALSE(rawNotWalkingReason(trialOf(pigFull())));
  EXPECT_TRUE(rawNotWalkingReason(trialOf(pigFull(), false)));
}

TEST(MarkerSetTables, BelowTheMinimumSaysWhatIsMissing) {
  Labelled noAnkles;
  for (const auto& p : pigLowerWithSacrum()) {
    if (p.first != "LANK") noAnkles.push_back(p);
  }
  noAnkles.push_back({"LANK", {0, 120, 90}});
  RawTrial raw = trialOf(noAnkles);
  raw.positionsMm.rightCols(3).setConstant(NAN);  // LANK never seen
  try {
    mapMarkerSet(raw);
    ADD_FAILURE() << "mapped without a left ankle";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("(missing l_ankle"), std::string::npos) << e.what();
  }
}

// [SECTION] Regression: the tables give the joints the hand-coded mapping gave -----------------

struct Reference {
  const char* file;
  int frame;
  std::array<double, kDims3> joints;
};
// mapMarkerSet at commit 195347e (before the tables), printed with %.6f.
#include "tests/mapping/marker_set_references.inc"

TEST(MarkerSetTables, SameJointsAsTheHandCodedMappingOnRealTrials) {
  EW_REQUIRE_SHARED_DATA();
  for (const auto& r : kReferences) {
    SCOPED_TRACE(std::string(r.file) + " frame " + std::to_string(r.frame));
    const JointTrial t = mapMarkerSet(readC3d(test::sharedDataDir() / r.file));
    for (int c = 0; c < kDims3; ++c) {
      const double want = r.joints[static_cast<std::size_t>(c)];
      const double got = t.positionsMm(r.frame, c);
      if (std::isnan(want)) continue;
      EXPECT_NEAR(got, want, 1e-5)
          << kJointNames[static_cast<std::size_t>(c / 3)] << " axis " << c % 3;
    }
  }
}

// [SECTION] Functional joint centres (Qualisys clusters) --------------------------------------

// A ball joint at c: the distal cluster turns about c, the proximal one translates. SCoRE
// must find c exactly; for a hinge, a point on the hinge axis.
TEST(FunctionalCentre, FindsABallJointAndAPointOnAHingeAxis) {
  const Vector3d c(100, 200, 500);
  const std::vector<Vector3d> prox = {{0, 0, 900}, {60, 10, 800}, {-30, 50, 850}};
  const std::vector<Vector3d> dist = {{10, 0, 300}, {70, -20, 350}, {-40, 40, 250}};
  for (const bool hinge : {false, true}) {
    SCOPED_TRACE(hinge ? "hinge" : "ball");
    const int frames = 100;
    std::vector<MarkerTrack> p(3, MarkerTrack(frames, 3)), d(3, MarkerTrack(frames, 3));
    for (int f = 0; f < frames; ++f) {
      const Vector3d shift(5.0 * f, 0, 0);
      const Eigen::Matrix3d r =
          (Eigen::AngleAxisd(0.9 * std::sin(0.1 * f), Vector3d::UnitY()) *
           Eigen::AngleAxisd(hinge ? 0.0 : 0.4 * std::cos(0.13 * f), Vector3d::UnitX()))
              .toRotationMatrix();
      for (int k = 0; k < 3; ++k) {
        p[static_cast<std::size_t>(k)].row(f) =
            (prox[static_cast<std::size_t>(k)] + shift).transpose();
        d[static_cast<std::size_t>(k)].row(f) =
            (c + r * (dist[static_cast<std::size_t>(k)] - c) + shift).transpose();
      }
    }
    const MarkerTrack centre = functionalJointCentre(p, d);
    // Anchored on a point above the joint, off the axis: the hinge point is its foot on
    // the axis (the y axis through c), here c + 30 y.
    MarkerTrack anchor(frames, 3);
    for (int f = 0; f < frames; ++f)
      anchor.row(f) = (c + Vector3d(20, 30, 400) + Vector3d(5.0 * f, 0, 0)).transpose();
    const MarkerTrack anchored = functionalJointCentre(p, d, &anchor);
    if (hinge) {
      const Vector3d got = anchored.row(10).transpose() - Vector3d(50, 0, 0);
      EXPECT_LT((got - (c + Vector3d(0, 30, 0))).norm(), 1e-6);
    } else {
      EXPECT_LT((anchored.row(10).transpose() - Vector3d(50, 0, 0) - c).norm(), 1e-6);
    }
    for (int f : {0, 50, 99}) {
      const Vector3d got = centre.row(f).transpose() - Vector3d(5.0 * f, 0, 0);
      if (hinge) {
        EXPECT_NEAR(got.x(), c.x(), 1e-6);  // on the y axis through c
        EXPECT_NEAR(got.z(), c.z(), 1e-6);
      } else {
        EXPECT_LT((got - c).norm(), 1e-6);
      }
    }
  }
  // Too few frames with both clusters complete: no fit, NaN.
  std::vector<MarkerTrack> few(3, MarkerTrack::Zero(5, 3));
  EXPECT_TRUE(functionalJointCentre(few, few).array().isNaN().all());
}

// On the Schreiber trials, where the epicondyles and malleoli give the truth: functional
// knees (thigh FTC FLE FME / shank FAX TTC FAL TAM, anchored on the Harrington hip as the
// Qualisys table does) and ankles (shank / foot FCC FM1 FM5). Measured: mean 27.6 mm
// (knee) and 27.0 mm (ankle) over 16 trials x 2 sides, worst 63 mm.
TEST(FunctionalCentre, CloseToTheAnatomicalCentresOnSchreiberTrials) {
  EW_REQUIRE_SHARED_DATA();
  const auto track = test::markerTrack;
  const auto meanDistance = test::meanTrackDistanceMm;
  double knees = 0, ankles = 0;
  int n = 0;
  std::ifstream list(test::sharedDataDir() / "walkers.csv");
  std::string line;
  while (std::getline(list, line)) {
    if (line.find(",schreiber-moissenet-2019,") == std::string::npos) continue;
    const RawTrial r = readC3d(test::sharedDataDir() / line.substr(0, line.find(',')));
    if (r.pointCount() != 52) continue;
    const JointTrial isb = mapMarkerSet(r);
    for (const std::string s : {"L_", "R_"}) {
      const MarkerTrack hip =
          isb.positionsMm.middleCols(3 * index(s == "L_" ? Joint::LHip : Joint::RHip), 3);
      SCOPED_TRACE(r.file + " " + s);
      const std::vector<MarkerTrack> shank = {track(r, s + "FAX"), track(r, s + "TTC"),
                                              track(r, s + "FAL"), track(r, s + "TAM")};
      const double knee = meanDistance(
          functionalJointCentre({track(r, s + "FTC"), track(r, s + "FLE"), track(r, s + "FME")},
                                shank, &hip),
          0.5 * (track(r, s + "FLE") + track(r, s + "FME")));
      const double ankle =
          meanDistance(functionalJointCentre(
                           shank, {track(r, s + "FCC"), track(r, s + "FM1"), track(r, s + "FM5")}),
                       0.5 * (track(r, s + "FAL") + track(r, s + "TAM")));
      EXPECT_LT(knee, 70.0);
      EXPECT_LT(ankle, 70.0);
      knees += knee, ankles += ankle, ++n;
    }
  }
  ASSERT_EQ(n, 32);
  EXPECT_LT(knees / n, 32.0);
  EXPECT_LT(ankles / n, 32.0);
}

TEST(MarkerSetTables, QualisysHybridMapsWithFunctionalKneesAndAnkles) {
  EW_REQUIRE_SHARED_DATA();
  const JointTrial t = mapMarkerSet(
      readC3d(test::sharedDataDir() / "c3d-samples/sample26_qualisys/Walking_Hybrid_1_1.c3d"));
  EXPECT_EQ(t.source, "Qualisys hybrid (pelvis + clusters)");
  for (Joint j : {Joint::LKnee, Joint::RKnee, Joint::LAnkle, Joint::RAnkle}) {
    EXPECT_FALSE(t.missing[index(j)]) << jointName(j);
    EXPECT_TRUE(t.estimated[index(j)]) << jointName(j);
  }
  for (Joint j : kUpperBody) EXPECT_TRUE(t.missing[index(j)]) << jointName(j);
  // Human, steady segment lengths (mean over frames where both ends exist).
  for (const auto& [a, b] :
       {std::pair{Joint::LHip, Joint::LKnee}, std::pair{Joint::RHip, Joint::RKnee},
        std::pair{Joint::LKnee, Joint::LAnkle}, std::pair{Joint::RKnee, Joint::RAnkle}}) {
    double sum = 0, sq = 0;
    int n = 0;
    for (int f = 0; f < t.frameCount(); ++f) {
      const double d = (jointAt(t.positionsMm, f, a) - jointAt(t.positionsMm, f, b)).norm();
      if (std::isfinite(d)) sum += d, sq += d * d, ++n;
    }
    ASSERT_GT(n, 100);
    const double mean = sum / n, sd = std::sqrt(sq / n - mean * mean);
    EXPECT_GT(mean, 300) << jointName(a) << "-" << jointName(b);
    EXPECT_LT(mean, 550) << jointName(a) << "-" << jointName(b);
    EXPECT_LT(sd / mean, 0.05) << jointName(a) << "-" << jointName(b);
  }
}

}  // namespace
}  // namespace ew

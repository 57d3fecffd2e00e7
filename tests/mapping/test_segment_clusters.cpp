// Segment-cluster sets (assets/marker-sets/80-segment-clusters.json): technical triads on
// pelvis, thighs, shanks and feet, no anatomical marker. Every leg joint is a functional
// centre; the hips are set a fixed width apart (symmetricFunctionalHips); legs whose fitted
// proportions are not a person's are refused. Fixtures: a walker whose joints are known
// exactly (forward kinematics written here), then the real Vicon 370 and TESTBPI samples.

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "core/common/errors.h"
#include "core/io/c3d_reader.h"
#include "core/mapping/functional_centre.h"
#include "core/mapping/joint_mapping.h"
#include "core/mapping/marker_set_table.h"
#include "tests/common/error_matchers.h"
#include "tests/common/marker_tracks.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

using Eigen::AngleAxisd;
using Eigen::Matrix3d;
using Eigen::Vector3d;

// [SECTION] A kinematic walker with clusters ----------------------------------------------

constexpr int kFrames = 200;  // 2 s at 100 Hz
constexpr double kHipWidth = 176, kThigh = 430;

struct Leg {
  double shankMm = 420;
  std::vector<Vector3d> hip, knee, ankle;
  std::vector<Matrix3d> thigh, shank, foot;  // segment orientations
};

Matrix3d rotY(double a) { return AngleAxisd(a, Vector3d::UnitY()).toRotationMatrix(); }
Matrix3d rotX(double a) { return AngleAxisd(a, Vector3d::UnitX()).toRotationMatrix(); }

// One side's joints over a stride a second, `s` +1 left (+y) and -1 right (half a stride
// later): the hip a ball joint (flexion and abduction), the knee a hinge straight below it,
// the ankle moving about two axes.
void moveLeg(Leg& leg, double s) {
  for (int f = 0; f < kFrames; ++f) {
    const double w = 2 * M_PI * f / 100.0 + (s > 0 ? 0 : M_PI);
    leg.thigh.push_back(rotY(0.4 * std::sin(w)) * rotX(s * 0.12 * std::cos(w)));
    leg.shank.push_back(leg.thigh.back() * rotY(-0.5 * (1 - std::cos(w))));
    leg.foot.push_back(leg.shank.back() * rotY(0.25 * std::sin(w)) * rotX(0.15 * std::sin(2 * w)));
    leg.hip.emplace_back(12.0 * f, s * kHipWidth / 2, 900);
    leg.knee.push_back(leg.hip.back() + leg.thigh.back() * Vector3d(0, 0, -kThigh));
    leg.ankle.push_back(leg.knee.back() + leg.shank.back() * Vector3d(0, 0, -leg.shankMm));
  }
}

// A marker's track: `at(f)` for every frame, appended to `raw` as `label`.
template <class At>
void addMarker(RawTrial& raw, const std::string& label, At&& at) {
  const int col = 3 * static_cast<int>(raw.labels.size());
  raw.labels.push_back(label);
  raw.positionsMm.conservativeResize(kFrames, col + 3);
  for (int f = 0; f < kFrames; ++f) raw.positionsMm.block<1, 3>(f, col) = at(f).transpose();
}

// Three markers fixed in a segment's frame (origin at its proximal joint), lateral on `s`.
std::vector<Vector3d> cluster(double s, double down) {
  return {{40, s * 70, -down}, {-30, s * 80, -down - 60}, {10, s * 60, -down - 120}};
}

// One side's thigh, shank and foot clusters: <p>TH1-3, <p>SK1-3, <p>FT1-3.
void addLeg(RawTrial& raw, const std::string& p, double s, Leg& leg) {
  moveLeg(leg, s);
  const auto segment = [&](const std::string& name, const std::vector<Vector3d>& origin,
                           const std::vector<Matrix3d>& r, const std::vector<Vector3d>& offsets) {
    for (std::size_t k = 0; k < offsets.size(); ++k) {
      addMarker(raw, p + name + std::to_string(k + 1), [&](int f) {
        const auto i = static_cast<std::size_t>(f);
        return Vector3d(origin[i] + r[i] * offsets[k]);
      });
    }
  };
  segment("TH", leg.hip, leg.thigh, cluster(s, 150));
  segment("SK", leg.knee, leg.shank, cluster(s, 120));
  segment("FT", leg.ankle, leg.foot, {{60, s * 30, -40}, {150, s * 20, -60}, {-40, s * 10, -50}});
}

struct ClusterWalker {
  RawTrial raw;
  Leg left, right;
};

ClusterWalker clusterWalker(double leftShank = 420, double rightShank = 420) {
  ClusterWalker w;
  w.left.shankMm = leftShank;
  w.right.shankMm = rightShank;
  w.raw.file = "clusters.c3d";
  w.raw.format = "C3D";
  w.raw.rateHz = 100;
  w.raw.units = "mm";
  w.raw.positionsMm.resize(kFrames, 0);
  // The pelvis cluster on the right of the sacrum, carried forward without turning.
  const std::vector<Vector3d> pelvis = {{-120, -40, 950}, {-110, -90, 1000}, {-90, -20, 1040}};
  for (std::size_t k = 0; k < pelvis.size(); ++k) {
    addMarker(w.raw, "RPV" + std::to_string(k + 1),
              [&](int f) { return Vector3d(pelvis[k] + Vector3d(12.0 * f, 0, 0)); });
  }
  addLeg(w.raw, "L", 1, w.left);
  addLeg(w.raw, "R", -1, w.right);
  return w;
}

double worstError(const JointTrial& t, Joint j, const std::vector<Vector3d>& truth) {
  double worst = 0;
  for (int f = 0; f < t.frameCount(); ++f)
    worst = std::max(worst, (jointAt(t.positionsMm, f, j) - truth[static_cast<std::size_t>(f)]).norm());
  return worst;
}

// [SECTION] Fixture tests ---------------------------------------------------------------------

// The fixture's hips are 176 mm apart, its knees hinges straight below them, its ankles move
// about two axes. The ankles come back exactly (1e-6 mm of rounding). The hips' 7 degrees
// of abduction fall below SCoRE's hinge threshold (5 % of the largest singular value), as a
// gait trial's do, so each hip is taken on its fitted flexion axis: measured 2.33 mm off,
// and the knees, anchored on them, 0.13 mm.
TEST(SegmentClusters, RecoversTheJointsOfAClusterWalker) {
  const ClusterWalker w = clusterWalker();
  const JointTrial t = mapMarkerSet(w.raw);
  EXPECT_EQ(t.source, "Segment clusters (Vicon 370 / Motion Lab technical triads)");
  EXPECT_LT(worstError(t, Joint::LHip, w.left.hip), 3.0);
  EXPECT_LT(worstError(t, Joint::RHip, w.right.hip), 3.0);
  EXPECT_LT(worstError(t, Joint::LKnee, w.left.knee), 0.5);
  EXPECT_LT(worstError(t, Joint::RKnee, w.right.knee), 0.5);
  EXPECT_LT(worstError(t, Joint::LAnkle, w.left.ankle), 1e-6);
  EXPECT_LT(worstError(t, Joint::RAnkle, w.right.ankle), 1e-6);
  for (Joint j : {Joint::LHip, Joint::RHip, Joint::LKnee, Joint::RKnee, Joint::LAnkle, Joint::RAnkle})
    EXPECT_TRUE(t.estimated[static_cast<std::size_t>(index(j))]) << jointName(j);
  for (Joint j : {Joint::Head, Joint::Sternum, Joint::LWrist})
    EXPECT_TRUE(t.missing[static_cast<std::size_t>(index(j))]) << jointName(j);
}

// Hips asked wider than they are: kept on their line about their midpoint (the fixture's
// mid-hip, within the 0.2 mm the hinge threshold costs here) and set that width apart.
TEST(SegmentClusters, SymmetricHipsKeepTheMidpointAndSetTheWidth) {
  const ClusterWalker w = clusterWalker();
  const auto tracks = [&](const std::string& prefix) {
    std::vector<MarkerTrack> out;
    for (std::size_t k = 0; k < w.raw.labels.size(); ++k) {
      if (w.raw.labels[k].rfind(prefix, 0) == 0)
        out.emplace_back(w.raw.positionsMm.middleCols(3 * static_cast<int>(k), 3));
    }
    return out;
  };
  const HipPair h = symmetricFunctionalHips(tracks("RPV"), tracks("LTH"), tracks("RTH"), 250);
  for (int f : {0, 77, 199}) {
    const Vector3d l = h.left.row(f).transpose(), r = h.right.row(f).transpose();
    const Vector3d mid = 0.5 * (w.left.hip[static_cast<std::size_t>(f)] + w.right.hip[static_cast<std::size_t>(f)]);
    EXPECT_NEAR((l - r).norm(), 250, 1e-6);
    EXPECT_LT((0.5 * (l + r) - mid).norm(), 0.5);
    EXPECT_GT((l - r).normalized().y(), 0.999);  // left on +y, within 2.6 degrees
  }
}

TEST(SegmentClusters, LegsOfUnequalLengthAreRefusedWithTheirLengths) {
  const auto problem = [](double left, double right) {
    try {
      mapMarkerSet(clusterWalker(left, right).raw);
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::BadData);
      EXPECT_EQ(e.file(), "clusters.c3d");
      return e.problem();
    }
    return std::string("accepted");
  };
  const std::string unequal = problem(420, 330);
  EXPECT_NE(unequal.find("implausible (left shank 420 mm, right 330 mm: 24 % apart, more than 10 %)"),
            std::string::npos)
      << unequal;
  const std::string shortShanks = problem(260, 260);
  EXPECT_NE(shortShanks.find("shanks 0.60 of the thighs' length, outside 0.80-1.35"),
            std::string::npos)
      << shortShanks;
  EXPECT_EQ(problem(400, 420), "accepted");  // 5 % apart: a person
}

TEST(SegmentClusters, MalformedFunctionalHipRulesNameTheKey) {
  const auto keyOf = [](const std::string& rule) {
    const std::string text =
        R"({"name": "x", "identify": ["A"], "joints": {"l_hip": [)" + rule + "]}}";
    try {
      parseMarkerSetTable(text, "t.json");
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Malformed);
      EXPECT_EQ(e.file(), "t.json");
      return e.position();
    }
    return std::string("accepted");
  };
  const std::string clusters =
      R"("pelvis": ["P1", "P2", "P3"], "thigh": ["T1", "T2", "T3"], "other_thigh": ["U1", "U2", "U3"])";
  EXPECT_EQ(keyOf(R"({"op": "functional_hip", "side": "left", )" + clusters + R"(, "width_mm": 176})"),
            "accepted");
  EXPECT_EQ(keyOf(R"({"op": "functional_hip", "side": "left", )" + clusters + "}"),
            "joints.l_hip[0].width_mm");
  EXPECT_EQ(keyOf(R"({"op": "functional_hip", "side": "left", )" + clusters + R"(, "width_mm": 1760})"),
            "joints.l_hip[0].width_mm");
  EXPECT_EQ(keyOf(R"({"op": "functional_hip", "side": "left", )" + clusters + R"(, "width_mm": "wide"})"),
            "joints.l_hip[0].width_mm");
  EXPECT_EQ(keyOf(R"({"op": "functional_hip", "side": "up", )" + clusters + R"(, "width_mm": 176})"),
            "joints.l_hip[0].side");
  EXPECT_EQ(keyOf(R"({"op": "functional_hip", "side": "left", "pelvis": ["P1", "P2"], "thigh": ["T1", "T2", "T3"], "other_thigh": ["U1", "U2", "U3"], "width_mm": 176})"),
            "joints.l_hip[0]");
  EXPECT_EQ(keyOf(R"({"op": "functional_hip", "side": "left", "pelvis": ["P1", "P2", "P3"], "thigh": ["T1", "T2", "T3"], "width_mm": 176})"),
            "joints.l_hip[0].other_thigh");
}

// [SECTION] Real data -------------------------------------------------------------------------

double meanDistance(const JointTrial& t, Joint a, Joint b) {
  double sum = 0;
  int n = 0;
  for (int f = 0; f < t.frameCount(); ++f) {
    const double d = (jointAt(t.positionsMm, f, a) - jointAt(t.positionsMm, f, b)).norm();
    if (std::isfinite(d)) sum += d, ++n;
  }
  return n ? sum / n : NAN;
}

// The Vicon 370 sample: thighs 429/425 mm, shanks 423/429 mm, hips 176 mm apart (measured).
TEST(SegmentClusters, Vicon370SampleGivesHumanLegs) {
  EW_REQUIRE_SHARED_DATA();
  const JointTrial t = mapMarkerSet(
      readC3d(test::sharedDataDir() / "c3d-samples/sample02_vicon370_encodings/pc_real.c3d"));
  EXPECT_EQ(t.source, "Segment clusters (Vicon 370 / Motion Lab technical triads)");
  EXPECT_NEAR(meanDistance(t, Joint::LHip, Joint::RHip), 176, 1e-6);
  for (const auto& [a, b] : {std::pair{Joint::LHip, Joint::LKnee}, std::pair{Joint::RHip, Joint::RKnee},
                             std::pair{Joint::LKnee, Joint::LAnkle}, std::pair{Joint::RKnee, Joint::RAnkle}}) {
    EXPECT_GT(meanDistance(t, a, b), 380) << jointName(a) << "-" << jointName(b);
    EXPECT_LT(meanDistance(t, a, b), 470) << jointName(a) << "-" << jointName(b);
  }
}

TEST(SegmentClusters, TestbpiLegsAreRefusedAsImplausible) {
  EW_REQUIRE_SHARED_DATA();
  const auto file = test::sharedDataDir() / "c3d-samples/sample08_header_pointers/TESTBPI.c3d";
  EXPECT_TRUE(test::throwsError([&] { mapMarkerSet(readC3d(file)); }, ErrorKind::BadData,
                                {"TESTBPI.c3d", "implausible", "shanks 0.75 of the thighs' length"}));
}

// Where the truth is known: on the 16 full-marker Schreiber trials, pelvis cluster R_IAS R_IPS L_IAS and
// thigh FTC FLE FME, the symmetric functional hips against the Harrington hips. Measured:
// mean 38.2 mm (the plain fits: 57.6 mm, 132-328 mm apart).
TEST(SegmentClusters, SymmetricHipsNearTheHarringtonHipsOnSchreiberTrials) {
  EW_REQUIRE_SHARED_DATA();
  const auto track = test::markerTrack;
  double sum = 0;
  int n = 0;
  std::ifstream list(test::sharedDataDir() / "walkers.csv");
  std::string line;
  while (std::getline(list, line)) {
    if (line.find(",schreiber-moissenet-2019,") == std::string::npos) continue;
    const RawTrial r = readC3d(test::sharedDataDir() / line.substr(0, line.find(',')));
    if (r.pointCount() != 52) continue;  // the 48-marker trials lack the trochanter (FTC)
    const JointTrial isb = mapMarkerSet(r);
    const auto thigh = [&](const std::string& s) {
      return std::vector<MarkerTrack>{track(r, s + "FTC"), track(r, s + "FLE"), track(r, s + "FME")};
    };
    const HipPair h = symmetricFunctionalHips({track(r, "R_IAS"), track(r, "R_IPS"), track(r, "L_IAS")},
                                              thigh("L_"), thigh("R_"), 176);
    for (const auto& [got, joint] : {std::pair{&h.left, Joint::LHip}, std::pair{&h.right, Joint::RHip}}) {
      // NaN when a marker is missing or no frame has both: fails the assertion.
      const double d = test::meanTrackDistanceMm(*got, isb.positionsMm.middleCols(3 * index(joint), 3));
      ASSERT_TRUE(std::isfinite(d)) << r.file;
      EXPECT_LT(d, 100.0) << r.file << " " << jointName(joint);
      sum += d, ++n;
    }
  }
  ASSERT_EQ(n, 32);
  EXPECT_LT(sum / n, 45.0);
  std::printf("symmetric functional hips vs Harrington: mean %.1f mm over %d hips\n", sum / n, n);
}

}  // namespace
}  // namespace ew

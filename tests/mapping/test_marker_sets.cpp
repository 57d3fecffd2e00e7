// Marker sets -> 15 joints on the real trials: every Schreiber C4 walker maps, segment
// lengths are human and rigid, the right side is on the walker's right, the 48-marker
// trials fall back with warnings, PiG/Helen Hayes sample files map, unknown sets say why.

#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/io/c3d_reader.h"
#include "core/mapping/joint_mapping.h"
#include "core/mapping/marker_sets.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

using Eigen::Vector3d;

// [SECTION] Helpers ---------------------------------------------------------------------

std::vector<std::filesystem::path> schreiberWalkers() {
  std::vector<std::filesystem::path> files;
  std::ifstream in(test::sharedDataDir() / "walkers.csv");
  std::string line;
  while (std::getline(in, line)) {
    if (line.find(",schreiber-moissenet-2019,") == std::string::npos) continue;
    files.push_back(test::sharedDataDir() / line.substr(0, line.find(',')));
  }
  return files;
}

std::vector<double> distances(const JointTrial& t, Joint a, Joint b) {
  std::vector<double> d;
  for (int f = 0; f < t.frameCount(); ++f) {
    const double v = (jointAt(t.positionsMm, f, a) - jointAt(t.positionsMm, f, b)).norm();
    if (std::isfinite(v)) d.push_back(v);
  }
  return d;
}

struct Stats {
  double mean = 0, cv = 0;
};

Stats stats(const std::vector<double>& v) {
  Stats s;
  if (v.empty()) return {NAN, NAN};
  for (double x : v) s.mean += x;
  s.mean /= static_cast<double>(v.size());
  double var = 0;
  for (double x : v) var += (x - s.mean) * (x - s.mean);
  s.cv = std::sqrt(var / static_cast<double>(v.size())) / s.mean;
  return s;
}

bool hasWarning(const JointTrial& t, const std::string& text) {
  for (const auto& w : t.warnings) {
    if (w.find(text) != std::string::npos) return true;
  }
  return false;
}

// Segment, plausible adult range of its mean length (mm). Ranges: Winter (2009) segment
// fractions of stature (thigh 0.245 H, shank 0.246 H, upper arm 0.186 H, forearm 0.146 H)
// for statures 1.50-1.95 m, widened by 15 % for marker-based joint centres (upper arm
// lower bound 200 mm: the Rab shoulder drop shortens it, 225-298 mm measured on these
// trials, and the acromion marker's skin motion gives it the largest CV, up to 4.8 %); hip-centre
// distance 140-230 mm (Harrington et al. 2007 adult pelvis widths 200-280 mm).
struct Segment {
  const char* name;
  Joint a, b;
  double minMm, maxMm;
};
const std::vector<Segment> kSegments = {
    {"l thigh", Joint::LHip, Joint::LKnee, 310, 550},
    {"r thigh", Joint::RHip, Joint::RKnee, 310, 550},
    {"l shank", Joint::LKnee, Joint::LAnkle, 310, 550},
    {"r shank", Joint::RKnee, Joint::RAnkle, 310, 550},
    {"l upper arm", Joint::LShoulder, Joint::LElbow, 200, 420},
    {"r upper arm", Joint::RShoulder, Joint::RElbow, 200, 420},
    {"l forearm", Joint::LElbow, Joint::LWrist, 180, 330},
    {"r forearm", Joint::RElbow, Joint::RWrist, 180, 330},
    {"pelvis width", Joint::LHip, Joint::RHip, 140, 230},
};

// Walking direction: the pelvis's horizontal displacement over the trial (these are
// overground trials, 1.3-2.6 m of travel), with z up (Schreiber lab frame).
Vector3d progression(const JointTrial& t) {
  Vector3d d = jointAt(t.positionsMm, t.frameCount() - 1, Joint::Pelvis) -
               jointAt(t.positionsMm, 0, Joint::Pelvis);
  d.z() = 0;
  return d.normalized();
}

// Mean over frames of the signed lateral offset of right minus left joint, measured along
// forward x up (= the walker's right when z is up).
double meanRightward(const JointTrial& t, Joint right, Joint left) {
  const Vector3d rightDir = progression(t).cross(Vector3d::UnitZ());
  double sum = 0;
  for (int f = 0; f < t.frameCount(); ++f) {
    sum += rightDir.dot(jointAt(t.positionsMm, f, right) - jointAt(t.positionsMm, f, left));
  }
  return sum / t.frameCount();
}

// [SECTION] Schreiber-Moissenet (ISB) --------------------------------------------------------

TEST(MarkerSetsIsb, AllEighteenWalkersMapWithHumanRigidSegments) {
  EW_REQUIRE_SHARED_DATA();
  const auto files = schreiberWalkers();
  ASSERT_EQ(files.size(), 18u);
  for (const auto& file : files) {
    SCOPED_TRACE(file.filename().string());
    const JointTrial t = mapMarkerSet(readC3d(file));
    EXPECT_EQ(t.source, "ISB (Schreiber-Moissenet)");
    EXPECT_EQ(t.positionsMm.cols(), kDims3);
    EXPECT_FALSE(t.positionsMm.array().isNaN().any()) << "no gaps in these trials";
    EXPECT_TRUE(t.estimated[index(Joint::Head)]);
    EXPECT_TRUE(hasWarning(t, "head estimated"));
    for (Joint j : {Joint::Pelvis, Joint::Sternum, Joint::LHip, Joint::RShoulder, Joint::LElbow,
                    Joint::RWrist}) {
      EXPECT_FALSE(t.estimated[index(j)]) << jointName(j);
    }
    for (const auto& seg : kSegments) {
      const Stats s = stats(distances(t, seg.a, seg.b));
      EXPECT_GE(s.mean, seg.minMm) << seg.name;
      EXPECT_LE(s.mean, seg.maxMm) << seg.name;
      EXPECT_LT(s.cv, 0.05) << seg.name << " length varies over the trial";
    }
    // Trunk: pelvis centre to neck base, ~0.29 H (Winter): 400-620 mm.
    const Stats trunk = stats(distances(t, Joint::Pelvis, Joint::Sternum));
    EXPECT_GT(trunk.mean, 400);
    EXPECT_LT(trunk.mean, 620);
  }
}

TEST(MarkerSetsIsb, RightJointsAreOnTheWalkersRight) {
  EW_REQUIRE_SHARED_DATA();
  int towardsPlusX = 0;
  for (const auto& file : schreiberWalkers()) {
    SCOPED_TRACE(file.filename().string());
    const JointTrial t = mapMarkerSet(readC3d(file));
    towardsPlusX += progression(t).x() > 0;
    EXPECT_GT(meanRightward(t, Joint::RHip, Joint::LHip), 100.0);
    EXPECT_GT(meanRightward(t, Joint::RShoulder, Joint::LShoulder), 200.0);
    EXPECT_GT(meanRightward(t, Joint::RKnee, Joint::LKnee), 50.0);
    EXPECT_GT(meanRightward(t, Joint::RAnkle, Joint::LAnkle), 0.0);
    // Head and sternum lie above the pelvis.
    EXPECT_GT(jointAt(t.positionsMm, 0, Joint::Head).z(), jointAt(t.positionsMm, 0, Joint::Sternum).z());
    EXPECT_GT(jointAt(t.positionsMm, 0, Joint::Sternum).z(), jointAt(t.positionsMm, 0, Joint::Pelvis).z());
  }
  // PROVENANCE: about half the trials walk towards +X: the check above saw both headings.
  EXPECT_GT(towardsPlusX, 2);
  EXPECT_LT(towardsPlusX, 16);
}

TEST(MarkerSetsIsb, FortyEightMarkerTrialsFallBackWithWarnings) {
  EW_REQUIRE_SHARED_DATA();
  for (const char* rel : {"2015026/2015026_C4_04.c3d", "2015032/2015032_C4_03.c3d"}) {
    SCOPED_TRACE(rel);
    const RawTrial raw = readC3d(test::sharedDataDir() / "schreiber-moissenet-2019" / rel);
    ASSERT_EQ(raw.pointCount(), 48);
    const JointTrial t = mapMarkerSet(raw);
    for (Joint j : {Joint::LKnee, Joint::RKnee, Joint::LAnkle, Joint::RAnkle}) {
      EXPECT_TRUE(t.estimated[index(j)]) << jointName(j);
      EXPECT_TRUE(hasWarning(t, std::string(jointName(j)) + " estimated")) << jointName(j);
    }
    EXPECT_FALSE(t.estimated[index(Joint::LElbow)]);
    EXPECT_FALSE(t.positionsMm.array().isNaN().any());
    for (const auto& seg : kSegments) {
      const Stats s = stats(distances(t, seg.a, seg.b));
      EXPECT_GE(s.mean, seg.minMm) << seg.name;
      EXPECT_LE(s.mean, seg.maxMm) << seg.name;
      EXPECT_LT(s.cv, 0.05) << seg.name;
    }
  }
}

// The lateral-only rule, tried where the truth is known: hide the medial markers of a
// complete trial and compare with the epicondyle / malleolus midpoints.
TEST(MarkerSetsIsb, LateralOnlyFallbackIsCloseToTheMidpoints) {
  EW_REQUIRE_SHARED_DATA();
  for (const auto& file : schreiberWalkers()) {
    RawTrial raw = readC3d(file);
    if (raw.pointCount() != 52) continue;
    SCOPED_TRACE(file.filename().string());
    const JointTrial full = mapMarkerSet(raw);
    for (auto& label : raw.labels) {
      if (label.ends_with("_FME") || label.ends_with("_TAM")) label = "hidden_" + label;
    }
    const JointTrial lateral = mapMarkerSet(raw);
    for (Joint j : {Joint::LKnee, Joint::RKnee, Joint::LAnkle, Joint::RAnkle}) {
      double sum = 0;
      for (int f = 0; f < full.frameCount(); ++f) {
        sum += (jointAt(full.positionsMm, f, j) - jointAt(lateral.positionsMm, f, j)).norm();
      }
      EXPECT_LT(sum / full.frameCount(), 30.0) << jointName(j);
    }
  }
}

TEST(MarkerSetsIsb, SubjectPrefixesAndCaseAreIgnored) {
  EW_REQUIRE_SHARED_DATA();
  RawTrial raw = readC3d(schreiberWalkers().front());
  const JointTrial plain = mapMarkerSet(raw);
  for (auto& label : raw.labels) {
    std::string lower;
    for (char c : label) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    label = "Subject01:" + lower;
  }
  const JointTrial prefixed = mapMarkerSet(raw);
  EXPECT_EQ(prefixed.source, plain.source);
  EXPECT_TRUE(prefixed.positionsMm.isApprox(plain.positionsMm));
  EXPECT_EQ(normaliseMarkerLabel(" Subject:lasi "), "LASI");
}

// [SECTION] Plug-in Gait / Helen Hayes and CMU ------------------------------------------------

TEST(MarkerSetsPlugInGait, HelenHayesSampleFilesMap) {
  EW_REQUIRE_SHARED_DATA();
  for (const char* rel : {"sample03_vicon370_gait/gait-raw.c3d",
                          "sample06_motion_analysis/newwalk.c3d"}) {
    SCOPED_TRACE(rel);
    const JointTrial t = mapMarkerSet(readC3d(test::sharedDataDir() / "c3d-samples" / rel));
    EXPECT_EQ(t.source, "Plug-in Gait / Helen Hayes");
    EXPECT_TRUE(t.estimated[index(Joint::LKnee)]);
    if (std::string(rel).find("gait-raw") != std::string::npos) {
      // Its arm markers are labelled but have no position in any frame: the upper body is
      // missing (to be estimated from a model), not built from NaN.
      for (Joint j : {Joint::Head, Joint::Sternum, Joint::RShoulder, Joint::LWrist})
        EXPECT_TRUE(t.missing[index(j)]) << jointName(j);
    } else {
      EXPECT_TRUE(t.estimated[index(Joint::Head)]);
      EXPECT_TRUE(t.estimated[index(Joint::Sternum)]);
      EXPECT_TRUE(t.estimated[index(Joint::RWrist)]);
      EXPECT_TRUE(hasWarning(t, "sternum estimated"));
    }
    // These old captures have long gaps; where the thigh is visible it has a human length.
    const Stats thigh = stats(distances(t, Joint::LHip, Joint::LKnee));
    EXPECT_GT(thigh.mean, 300);
    EXPECT_LT(thigh.mean, 550);
  }
}

TEST(MarkerSetsPlugInGait, LowerBodyOnlyFilesMapWithTheUpperBodyMissing) {
  EW_REQUIRE_SHARED_DATA();
  for (const char* rel : {"sample00_vicon_nexus/pyCGM2 lower limb CGM24 Walking01.c3d",
                          "sample03_vicon370_gait/gait-pig-nz.c3d"}) {
    SCOPED_TRACE(rel);
    const JointTrial t = mapMarkerSet(readC3d(test::sharedDataDir() / "c3d-samples" / rel));
    EXPECT_EQ(t.source, "Plug-in Gait / Helen Hayes");
    for (Joint j : {Joint::Head, Joint::Sternum, Joint::RShoulder, Joint::RElbow, Joint::RWrist,
                    Joint::LShoulder, Joint::LElbow, Joint::LWrist}) {
      EXPECT_TRUE(t.missing[index(j)]) << jointName(j);
    }
    for (Joint j : {Joint::Pelvis, Joint::LHip, Joint::RHip, Joint::LKnee, Joint::RKnee,
                    Joint::LAnkle, Joint::RAnkle}) {
      EXPECT_FALSE(t.missing[index(j)]) << jointName(j);
    }
    const Stats thigh = stats(distances(t, Joint::LHip, Joint::LKnee));
    EXPECT_GT(thigh.mean, 300);
    EXPECT_LT(thigh.mean, 550);
    const Stats shank = stats(distances(t, Joint::RKnee, Joint::RAnkle));
    EXPECT_GT(shank.mean, 300);
    EXPECT_LT(shank.mean, 550);
  }
}

// No CMU C3D is in the shared data (the CMU trials there are BVH/AMC), so the CMU rules
// are exercised on a Schreiber trial relabelled to the CMU names, with head markers placed
// around the estimated head: the mapping must pick the CMU set and agree with ISB where
// the two sets measure the same landmarks.
TEST(MarkerSetsCmu, RelabelledTrialMapsAsCmu) {
  EW_REQUIRE_SHARED_DATA();
  const RawTrial isb = readC3d(schreiberWalkers().front());
  const JointTrial reference = mapMarkerSet(isb);
  const std::vector<std::pair<std::string, std::string>> names = {
      {"L_IAS", "LFWT"}, {"R_IAS", "RFWT"}, {"L_IPS", "LBWT"}, {"R_IPS", "RBWT"},
      {"L_FLE", "LKNE"}, {"R_FLE", "RKNE"}, {"L_FAL", "LANK"}, {"R_FAL", "RANK"},
      {"L_SAA", "LSHO"}, {"R_SAA", "RSHO"}, {"L_HLE", "LELB"}, {"R_HLE", "RELB"},
      {"L_RSP", "LWRA"}, {"R_RSP", "RWRA"}, {"L_UHE", "LWRB"}, {"R_UHE", "RWRB"},
      {"CV7", "C7"},     {"SJN", "CLAV"}};
  RawTrial cmu = isb;
  cmu.labels.clear();
  cmu.positionsMm.resize(isb.frameCount(), 3 * (static_cast<int>(names.size()) + 4));
  for (std::size_t k = 0; k < names.size(); ++k) {
    const auto it = std::find(isb.labels.begin(), isb.labels.end(), names[k].first);
    ASSERT_NE(it, isb.labels.end());
    cmu.labels.push_back(names[k].second);
    cmu.positionsMm.middleCols(3 * static_cast<int>(k), 3) =
        isb.positionsMm.middleCols(3 * (it - isb.labels.begin()), 3);
  }
  const Eigen::Vector3d offsets[4] = {{60, 60, 0}, {-60, 60, 0}, {60, -60, 0}, {-60, -60, 0}};
  const char* head[4] = {"LFHD", "RFHD", "LBHD", "RBHD"};
  for (int k = 0; k < 4; ++k) {
    cmu.labels.push_back(head[k]);
    const int c = 3 * (static_cast<int>(names.size()) + k);
    for (int f = 0; f < cmu.frameCount(); ++f) {
      cmu.positionsMm.block<1, 3>(f, c) =
          (jointAt(reference.positionsMm, f, Joint::Head) + offsets[k]).transpose();
    }
  }
  const JointTrial t = mapMarkerSet(cmu);
  EXPECT_EQ(t.source, "CMU 41-marker");
  EXPECT_FALSE(t.estimated[index(Joint::Head)]);
  EXPECT_TRUE(t.estimated[index(Joint::LKnee)]);
  for (Joint j : {Joint::Head, Joint::Sternum, Joint::Pelvis, Joint::LHip, Joint::RShoulder,
                  Joint::LWrist}) {
    const double d = (jointAt(t.positionsMm, 0, j) - jointAt(reference.positionsMm, 0, j)).norm();
    EXPECT_LT(d, 1e-6) << jointName(j);
  }
}

// [SECTION] Unknown sets and the shared rules ---------------------------------------------------

TEST(MarkerSetsUnknown, UnknownLabelsThrowListingTheLabelsAndTheNeeds) {
  EW_REQUIRE_SHARED_DATA();
  // A real walk whose labels no set knows: the Vicon 370 sample's clusters renamed.
  RawTrial raw =
      readC3d(test::sharedDataDir() / "c3d-samples/sample02_vicon370_encodings/pc_real.c3d");
  for (auto& label : raw.labels) label = "Q" + label;
  try {
    mapMarkerSet(raw);
    ADD_FAILURE() << "unknown set mapped";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::UnknownMarkerSet);
    const std::string msg = e.what();
    EXPECT_NE(msg.find("QRFT1 QRFT2 QRFT3 QRSK1"), std::string::npos) << msg;
    for (const auto& set : knownMarkerSets()) EXPECT_NE(msg.find(set.name + " needs"), std::string::npos);
    EXPECT_NE(msg.find("pc_real.c3d"), std::string::npos);
  }
}

TEST(MarkerSetsUnknown, SyntheticLabelsThrow) {
  RawTrial raw;
  raw.file = "made_up.c3d";
  raw.labels = {"FOO", "BAR"};
  raw.positionsMm = Eigen::MatrixXd::Zero(3, 6);
  EXPECT_THROW(mapMarkerSet(raw), Error);
}

TEST(MarkerSetsRules, HarringtonHipCentresSitBelowBehindAndInsideTheAsis) {
  // Pelvis with z right, x anterior, y up in the lab frame: ASIS 240 mm apart, PSIS 160 mm
  // behind. Expected from the regression: x = -0.24*160 - 9.9 = -48.3,
  // y = -0.30*240 - 10.9 = -82.9, z = +/-(0.33*240 + 7.3) = +/-86.5.
  const Vector3d lAsis(-120, 0, 0), rAsis(120, 0, 0);
  // Lab axes: x right, y forward, z up; the ISB pelvis frame maps x->forward, y->up, z->right.
  const Vector3d psis(0, -160, 0);
  const HipCentres h = harringtonHipCentres(lAsis, rAsis, psis);
  EXPECT_NEAR(h.right.x(), 86.5, 1e-9);
  EXPECT_NEAR(h.left.x(), -86.5, 1e-9);
  EXPECT_NEAR(h.right.y(), -48.3, 1e-9);
  EXPECT_NEAR(h.right.z(), -82.9, 1e-9);
  EXPECT_TRUE(harringtonHipCentres(Vector3d::Constant(NAN), rAsis, psis).right.array().isNaN().all());
}

}  // namespace
}  // namespace ew

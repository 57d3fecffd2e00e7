// An .asf skeleton and its .amc motions opened together: both files (either order), the
// .asf alone, or their folder, all give the AMC trials, each read with that skeleton.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/common/errors.h"
#include "core/gait/dataset.h"
#include "core/io/load_trial.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

namespace fs = std::filesystem;

// A root and one bone up +y, two frames (the reader's own tests cover the kinematics).
const char* kAsf =
    ":version 1.10\n:name tiny\n:units\n  mass 1.0\n  length 1.0\n  angle deg\n"
    ":root\n   order TX TY TZ RX RY RZ\n   axis XYZ\n   position 0 0 0\n"
    "   orientation 0 0 0\n:bonedata\n  begin\n     id 1\n     name a\n"
    "     direction 0 1 0\n     length 2\n     axis 0 0 0 XYZ\n    dof rx\n"
    "    limits (-180.0 180.0)\n  end\n:hierarchy\n  begin\n    root a\n  end\n";
const char* kAmc =
    ":FULLY-SPECIFIED\n:DEGREES\n1\nroot 1 2 3 0 0 0\na 0\n2\nroot 2 2 3 0 0 0\na 10\n";

fs::path writeSkeletonFolder(const std::string& stem) {
  const fs::path dir = test::makeTempDir(stem);
  std::ofstream(dir / "07.asf") << kAsf;
  std::ofstream(dir / "07_01.amc") << kAmc;
  std::ofstream(dir / "07_02.amc") << kAmc;
  return dir;
}

std::vector<fs::path> collected(const std::vector<fs::path>& paths) {
  std::vector<std::string> warnings;
  std::vector<fs::path> out;
  for (const auto& t : collectTrialFiles(paths, warnings)) out.push_back(t.path);
  EXPECT_TRUE(warnings.empty()) << warnings.front();
  return out;
}

TEST(AsfAmcTogether, BothFilesInEitherOrderGiveTheOneTrial) {
  const fs::path dir = writeSkeletonFolder("asf_amc_pair");
  const std::vector<fs::path> want = {dir / "07_01.amc"};
  EXPECT_EQ(collected({dir / "07.asf", dir / "07_01.amc"}), want);
  EXPECT_EQ(collected({dir / "07_01.amc", dir / "07.asf"}), want);
  const RawTrial raw = readRawTrial(want.front());
  EXPECT_EQ(raw.format, "ASF/AMC");
  EXPECT_EQ(raw.frameCount(), 2);
}

TEST(AsfAmcTogether, TheSkeletonAloneOrTheFolderOpenEveryMotion) {
  const fs::path dir = writeSkeletonFolder("asf_amc_alone");
  const std::vector<fs::path> want = {dir / "07_01.amc", dir / "07_02.amc"};
  EXPECT_EQ(collected({dir / "07.asf"}), want);
  EXPECT_EQ(collected({dir}), want);
}

// The viewer opens dropped items one by one: the .asf dropped with its .amc is no item.
TEST(AsfAmcTogether, DroppedTogetherTheSkeletonIsNoItemOfItsOwn) {
  const fs::path dir = writeSkeletonFolder("asf_amc_drop");
  const std::vector<fs::path> dropped = {dir / "07.asf", dir / "07_02.amc", dir / "other.c3d"};
  EXPECT_EQ(withoutSkeletonsOfGivenMotions(dropped),
            (std::vector<fs::path>{dir / "07_02.amc", dir / "other.c3d"}));
  EXPECT_EQ(withoutSkeletonsOfGivenMotions({dir / "07.asf"}),
            (std::vector<fs::path>{dir / "07.asf"}));
}

TEST(AsfAmcTogether, ASkeletonWithoutMotionSaysSo) {
  const fs::path dir = test::makeTempDir("asf_no_amc");
  std::ofstream(dir / "07.asf") << kAsf;
  std::vector<std::string> warnings;
  try {
    collectTrialFiles({dir / "07.asf"}, warnings);
    ADD_FAILURE();
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_EQ(e.file(), (dir / "07.asf").string());
    EXPECT_NE(std::string(e.what()).find("no .amc motion file"), std::string::npos);
  }
}

}  // namespace
}  // namespace ew

// Model files: exact round trip, atomic writes, clear errors for damaged files.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <sstream>

#include "core/common/errors.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/model_file.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

EigenwalkerModel sampleModel() {
  const Eigen::MatrixXd w = syntheticWalkerSet(9, 21);
  std::vector<std::string> ids, subjects;
  for (int i = 0; i < 9; ++i) {
    subjects.push_back("Sü" + std::to_string(i));  // non-ASCII survives
    ids.push_back(subjects.back() + "/walk \"fast\"");
  }
  auto m = buildModel(w, ids, subjects, Eigen::VectorXd::LinSpaced(9, 5.0, 7.0) / 3.0);
  m.provenance = {"synthetic seed 21", "line two\twith tab"};
  return m;
}

// The error's message, or "" if loading succeeded.
std::string loadError(const std::filesystem::path& p, ErrorKind* kind = nullptr) {
  try {
    loadModel(p);
  } catch (const Error& e) {
    if (kind) *kind = e.kind();
    return e.what();
  }
  return "";
}

std::uint64_t fnv(const std::string& s) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

class ModelFile : public ::testing::Test {
 protected:
  std::filesystem::path dir = test::makeTempDir("model_file");
  std::filesystem::path file = dir / "model.ewm";
  void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(ModelFile, RoundTripIsBitwiseExact) {
  const auto m = sampleModel();
  saveModel(m, file);
  const auto back = loadModel(file);
  EXPECT_TRUE(test::bitwiseEqual(back.mean, m.mean));
  EXPECT_TRUE(test::bitwiseEqual(back.eigenwalkers, m.eigenwalkers));
  EXPECT_TRUE(test::bitwiseEqual(back.eigenvalues, m.eigenvalues));
  EXPECT_TRUE(test::bitwiseEqual(back.spectrum, m.spectrum));
  EXPECT_TRUE(test::bitwiseEqual(back.coefficients, m.coefficients));
  EXPECT_TRUE(test::bitwiseEqual(back.omegasRadS, m.omegasRadS));
  EXPECT_EQ(back.walkerIds, m.walkerIds);
  EXPECT_EQ(back.subjects, m.subjects);
  EXPECT_EQ(back.provenance, m.provenance);
  // Saving the loaded model gives the same bytes.
  saveModel(back, dir / "again.ewm");
  EXPECT_EQ(test::readTextFile(file), test::readTextFile(dir / "again.ewm"));
  // Only the target is left in the folder (no temporary files).
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 2);
}

TEST_F(ModelFile, EveryTruncationIsAnErrorNamingTheFile) {
  saveModel(sampleModel(), file);
  const std::string bytes = test::readTextFile(file);
  const auto cut = dir / "cut.ewm";
  for (size_t size : {size_t{0}, size_t{10}, size_t{25}, bytes.find('\n', 20) + 1,
                      bytes.size() / 2, bytes.size() - 8, bytes.size() - 1}) {
    test::writeBinaryFile(cut, bytes.substr(0, size));
    ErrorKind kind = ErrorKind::Io;
    const std::string message = loadError(cut, &kind);
    EXPECT_EQ(kind, ErrorKind::Malformed) << "size " << size << ": " << message;
    EXPECT_NE(message.find("cut.ewm"), std::string::npos) << message;
    EXPECT_TRUE(message.find("byte") != std::string::npos || message.find("line") != std::string::npos)
        << message;
  }
  test::writeBinaryFile(cut, bytes.substr(0, bytes.size() - 8));
  EXPECT_NE(loadError(cut).find("truncated"), std::string::npos);
}

TEST_F(ModelFile, EveryFlippedBitIsDetected) {
  saveModel(sampleModel(), file);
  const std::string bytes = test::readTextFile(file);
  const auto bad = dir / "flipped.ewm";
  // A flip anywhere: magic, metadata, checksum line, every array of the payload.
  for (size_t at = 0; at < bytes.size(); at += 97) {
    std::string damaged = bytes;
    damaged[at] = static_cast<char>(damaged[at] ^ 0x10);
    test::writeBinaryFile(bad, damaged);
    const std::string message = loadError(bad);
    EXPECT_FALSE(message.empty()) << "flip at byte " << at << " went unnoticed";
    EXPECT_NE(message.find("flipped.ewm"), std::string::npos) << message;
  }
  std::string damaged = bytes;
  damaged[bytes.size() - 3] = static_cast<char>(damaged[bytes.size() - 3] ^ 1);
  test::writeBinaryFile(bad, damaged);
  const std::string message = loadError(bad);
  EXPECT_NE(message.find("checksum mismatch in array 'omegas_rad_s'"), std::string::npos) << message;
}

TEST_F(ModelFile, WrongMagicVersionAndTrailingBytes) {
  test::writeBinaryFile(file, "PLY\nformat ascii\n");
  EXPECT_NE(loadError(file).find("not an eigenwalker model file"), std::string::npos);
  saveModel(sampleModel(), file);
  std::string bytes = test::readTextFile(file);
  test::writeBinaryFile(file, bytes + "x");
  EXPECT_NE(loadError(file).find("unexpected bytes"), std::string::npos);
  bytes.replace(bytes.find(" 1\n"), 3, " 7\n");
  test::writeBinaryFile(file, bytes);
  ErrorKind kind = ErrorKind::Io;
  EXPECT_NE(loadError(file, &kind).find("version 7"), std::string::npos);
  EXPECT_EQ(kind, ErrorKind::Unsupported);
}

// Writes `bytes` (a saved model) to `file` with `from` replaced by `to` in its metadata and the
// checksum made again, so that the checks behind the checksum must catch the edit; the error
// loading it gives ("" if none).
std::string loadEdited(const std::filesystem::path& file, const std::string& bytes, const std::string& from,
                       const std::string& to) {
  const size_t l1 = bytes.find('\n'), l2 = bytes.find('\n', l1 + 1), l3 = bytes.find('\n', l2 + 1);
  std::string meta = bytes.substr(l1 + 1, l2 - l1 - 1);
  const auto at = meta.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  if (at == std::string::npos) return "(not edited)";
  meta.replace(at, from.size(), to);
  char sum[17];
  std::snprintf(sum, sizeof sum, "%016llx", static_cast<unsigned long long>(fnv(meta)));
  test::writeBinaryFile(file, bytes.substr(0, l1 + 1) + meta + "\nfnv1a64 " + sum + "\n" + bytes.substr(l3 + 1));
  return loadError(file);
}

TEST_F(ModelFile, MismatchedSizesAreReported) {
  saveModel(sampleModel(), file);
  const std::string bytes = test::readTextFile(file);
  const auto rewrite = [&](const std::string& from, const std::string& to) { return loadEdited(file, bytes, from, to); };
  EXPECT_NE(rewrite("\"dims\":225", "\"dims\":224").find("dims must be 225"), std::string::npos);
  EXPECT_NE(rewrite("\"walkers\":9", "\"walkers\":10").find("line 2"), std::string::npos);
  EXPECT_NE(rewrite("\"name\":\"spectrum\"", "\"name\":\"spectra\"").find("should be 'spectrum'"),
            std::string::npos);
}

// Each walker's speed (m/s, or unknown) is kept for the gait report's band of the model's walkers.
TEST_F(ModelFile, WalkerSpeedsSurviveARoundTripAndAnOlderFileHasNone) {
  auto m = sampleModel();
  saveModel(m, file);
  EXPECT_TRUE(loadModel(file).speedsMps.empty());  // none recorded: none read back
  EXPECT_EQ(test::readTextFile(file).find("speeds_mps"), std::string::npos);

  for (int r = 0; r < m.walkerCount(); ++r)
    m.speedsMps.push_back(r == 3 ? std::nullopt : std::optional<double>(0.9 + 0.05 * r));
  saveModel(m, file);
  const auto back = loadModel(file);
  ASSERT_EQ(back.speedsMps.size(), 9u);
  EXPECT_FALSE(back.speedsMps[3].has_value());  // a treadmill walker's stays unknown
  for (size_t r = 0; r < 9; ++r) {
    if (r == 3) continue;
    EXPECT_EQ(back.speedsMps[r], m.speedsMps[r]);
  }
}

TEST_F(ModelFile, ADamagedSpeedListIsAnErrorNamingTheKey) {
  auto m = sampleModel();
  m.speedsMps.assign(9, 1.25);
  saveModel(m, file);
  const std::string bytes = test::readTextFile(file);
  const std::string list = "\"speeds_mps\":[1.25,1.25,1.25,1.25,1.25,1.25,1.25,1.25,1.25]";
  ASSERT_NE(bytes.find(list), std::string::npos);
  const auto damaged = [&](const std::string& to) {
    const std::string e = loadEdited(file, bytes, list, to);
    EXPECT_NE(e.find("speeds_mps"), std::string::npos) << to << ": " << e;
    EXPECT_NE(e.find("model.ewm"), std::string::npos) << e;
  };
  damaged("\"speeds_mps\":[1.25,1.25]");                                        // too few
  damaged("\"speeds_mps\":[1.25,1.25,1.25,1.25,-1,1.25,1.25,1.25,1.25]");      // not a speed
  damaged("\"speeds_mps\":[1.25,1.25,1.25,1.25,\"fast\",1.25,1.25,1.25,1.25]");  // not a number
  damaged("\"speeds_mps\":[1.25,1.25,1.25,1.25,1e300,1.25,1.25,1.25,1.25]");   // no walk
  damaged("\"speeds_mps\":{\"a\":1}");                                           // not a list

  // What loading refuses is not saved either.
  m.speedsMps[2] = 0.0;
  EXPECT_THROW(saveModel(m, dir / "bad.ewm"), Error);
  m.speedsMps.pop_back();
  m.speedsMps[2] = 1.0;
  EXPECT_THROW(saveModel(m, dir / "bad.ewm"), Error);
  EXPECT_FALSE(std::filesystem::exists(dir / "bad.ewm"));
}

TEST_F(ModelFile, UnwritableTargetIsAnIoErrorAndLeavesNothing) {
  try {
    saveModel(sampleModel(), dir / "no_such_folder" / "m.ewm");
    FAIL() << "expected an error";
  } catch (const Error& e) {
    EXPECT_EQ(e.kind(), ErrorKind::Io);
    EXPECT_NE(std::string(e.what()).find("m.ewm"), std::string::npos);
  }
  EXPECT_EQ(loadError(dir / "absent.ewm").find("absent.ewm") != std::string::npos, true);
}

TEST_F(ModelFile, OverwriteReplacesTheWholeFile) {
  saveModel(sampleModel(), file);
  auto small = sampleModel();
  small = buildModel(small.eigenwalkers.leftCols(3) * 100.0, {"a", "b", "c"}, {"a", "b", "c"},
                     Eigen::Vector3d(6, 6, 6));
  saveModel(small, file);
  EXPECT_EQ(loadModel(file).walkerCount(), 3);
}

}  // namespace
}  // namespace ew

// The σ² optimum stored in a model file (docs/MODEL_FORMAT.md, "sigma2_optimum"): it
// survives a round trip exactly, older files without it still load (σ² falls back to the
// paper's 70 mm², and says so), and a damaged entry is a typed error naming the file.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <sstream>

#include "core/common/errors.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/model_file.h"
#include "core/eigenwalker/synthetic_walkers.h"
#include "tests/common/test_support.h"

namespace ew {
namespace {

EigenwalkerModel sampleModel() {
  const Eigen::MatrixXd w = syntheticWalkerSet(7, 5);
  std::vector<std::string> ids, subjects;
  for (int i = 0; i < 7; ++i) {
    subjects.push_back("S" + std::to_string(i));
    ids.push_back(subjects.back() + "/walk");
  }
  return buildModel(w, ids, subjects, Eigen::VectorXd::Constant(7, 5.5));
}

Sigma2Optimum sampleOptimum() {
  Sigma2Optimum s;
  s.sigma2Mm2 = 350.0;
  s.meanAbsErrorMm2 = 123.456789012345;
  s.gridMm2 = {1, 10, 350, 5000};
  s.anglesDeg = {-90, -45.5, 0, 45.5, 90};
  s.criterion = "smallest mean E_a";
  s.atGridEdge = false;
  return s;
}

std::string readBytes(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

std::uint64_t fnv(const std::string& s) {
  std::uint64_t h = 14695981039346656037ull;
  for (unsigned char c : s) h = (h ^ c) * 1099511628211ull;
  return h;
}

// The file with its metadata line edited by `edit` and its checksum line made to match,
// so the loader reaches the σ² entry instead of stopping at the checksum.
std::string withMetadata(const std::string& bytes, const std::function<void(std::string&)>& edit) {
  const size_t e1 = bytes.find('\n'), e2 = bytes.find('\n', e1 + 1), e3 = bytes.find('\n', e2 + 1);
  std::string meta = bytes.substr(e1 + 1, e2 - e1 - 1);
  edit(meta);
  char sum[17];
  std::snprintf(sum, sizeof sum, "%016llx", static_cast<unsigned long long>(fnv(meta)));
  return bytes.substr(0, e1 + 1) + meta + "\nfnv1a64 " + sum + bytes.substr(e3);
}

class ModelSigma2 : public ::testing::Test {
 protected:
  std::filesystem::path dir = test::makeTempDir("model_sigma2");
  std::filesystem::path file = dir / "model.ewm";
  void TearDown() override { std::filesystem::remove_all(dir); }
};

TEST_F(ModelSigma2, TheOptimumSurvivesARoundTripExactly) {
  auto m = sampleModel();
  m.sigma2Optimum = sampleOptimum();
  saveModel(m, file);
  const auto back = loadModel(file);
  ASSERT_TRUE(back.sigma2Optimum.has_value());
  EXPECT_EQ(*back.sigma2Optimum, *m.sigma2Optimum);  // doubles written shortest-exact by the JSON
  EXPECT_EQ(defaultSigma2Mm2(back), 350.0);
  EXPECT_NE(defaultSigma2Source(back).find("optimum measured on the model's 7 walkers"),
            std::string::npos);
}

TEST_F(ModelSigma2, AModelWithoutTheOptimumFallsBackToThePapers70) {
  const auto m = sampleModel();  // as an older file: no "sigma2_optimum" key at all
  saveModel(m, file);
  EXPECT_EQ(readBytes(file).find("sigma2_optimum"), std::string::npos);
  const auto back = loadModel(file);
  EXPECT_FALSE(back.sigma2Optimum.has_value());
  EXPECT_EQ(defaultSigma2Mm2(back), kPaperSigma2Mm2);
  EXPECT_EQ(kPaperSigma2Mm2, 70.0);
  EXPECT_NE(defaultSigma2Source(back).find("the paper's 70 mm2"), std::string::npos);
}

TEST_F(ModelSigma2, ADamagedEntryIsAnErrorNamingTheFileAndTheKey) {
  auto m = sampleModel();
  m.sigma2Optimum = sampleOptimum();
  saveModel(m, file);
  const std::string good = readBytes(file);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"\"sigma2_mm2\":350.0", "\"sigma2_mm2\":-1.0"},
      {"\"sigma2_mm2\":350.0", "\"sigma2_mm2\":\"350\""},
      {"\"grid_mm2\":[1.0,10.0,350.0,5000.0]", "\"grid_mm2\":[1.0,\"x\"]"},
      {"\"criterion\":\"smallest mean E_a\"", "\"criterion\":3"},
  };
  for (const auto& fromTo : cases) {
    // Named copies: clang 14 cannot capture structured bindings in a lambda.
    const std::string& from = fromTo.first;
    const std::string& to = fromTo.second;
    const std::string bad = withMetadata(good, [&](std::string& meta) {
      const size_t at = meta.find(from);
      ASSERT_NE(at, std::string::npos) << from << " not in " << meta;
      meta.replace(at, from.size(), to);
    });
    try {
      parseModel(bad, "damaged.ewm");
      ADD_FAILURE() << "accepted " << to;
    } catch (const Error& e) {
      EXPECT_EQ(e.kind(), ErrorKind::Malformed) << e.what();
      EXPECT_NE(std::string(e.what()).find("damaged.ewm"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("sigma2_optimum"), std::string::npos) << e.what();
    }
  }
}

TEST_F(ModelSigma2, ANonPositiveOptimumIsNotSaved) {
  auto m = sampleModel();
  m.sigma2Optimum = sampleOptimum();
  m.sigma2Optimum->sigma2Mm2 = 0.0;
  EXPECT_THROW(saveModel(m, file), Error);
  EXPECT_FALSE(std::filesystem::exists(file));
}

TEST(LeadingComponents, KeepsTheFirstNEigenwalkersAndEverythingElse) {
  const auto m = sampleModel();
  ASSERT_GE(m.componentCount(), 3);
  const auto t = leadingComponents(m, 2);
  EXPECT_EQ(t.componentCount(), 2);
  EXPECT_EQ(t.eigenwalkers, m.eigenwalkers.leftCols(2));
  EXPECT_EQ(t.eigenvalues, m.eigenvalues.head(2));
  EXPECT_EQ(t.coefficients, m.coefficients.topRows(2));
  EXPECT_EQ(t.mean, m.mean);
  EXPECT_EQ(t.spectrum, m.spectrum);
  EXPECT_EQ(leadingComponents(m, 0).componentCount(), 1);  // clamped
  EXPECT_EQ(leadingComponents(m, 999).componentCount(), m.componentCount());
}

}  // namespace
}  // namespace ew

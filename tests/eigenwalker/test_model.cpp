// METHOD §4: the eigenwalker model (PCA of Fourier vectors) and leave-one-subject-out.
#include <gtest/gtest.h>

#include "core/common/errors.h"
#include "core/eigenwalker/model.h"
#include "core/eigenwalker/synthetic_walkers.h"

namespace ew {
namespace {

struct Set {
  Eigen::MatrixXd w;
  std::vector<std::string> ids, subjects;
  Eigen::VectorXd omegas;
};

// R walkers; walkers 0 and 1 belong to the same subject "S0" (two conditions).
Set makeSet(int r) {
  Set s;
  s.w = syntheticWalkerSet(r, 5);
  s.omegas = Eigen::VectorXd::LinSpaced(r, 5.5, 7.5);
  for (int i = 0; i < r; ++i) {
    const std::string subject = "S" + std::to_string(i == 1 ? 0 : i);
    s.subjects.push_back(subject);
    s.ids.push_back(subject + "/c" + std::to_string(i));
  }
  return s;
}

EigenwalkerModel build(const Set& s, const ModelOptions& options = {}) {
  return buildModel(s.w, s.ids, s.subjects, s.omegas, options);
}

TEST(Model, MeanEigenwalkersEigenvaluesAndCoefficients) {
  const Set s = makeSet(24);
  const auto m = build(s, {.varianceThreshold = 0.95, .components = std::nullopt});
  const int n = m.componentCount();
  EXPECT_LT((m.mean - s.w.rowwise().mean()).norm(), 1e-9);
  EXPECT_LT((m.eigenwalkers.transpose() * m.eigenwalkers - Eigen::MatrixXd::Identity(n, n))
                .cwiseAbs().maxCoeff(), 1e-12);
  ASSERT_EQ(m.spectrum.size(), 23);
  for (int i = 1; i < m.spectrum.size(); ++i) EXPECT_LE(m.spectrum(i), m.spectrum(i - 1));
  // λ_n is the variance of the walkers' coefficients on e_n (METHOD §4: S_n² / (R − 1)).
  for (int i = 0; i < n; ++i) {
    EXPECT_NEAR(m.coefficients.row(i).squaredNorm() / 23.0, m.eigenvalues(i),
                1e-9 * m.eigenvalues(0));
  }
  // Smallest N reaching 95 %.
  EXPECT_GE(m.explainedVariance(), 0.95);
  EXPECT_LT(m.spectrum.head(n - 1).sum() / m.spectrum.sum(), 0.95);
  EXPECT_EQ(m.walkerIds, s.ids);
  EXPECT_EQ(m.subjects, s.subjects);
}

TEST(Model, AllComponentsReproduceEveryWalker) {
  const Set s = makeSet(24);
  ModelOptions options;
  options.components = 500;  // clamped to R − 1
  const auto m = build(s, options);
  EXPECT_EQ(m.componentCount(), 23);
  EXPECT_NEAR(m.explainedVariance(), 1.0, 1e-12);
  for (int r = 0; r < 24; ++r) {
    EXPECT_LT((synthesizeWalker(m, m.coefficients.col(r)) - s.w.col(r)).cwiseAbs().maxCoeff(), 1e-8);
    EXPECT_LT((projectOntoModel(m, s.w.col(r)) - m.coefficients.col(r)).norm(), 1e-8);
  }
}

TEST(Model, EigenvectorSignsAreDeterministic) {
  const Set s = makeSet(12);
  const auto m = build(s);
  for (int n = 0; n < m.componentCount(); ++n) {
    Eigen::Index i = 0;
    m.eigenwalkers.col(n).cwiseAbs().maxCoeff(&i);
    EXPECT_GT(m.eigenwalkers(i, n), 0.0);
  }
  // Column order of W does not change the model.
  Set shuffled = s;
  shuffled.w.col(0).swap(shuffled.w.col(5));
  const auto m2 = build(shuffled);
  EXPECT_LT((m2.eigenwalkers - m.eigenwalkers).cwiseAbs().maxCoeff(), 1e-9);
}

TEST(Model, LeaveOneSubjectOutDropsEveryWalkerOfTheSubject) {
  const Set s = makeSet(24);
  ModelOptions options;
  options.components = 22;
  const auto m = buildModelWithoutSubject(s.w, s.ids, s.subjects, s.omegas, "S0", options);
  EXPECT_EQ(m.walkerCount(), 22);
  EXPECT_EQ(m.componentCount(), 21);  // at most R' − 1
  for (const auto& subject : m.subjects) EXPECT_NE(subject, "S0");
  // Same as building from the remaining columns directly.
  const auto direct = buildModel(s.w.rightCols(22), {s.ids.begin() + 2, s.ids.end()},
                                 {s.subjects.begin() + 2, s.subjects.end()},
                                 s.omegas.tail(22), options);
  EXPECT_LT((m.eigenwalkers - direct.eigenwalkers).cwiseAbs().maxCoeff(), 1e-10);
  EXPECT_EQ(m.omegasRadS, direct.omegasRadS);
  ASSERT_FALSE(m.provenance.empty());
  EXPECT_NE(m.provenance.back().find("S0"), std::string::npos);
}

TEST(Model, BadInputsAreErrors) {
  const Set s = makeSet(4);
  EXPECT_THROW(buildModelWithoutSubject(s.w, s.ids, s.subjects, s.omegas, "nobody"), Error);
  EXPECT_THROW(buildModel(s.w.leftCols(1), {"a"}, {"a"}, s.omegas.head(1)), Error);
  EXPECT_THROW(buildModel(s.w, s.ids, s.subjects, s.omegas.head(3)), Error);
  Eigen::MatrixXd bad = s.w;
  bad(3, 2) = std::nan("");
  EXPECT_THROW(buildModel(bad, s.ids, s.subjects, s.omegas), Error);
  const auto m = build(s);
  EXPECT_THROW(synthesizeWalker(m, Eigen::VectorXd::Zero(m.componentCount() + 1)), Error);
}

TEST(Model, SynthesizedFramesFollowTheCoefficients) {
  const Set s = makeSet(10);
  const auto m = build(s);
  const Eigen::VectorXd t = Eigen::VectorXd::LinSpaced(7, 0.0, 1.0);
  const Eigen::MatrixXd meanFrames = synthesizeWalkerFrames(m, Eigen::VectorXd::Zero(m.componentCount()), 6.0, 0.2, t);
  EXPECT_NEAR(meanFrames(0, 2), m.mean(2) + m.mean(45 + 2) * std::sin(0.2) +
                                    m.mean(90 + 2) * std::cos(0.2) + m.mean(135 + 2) * std::sin(0.4) +
                                    m.mean(180 + 2) * std::cos(0.4), 1e-9);
}

}  // namespace
}  // namespace ew

// The project's one symmetric eigensolver (core/common/symmetric_eigen.h): A v = λ v with the
// values ascending and the vectors orthonormal, from the lower triangle alone; a matrix with a
// NaN says it did not converge.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "core/common/symmetric_eigen.h"

namespace ew {
namespace {

TEST(SymmetricEigen, ItsVectorsAndValuesDecomposeTheMatrix) {
  const Eigen::MatrixXd b = Eigen::MatrixXd::Random(6, 4);
  const Eigen::MatrixXd a = b * b.transpose() + Eigen::MatrixXd::Identity(6, 6);
  Eigen::MatrixXd lower = a.triangularView<Eigen::Lower>();
  lower.triangularView<Eigen::StrictlyUpper>().setConstant(1e9);  // not read
  const SymmetricEigen e = symmetricEigen(lower);
  ASSERT_TRUE(e.converged);
  ASSERT_EQ(e.values.size(), 6);
  for (Eigen::Index i = 0; i + 1 < e.values.size(); ++i) EXPECT_LE(e.values[i], e.values[i + 1]);
  EXPECT_NEAR(e.values[0], 1.0, 1e-9) << "b b' has rank 4: two eigenvalues of 1";
  EXPECT_LT((a * e.vectors - e.vectors * e.values.asDiagonal()).cwiseAbs().maxCoeff(), 1e-9);
  EXPECT_LT((e.vectors.transpose() * e.vectors - Eigen::MatrixXd::Identity(6, 6)).cwiseAbs().maxCoeff(), 1e-12);
}

TEST(SymmetricEigen, ANonFiniteMatrixDoesNotConverge) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Identity(3, 3);
  a(2, 1) = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(symmetricEigen(a).converged);
}

}  // namespace
}  // namespace ew

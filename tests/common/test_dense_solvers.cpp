// The project's one symmetric eigensolver (core/common/symmetric_eigen.h): A v = λ v with the
// values ascending and the vectors orthonormal, from the lower triangle alone; a matrix with a
// NaN says it did not converge. Its one thin SVD (core/common/thin_svd.h): A = U S Vᵀ, and the
// solve through it the least-squares one, or the minimum-norm one when a direction is dropped.

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include <Eigen/Cholesky>

#include "core/common/symmetric_eigen.h"
#include "core/common/thin_svd.h"

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

TEST(ThinSvd, ItsFactorsRebuildTheMatrixAndItsSolveDropsTheFreeDirection) {
  Eigen::MatrixXd a = Eigen::MatrixXd::Random(9, 4);
  const Eigen::VectorXd rhs = Eigen::VectorXd::Random(9);
  // Well conditioned: the least-squares solution (the normal equations agree).
  const ThinSvd full = thinSvd(a);
  ASSERT_EQ(full.u.cols(), 4);
  EXPECT_LT((full.u * full.singularValues.asDiagonal() * full.v.transpose() - a).cwiseAbs().maxCoeff(), 1e-12);
  const Eigen::VectorXd normal = (a.transpose() * a).ldlt().solve(a.transpose() * rhs);
  EXPECT_LT((solveThroughSvd(full, rhs, 1e-12) - normal).cwiseAbs().maxCoeff(), 1e-9);
  // A direction nearly free (a hinge's axis): dropped at 5 %, the solution has nothing along it
  // and leaves a residual with nothing along the kept directions.
  a.col(3) = a.col(0) + 1e-4 * a.col(3);
  const ThinSvd hinge = thinSvd(a);
  ASSERT_LT(hinge.singularValues[3], 0.05 * hinge.singularValues[0]);
  const Eigen::VectorXd x = solveThroughSvd(hinge, rhs, 0.05);
  EXPECT_LT(std::abs(hinge.v.col(3).dot(x)), 1e-12);
  EXPECT_LT((hinge.u.leftCols(3).transpose() * (a * x - rhs)).cwiseAbs().maxCoeff(), 1e-12);
}

}  // namespace
}  // namespace ew

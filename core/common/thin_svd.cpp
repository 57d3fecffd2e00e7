#include "core/common/thin_svd.h"

#include <Eigen/SVD>
#include <algorithm>
#include <limits>

namespace ew {

ThinSvd thinSvd(const Eigen::MatrixXd& a) {
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(a, Eigen::ComputeThinU | Eigen::ComputeThinV);
  return {svd.matrixU(), svd.matrixV(), svd.singularValues()};
}

Eigen::VectorXd solveThroughSvd(const ThinSvd& svd, const Eigen::VectorXd& rhs, double threshold) {
  const Eigen::VectorXd& s = svd.singularValues;
  if (s.size() == 0) return Eigen::VectorXd::Zero(svd.v.rows());
  const double kept = std::max(s[0] * threshold, std::numeric_limits<double>::min());
  Eigen::Index rank = s.size();
  while (rank > 0 && !(s[rank - 1] >= kept)) --rank;
  Eigen::VectorXd tmp = svd.u.leftCols(rank).transpose() * rhs;
  tmp = s.head(rank).asDiagonal().inverse() * tmp;
  return svd.v.leftCols(rank) * tmp;
}

}  // namespace ew

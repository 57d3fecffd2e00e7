#include "core/common/symmetric_eigen.h"

#include <Eigen/Eigenvalues>

namespace ew {

SymmetricEigen symmetricEigen(const Eigen::MatrixXd& symmetric) {
  const Eigen::MatrixXd full = symmetric.selfadjointView<Eigen::Lower>();
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> solver(full);
  return {solver.eigenvalues(), solver.eigenvectors(), solver.info() == Eigen::Success};
}

}  // namespace ew

#pragma once
// The eigendecomposition of a dense symmetric matrix (Eigen's SelfAdjointEigenSolver), compiled
// in one place for the project: the solver's templates cost 7 s to compile with GCC at -O3 and
// 15 s with clang and the sanitizers in every unit that instantiates them (docs/DEVELOPING.md, "CI").
#include <Eigen/Core>

namespace ew {

struct SymmetricEigen {
  Eigen::VectorXd values;   // ascending
  Eigen::MatrixXd vectors;  // column i belongs to values[i]
  bool converged = true;    // false for a matrix with non-finite entries: the above mean nothing
};

// Of `symmetric`'s lower triangle (the upper one is not read).
SymmetricEigen symmetricEigen(const Eigen::MatrixXd& symmetric);

}  // namespace ew

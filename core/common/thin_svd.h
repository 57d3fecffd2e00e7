#pragma once
// The thin singular value decomposition of a dense matrix (Eigen's JacobiSVD, QR-preconditioned:
// accurate on the small singular values), compiled in one place for the project: its templates
// cost 6-8 s with GCC at -O3 and about twice that with clang and the sanitizers in every unit that
// instantiates them (docs/DEVELOPING.md, "CI"). The eigenwalker model, the semantic axes' ridge
// regression and the functional joint centres use it.
#include <Eigen/Core>

namespace ew {

struct ThinSvd {
  Eigen::MatrixXd u, v;           // m × k and n × k, k = min(m, n)
  Eigen::VectorXd singularValues; // k, largest first
};

ThinSvd thinSvd(const Eigen::MatrixXd& a);

// The least-squares solution of a x = rhs through `svd`, the singular values below `threshold`
// times the largest dropped: the minimum-norm point where they leave a direction free (Eigen's
// JacobiSVD::solve after setThreshold, computed the same way).
Eigen::VectorXd solveThroughSvd(const ThinSvd& svd, const Eigen::VectorXd& rhs, double threshold);

}  // namespace ew

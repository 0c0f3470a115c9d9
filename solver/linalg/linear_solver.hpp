#pragma once
// What the time stepper needs of a factorized symmetric positive-definite matrix: repeated solves.
// Implementations: SparseCholesky (CHOLMOD, any sparsity; the general path and the oracle) and
// BlockCirculantSolver (FFT in x; the uniform periodic mesh only, ~20x faster per solve).
#include <Eigen/Dense>

namespace slidewave {

class LinearSolver {
 public:
  virtual ~LinearSolver() = default;
  /// x = A^{-1} b; b and x have size() entries.
  virtual void solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const = 0;
  virtual int size() const = 0;

  Eigen::VectorXd solve(const Eigen::VectorXd& b) const {
    Eigen::VectorXd x(size());
    solve_into(b, x);
    return x;
  }
};

}  // namespace slidewave

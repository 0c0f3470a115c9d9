#pragma once
// Sparse Cholesky factorization of a symmetric positive-definite matrix (CHOLMOD, through Eigen).
// Factorize once, solve many times. A failed factorization is an exception (edge of the library):
// the matrices here are SPD by construction, so failure means a modelling error.
#include <Eigen/CholmodSupport>
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <memory>

#include "linalg/linear_solver.hpp"

namespace slidewave {

class SparseCholesky : public LinearSolver {
 public:
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A);
  using LinearSolver::solve;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  void solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const override;
  int size() const override { return n_; }

 private:
  int n_;
  std::unique_ptr<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower>> llt_;
};

}  // namespace slidewave

#pragma once
// Sparse Cholesky factorization of a symmetric positive-definite matrix (CHOLMOD's supernodal L L^T).
// Factorize once, solve many times. A failed factorization is an exception (edge of the library):
// the matrices here are SPD by construction, so failure means a modelling error.
// CHOLMOD is called as Eigen's CholmodDecomposition in CholmodSupernodalLLt mode calls it (the same calls on the
// same arrays, so the same bits), through the table of linalg/cholmod_library.hpp, which loads it on first use.
#include <cholmod.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include "linalg/linear_solver.hpp"

namespace slidewave {

class SparseCholesky : public LinearSolver {
 public:
  /// @param A            the lower triangle is read (column-major, compressed)
  /// @param blas_threads the thread count of CHOLMOD's BLAS (numerics.threads)
  explicit SparseCholesky(const Eigen::SparseMatrix<double>& A, int blas_threads = 1);
  ~SparseCholesky() override;
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  using LinearSolver::solve;
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  void solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const override;
  int size() const override { return n_; }

 private:
  int n_;
  mutable cholmod_common common_;  ///< CHOLMOD's workspace and statistics: its solves write them
  cholmod_factor* factor_ = nullptr;
};

}  // namespace slidewave

#include "linalg/sparse_cholesky.hpp"

#include <stdexcept>

namespace slidewave {

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A)
    : n_(static_cast<int>(A.rows())),
      llt_(std::make_unique<Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower>>()) {
  llt_->setMode(Eigen::CholmodSupernodalLLt);
  llt_->compute(A);
  if (llt_->info() != Eigen::Success)
    throw std::runtime_error("CHOLMOD factorization failed: the matrix is not positive definite");
}

void SparseCholesky::solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const {
  x = llt_->solve(Eigen::VectorXd(b));
  if (llt_->info() != Eigen::Success) throw std::runtime_error("CHOLMOD solve failed");
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& B) const {
  Eigen::MatrixXd X = llt_->solve(B);
  if (llt_->info() != Eigen::Success) throw std::runtime_error("CHOLMOD solve failed");
  return X;
}

}  // namespace slidewave

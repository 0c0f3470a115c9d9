#include "linalg/sparse_cholesky.hpp"

#include <stdexcept>

#include "linalg/cholmod_library.hpp"

namespace slidewave {

namespace {

/// The lower triangle of A as CHOLMOD reads it, sharing A's arrays (Eigen's viewAsCholmod of a
/// selfadjointView<Lower>).
cholmod_sparse lower_view(const Eigen::SparseMatrix<double>& A) {
  if (!A.isCompressed()) throw std::invalid_argument("SparseCholesky: the matrix must be compressed");
  cholmod_sparse v{};
  v.nrow = static_cast<std::size_t>(A.rows());
  v.ncol = static_cast<std::size_t>(A.cols());
  v.nzmax = static_cast<std::size_t>(A.nonZeros());
  v.p = const_cast<int*>(A.outerIndexPtr());
  v.i = const_cast<int*>(A.innerIndexPtr());
  v.x = const_cast<double*>(A.valuePtr());
  v.stype = -1;
  v.itype = CHOLMOD_INT;
  v.xtype = CHOLMOD_REAL;
  v.dtype = CHOLMOD_DOUBLE;
  v.sorted = 1;
  v.packed = 1;
  return v;
}

/// A column-major n x k block of doubles as CHOLMOD reads it (Eigen's viewAsCholmod of a dense matrix).
cholmod_dense dense_view(const double* data, Eigen::Index rows, Eigen::Index cols) {
  cholmod_dense v{};
  v.nrow = static_cast<std::size_t>(rows);
  v.ncol = static_cast<std::size_t>(cols);
  v.nzmax = v.nrow * v.ncol;
  v.d = v.nrow;
  v.x = const_cast<double*>(data);
  v.xtype = CHOLMOD_REAL;
  v.dtype = CHOLMOD_DOUBLE;
  return v;
}

}  // namespace

SparseCholesky::SparseCholesky(const Eigen::SparseMatrix<double>& A, int blas_threads)
    : n_(static_cast<int>(A.rows())) {
  const CholmodLibrary& lib = cholmod_library();
  lib.set_blas_threads(blas_threads);
  lib.start(&common_);
  common_.final_asis = 1;
  common_.supernodal = CHOLMOD_SUPERNODAL;
  cholmod_sparse view = lower_view(A);
  factor_ = lib.analyze(&view, &common_);
  double no_shift[2] = {0.0, 0.0};
  const bool factorized =
      factor_ && lib.factorize_p(&view, no_shift, nullptr, 0, factor_, &common_) && factor_->minor == factor_->n;
  if (!factorized) {  // a constructor that throws runs no destructor: CHOLMOD's memory is freed here
    if (factor_) lib.free_factor(&factor_, &common_);
    lib.finish(&common_);
    throw std::runtime_error("CHOLMOD factorization failed: the matrix is not positive definite");
  }
}

SparseCholesky::~SparseCholesky() {
  const CholmodLibrary& lib = cholmod_library();
  if (factor_) lib.free_factor(&factor_, &common_);
  lib.finish(&common_);
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& B) const {
  const CholmodLibrary& lib = cholmod_library();
  cholmod_dense b = dense_view(B.data(), B.rows(), B.cols());
  cholmod_dense* x = lib.solve(CHOLMOD_A, factor_, &b, &common_);
  if (!x) throw std::runtime_error("CHOLMOD solve failed");
  Eigen::MatrixXd X = Eigen::Map<const Eigen::MatrixXd>(static_cast<const double*>(x->x), B.rows(), B.cols());
  lib.free_dense(&x, &common_);
  return X;
}

void SparseCholesky::solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const {
  const CholmodLibrary& lib = cholmod_library();
  cholmod_dense b_view = dense_view(b.data(), b.size(), 1);  // a Ref<const VectorXd> is contiguous
  cholmod_dense* solution = lib.solve(CHOLMOD_A, factor_, &b_view, &common_);
  if (!solution) throw std::runtime_error("CHOLMOD solve failed");
  x = Eigen::Map<const Eigen::VectorXd>(static_cast<const double*>(solution->x), b.size());
  lib.free_dense(&solution, &common_);
}

}  // namespace slidewave

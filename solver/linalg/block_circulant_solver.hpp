#pragma once
// Direct solver for a symmetric positive-definite matrix that is block-circulant with nearest-neighbour
// coupling: the effective matrix K_eff = M_ff / (beta dt^2) + (1 - a) K_ff (or K_ff, M_ff alone) of the
// uniform periodic layer (mesh/layer_mesh.hpp).
//
// Slice i (mesh column i, periodic in i in [0, n_x)) holds the s = 2 n_y free DOFs 2 (j n_x + i) + d,
// ordered locally as r = 2 j + d. The matrix acts as
//     (A x)_i = B_{-1} x_{i-1} + B_0 x_i + B_{+1} x_{i+1},   indices mod n_x,   B_{-1} = B_{+1}^T.
// The DFT in i, X_m = sum_i x_i e^{-i theta_m i}, theta_m = 2 pi m / n_x, block-diagonalizes it
// (Golub & Van Loan, Matrix Computations, 4th ed., sec. 4.8):
//     A(theta_m) X_m = F_m,   A(theta) = B_0 + B_{+1} e^{i theta} + B_{-1} e^{-i theta},
// n_x independent Hermitian positive-definite systems with the half-bandwidth p of the blocks (p = 3 for
// Q4). Real data need m = 0..n_x/2 only (X_{n_x-m} = conj X_m). Each A(theta_m) is factorized once as
// L D L^H (L unit lower banded, D real positive; no pivoting is needed for HPD matrices, ibid. sec. 4.3).
// A solve is: real-to-complex FFT along i of all s rows (FFTW), forward and backward banded substitution
// for every m (vectorized across m), complex-to-real FFT. Cost O(n log n_x + n p), memory O(n p).
//
// When not to use: a mesh that is not uniform in x, a matrix with couplings beyond the neighbouring
// column, non-periodic sides, or a matrix that is not SPD. Then use SparseCholesky (the general path and
// the oracle in the tests). Slices must agree to 1e-12 relative (the check in the constructor); the
// blocks of slice 0 are the ones factorized. The layer's own matrices are block-circulant by construction
// (fem/assembly.hpp): their blocks are read off the rows of slice 0's neighbourhood of the assembled matrix
// on all DOFs (circulant_blocks_of_rows), with neither the free-free matrix nor the check.
//
// Split solve (linalg/split_solver.hpp), for a step with contact forces on the bottom row (slice rows r = 0,
// 1, the first 2 n_x DOFs): the response to them is, per wavenumber, G_m = A(theta_m)^{-1} E (E the unit
// columns at local rows 0 and 1, precomputed; the 1/n_x is folded in as in inv_D), times the DFT R_m of
// the 2 x n_x loads. solve_free() keeps the spectrum X_m of the free solve and inverse-transforms only rows
// 0 and 1; solve_loaded() adds G_m R_m and inverse-transforms all rows once: about one solve for both.
//
// Threads: a solve runs on a team of `threads` OpenMP threads (numerics.threads; linalg/thread_team.hpp).
// The FFTs go one mesh row j at a time (the rows 2 j, 2 j + 1) through one plan executed on each row's
// own arrays (FFTW's new-array execute functions are thread-safe), rows shared out to the threads; the
// sweeps share out the wavenumbers m (each m is its own system). Which thread does a row or an m never
// changes how it is computed, so x is the same to the bit for any thread count. A solve has three
// synchronization points (start, two barriers), so the team needs a free core per thread: on a busy
// machine a barrier waits for a descheduled thread (libgomp spin-waits by default, 5-7x slower per step
// on the shared 2-core machine of README "Threads for one run"; OMP_WAIT_POLICY=PASSIVE limits the loss).
// Thread safety: solve() writes a mutable workspace, so one object must not be used by two callers at
// once; build one solver per caller. Construction (FFTW planning) is serialized internally.
//
// Reproducibility: the FFT plans are made with FFTW_ESTIMATE | FFTW_NO_SIMD, so they depend on the sizes
// alone (not on timing or on the CPU's vector extensions), and a solve is bitwise repeatable.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "linalg/split_solver.hpp"

namespace slidewave {

/// The blocks of slice 0, dense s x s: B[0] = B_{-1}, B[1] = B_0, B[2] = B_{+1}; and the half-bandwidth of
/// their entries above 1e-12 times the matrix's largest (what the factors store).
struct CirculantBlocks {
  Eigen::MatrixXd B[3];
  int bandwidth = 0;
};

/// The blocks of the leading 2 n_x n_y rows and columns (the free DOFs) of a matrix assembled on all DOFs of the
/// uniform periodic layer (fem/assembly.hpp: row-major, DOF 2 (j n_x + i) + d, the top's DOFs after the free
/// ones), read off the rows of slices n_x - 1, 0, 1: the entries that the checking constructor reads off the
/// columns of slice 0 of the free-free block, the same numbers (an entry sums the same one or two element
/// contributions whichever way it is assembled), and the bandwidth by the same rule. Trusts the structure.
CirculantBlocks circulant_blocks_of_rows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& A, int n_x, int n_y);

class BlockCirculantSolver : public SplitSolver {
 public:
  /// Checks the structure (std::invalid_argument with the first mismatch if A is not square of size
  /// 2 n_x n_y, symmetric and block-circulant with nearest-neighbour coupling; n_x >= 3, n_y >= 1) and
  /// factorizes A(theta_m), m = 0..n_x/2 (std::runtime_error if one is not positive definite).
  /// @param A full symmetric storage (both triangles), DOF 2 (j n_x + i) + d
  /// @param threads size of the OpenMP team of each solve (>= 1, else std::invalid_argument)
  BlockCirculantSolver(const Eigen::SparseMatrix<double>& A, int n_x, int n_y, int threads = 1);
  /// Factorizes the matrix of these blocks, whose structure the caller vouches for (circulant_blocks_of_rows).
  BlockCirculantSolver(const CirculantBlocks& blocks, int n_x, int n_y, int threads = 1);
  ~BlockCirculantSolver();
  BlockCirculantSolver(BlockCirculantSolver&&) noexcept;
  BlockCirculantSolver& operator=(BlockCirculantSolver&&) noexcept;
  BlockCirculantSolver(const BlockCirculantSolver&) = delete;
  BlockCirculantSolver& operator=(const BlockCirculantSolver&) = delete;

  /// x = A^{-1} b.
  Eigen::VectorXd solve(const Eigen::VectorXd& b) const;
  /// X = A^{-1} B, column by column through the same workspace (no allocation per column).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;
  /// x = A^{-1} b without allocating; b and x may be the same vector. Both have size() entries.
  void solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const override;

  int size() const override { return 2 * n_x_ * n_y_; }
  /// The bottom row of the mesh (j = 0): 2 n_x DOFs.
  int n_contact() const override { return 2 * n_x_; }
  void solve_free(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> u_contact) override;
  void solve_loaded(const Eigen::Ref<const Eigen::VectorXd>& g, Eigen::Ref<Eigen::VectorXd> u) override;
  int n_x() const { return n_x_; }
  int n_y() const { return n_y_; }
  /// Half-bandwidth p of the blocks in the slice ordering r = 2 j + d.
  int bandwidth() const { return p_; }
  int threads() const { return threads_; }
  /// Bytes held by the factors, the workspace and the FFT plans' arrays (not the plans themselves).
  std::size_t memory_bytes() const;

  /// True if A has the structure the constructor requires (see there); otherwise false, and the first
  /// mismatch found is written to *reason when reason is not null.
  static bool is_block_circulant(const Eigen::SparseMatrix<double>& A, int n_x, int n_y, std::string* reason = nullptr);

 private:
  struct FftPlans;  // FFTW plans, kept out of this header

  // The spectrum buffers, each with FFT plans of its own: work_ (solves), kept_ (the free solve's spectrum,
  // split solve), contact_ (rows 0 and 1 only: the bottom row's 2 n_x values).
  enum class Spectrum { work = 0, kept = 1, contact = 2 };
  /// Mesh rows j0 <= j < j1 of b (real) -> the buffer's data rows 2 j, 2 j + 1.
  void transform(Spectrum spectrum, const double* b, int j0, int j1) const;
  /// The buffer's data rows 2 j, 2 j + 1 -> mesh rows j0 <= j < j1 of x; destroys them.
  void inverse_transform(Spectrum spectrum, double* x, int j0, int j1) const;
  /// y <- A^{-1} y / n_x on a padded (s + 2p)-row spectrum, lanes m0 <= m < m1.
  void sweep(double* y_re, double* y_im, int m0, int m1) const;
  void prepare_split();  ///< G and the split workspace (block_circulant_split.cpp)

  int n_x_, n_y_;
  int s_;        ///< slice size 2 n_y
  int p_;        ///< half-bandwidth of the blocks
  int n_modes_;  ///< n_x / 2 + 1 wavenumbers
  int lanes_;    ///< n_modes_ padded to an even count (vector lanes across m)
  int threads_;  ///< OpenMP team size of a solve
  /// Lanes are shared out to threads in multiples of a 64-byte cache line of doubles.
  static constexpr int kLaneGranule = 8;

  // Factors, structure of arrays with m fastest: L(r, r-k) at ((r p + k - 1) lanes + m), real and
  // imaginary parts apart; rows s..s+p-1 are zero so that the backward sweep needs no bounds test.
  // inv_D(r) at (r lanes + m) holds 1 / (n_x D_r): the 1/n_x of the inverse DFT is folded in.
  std::vector<double> L_re_, L_im_, inv_D_;
  // Spectrum of the right-hand side, (s + 2p) rows of lanes_ entries; the data occupy rows p..p+s-1
  // and the p zero rows on either side stand in for the missing band entries at the ends.
  mutable std::vector<double> work_re_, work_im_;
  std::unique_ptr<FftPlans> plans_;
  // Split solve: G_m, column b (0, 1) at ((b s + r) lanes + m); the kept spectrum of the free solve
  // (padded like work_); rows 0, 1 of a spectrum (scratch for the contact transforms).
  std::vector<double> G_re_, G_im_, kept_re_, kept_im_, contact_re_, contact_im_;
  bool kept_valid_ = false;
};

}  // namespace slidewave

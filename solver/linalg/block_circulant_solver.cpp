#include "linalg/block_circulant_solver.hpp"

#include <fftw3.h>

#include <algorithm>
#include <cassert>
#include <cmath>
#include <complex>
#include <mutex>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "linalg/fftw_planner.hpp"
#include "linalg/thread_team.hpp"
#include "linalg/vector_clones.hpp"

namespace slidewave {

namespace {

constexpr double kRelativeTolerance = 1e-12;
constexpr double kPi = 3.14159265358979323846;

/// max |A_ij| over the stored entries (NaN entries ignored, as std::max ignores them). Four running maxima
/// over a compressed matrix's values (max is exact in any order), so that the loop is not one chain of
/// dependent maxsd: the matrices have millions of entries.
__attribute__((noinline)) double largest_magnitude(const Eigen::SparseMatrix<double>& A) {
  const double* values = A.valuePtr();
  double largest[4] = {0, 0, 0, 0};
  const auto take = [&largest, values](int lane, long e) {
    const double magnitude = std::fabs(values[e]);
    if (magnitude > largest[lane]) largest[lane] = magnitude;
  };
  if (A.isCompressed()) {
    const long n = A.nonZeros();
    long e = 0;
    for (; e + 4 <= n; e += 4)
      for (int lane = 0; lane < 4; ++lane) take(lane, e + lane);
    for (; e < n; ++e) take(0, e);
  } else {
    for (int k = 0; k < A.outerSize(); ++k)
      for (long e = A.outerIndexPtr()[k]; e < A.outerIndexPtr()[k] + A.innerNonZeroPtr()[k]; ++e) take(0, e);
  }
  return std::max({largest[0], largest[1], largest[2], largest[3]});
}

/// An entry (r, c) of block B[b].
struct Position {
  int b, r, c;
};

/// The entries of the blocks above tol in magnitude, block by block, column by column.
std::vector<Position> significant_entries(const CirculantBlocks& blocks, double tol) {
  const int s = static_cast<int>(blocks.B[1].rows());
  std::vector<Position> significant;
  for (int b = 0; b < 3; ++b)
    for (int c = 0; c < s; ++c)
      for (int r = 0; r < s; ++r)
        if (std::fabs(blocks.B[b](r, c)) > tol) significant.push_back({b, r, c});
  return significant;
}

int bandwidth(const std::vector<Position>& significant) {
  int p = 0;
  for (const Position& q : significant) p = std::max(p, std::abs(q.r - q.c));
  return p;
}

/// Empty if A is block-circulant, symmetric and nearest-neighbour (blocks written to *out), else the
/// first mismatch. Entries are compared to kRelativeTolerance * max |A_ij|; a structural zero in one
/// slice counts as 0 against the other slices. A is column-major: the columns of slice i_c are visited
/// slice by slice, so an entry of slice 0 that a later slice lacks is caught by a visit stamp.
std::string find_mismatch(const Eigen::SparseMatrix<double>& A, int n_x, int n_y, CirculantBlocks* out) {
  std::ostringstream why;
  why.precision(17);
  if (n_x < 3 || n_y < 1) {
    why << "need n_x >= 3 and n_y >= 1 (got n_x = " << n_x << ", n_y = " << n_y << ")";
    return why.str();
  }
  const long long n = 2LL * n_x * n_y;
  if (A.rows() != n || A.cols() != n) {
    why << "A is " << A.rows() << " x " << A.cols() << ", expected " << n << " x " << n << " (2 n_x n_y)";
    return why.str();
  }
  const int s = 2 * n_y;
  const double scale = largest_magnitude(A);
  if (!(scale > 0) || !std::isfinite(scale)) return "A is zero or not finite";
  const double tol = kRelativeTolerance * scale;

  // DOF -> (slice i, local r = 2 j + d), tabulated (the entries are millions, the DOFs n), and the column
  // of slice i, local c.
  std::vector<int> slice(static_cast<std::size_t>(n)), local(static_cast<std::size_t>(n));
  for (int dof = 0; dof < n; ++dof) {
    slice[dof] = (dof / 2) % n_x;
    local[dof] = 2 * ((dof / 2) / n_x) + dof % 2;
  }
  const auto slice_of = [&slice](int dof) { return slice[dof]; };
  const auto local_of = [&local](int dof) { return local[dof]; };
  const auto column = [n_x](int i, int c) { return 2 * ((c / 2) * n_x + i) + c % 2; };

  CirculantBlocks blocks;
  for (auto& B : blocks.B) B = Eigen::MatrixXd::Zero(s, s);
  // Row slice i_r of an entry in column slice i_c: offset o = i_c - i_r, modulo n_x, in {-1, 0, +1}
  // selects B_o (n_x >= 3, so the three offsets are distinct).
  const auto block_index = [n_x](int i_r, int i_c) {
    const int o = i_c - i_r;
    return o == 0 ? 1 : (o == 1 || o == 1 - n_x) ? 2 : (o == -1 || o == n_x - 1) ? 0 : -1;
  };
  for (int c = 0; c < s; ++c)
    for (Eigen::SparseMatrix<double>::InnerIterator it(A, column(0, c)); it; ++it) {
      const int b = block_index(slice_of(it.index()), 0);
      if (b < 0) {
        if (std::fabs(it.value()) > tol) {
          why << "A(" << it.index() << ", " << column(0, c) << ") couples slices 0 and " << slice_of(it.index())
              << ", which are not neighbours";
          return why.str();
        }
        continue;
      }
      blocks.B[b](local_of(it.index()), c) += it.value();
    }

  // Significant entries of the reference blocks, to find the ones another slice lacks.
  const std::vector<Position> significant = significant_entries(blocks, tol);
  // A slice has all of them when as many of its entries sit at a significant position (the entries of a
  // column slice have distinct positions (b, r, c)); only a slice that lacks one is searched for which.
  const auto first_lacking = [&](int i) -> const Position* {
    std::vector<char> found(3 * static_cast<std::size_t>(s) * s, 0);
    const auto at = [s](int b, int r, int c) { return (static_cast<std::size_t>(b) * s + c) * s + r; };
    for (int c = 0; c < s; ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, column(i, c)); it; ++it) {
        const int b = block_index(slice_of(it.index()), i);
        if (b >= 0) found[at(b, local_of(it.index()), c)] = 1;
      }
    for (const Position& q : significant)
      if (!found[at(q.b, q.r, q.c)]) return &q;
    return nullptr;
  };
  for (int i = 1; i < n_x; ++i) {
    std::size_t present = 0;
    for (int c = 0; c < s; ++c)
      for (Eigen::SparseMatrix<double>::InnerIterator it(A, column(i, c)); it; ++it) {
        const int i_r = slice_of(it.index()), r = local_of(it.index());
        const int b = block_index(i_r, i);
        const double reference = b < 0 ? 0.0 : blocks.B[b](r, c);
        if (std::fabs(it.value() - reference) > tol) {
          why << "A(" << it.index() << ", " << column(i, c) << ") = " << it.value() << " differs from " << reference
              << ", its counterpart in slice 0 (column slice " << i << ", row slice " << i_r << ")";
          return why.str();
        }
        if (std::fabs(reference) > tol) ++present;
      }
    if (present == significant.size()) continue;
    if (const Position* q = first_lacking(i)) {
      why << "column slice " << i << " lacks the entry (" << q->r << ", " << q->c << ") of block "
          << (q->b == 0   ? "B_{-1}"
              : q->b == 1 ? "B_0"
                          : "B_{+1}")
          << " = " << blocks.B[q->b](q->r, q->c) << " of slice 0";
      return why.str();
    }
  }

  // Symmetry: B_0 = B_0^T and B_{-1} = B_{+1}^T make A(theta) Hermitian.
  for (int c = 0; c < s; ++c)
    for (int r = 0; r < s; ++r) {
      if (std::fabs(blocks.B[1](r, c) - blocks.B[1](c, r)) > tol) {
        why << "A is not symmetric: B_0(" << r << ", " << c << ") != B_0(" << c << ", " << r << ")";
        return why.str();
      }
      if (std::fabs(blocks.B[0](r, c) - blocks.B[2](c, r)) > tol) {
        why << "A is not symmetric: B_{-1}(" << r << ", " << c << ") != B_{+1}(" << c << ", " << r << ")";
        return why.str();
      }
    }

  blocks.bandwidth = bandwidth(significant);
  if (out) *out = std::move(blocks);
  return {};
}

}  // namespace

struct BlockCirculantSolver::FftPlans {
  // Per spectrum buffer (index Spectrum): its r2c and c2r plans of one mesh row j (the two rows r = 2 j + d),
  // made on the buffer's first data row (real, imaginary) and executed row by row at offsets.
  fftw_plan forward[3] = {}, inverse[3] = {};
  double *re[3] = {}, *im[3] = {};
  ~FftPlans() {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    for (int k = 0; k < 3; ++k) {
      if (forward[k]) fftw_destroy_plan(forward[k]);
      if (inverse[k]) fftw_destroy_plan(inverse[k]);
    }
  }
};

bool BlockCirculantSolver::is_block_circulant(const Eigen::SparseMatrix<double>& A, int n_x, int n_y,
                                              std::string* reason) {
  const std::string why = find_mismatch(A, n_x, n_y, nullptr);
  if (reason) *reason = why;
  return why.empty();
}

namespace {

CirculantBlocks checked_blocks(const Eigen::SparseMatrix<double>& A, int n_x, int n_y) {
  CirculantBlocks blocks;
  const std::string why = find_mismatch(A, n_x, n_y, &blocks);
  if (!why.empty()) throw std::invalid_argument("BlockCirculantSolver: " + why);
  return blocks;
}

}  // namespace

CirculantBlocks circulant_blocks_of_rows(const Eigen::SparseMatrix<double, Eigen::RowMajor>& A, int n_x, int n_y) {
  const int s = 2 * n_y, n = 2 * n_x * n_y;
  if (n_x < 3 || n_y < 1 || A.rows() < n || A.cols() < n)
    throw std::invalid_argument("circulant_blocks_of_rows: need n_x >= 3, n_y >= 1 and 2 n_x n_y rows and columns");
  // The largest magnitude of the free-free block: the scale of the significance rule of find_mismatch.
  double scale = 0;
  for (int row = 0; row < n; ++row)
    for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(A, row); it; ++it)
      if (it.index() < n) scale = std::max(scale, std::fabs(it.value()));
  CirculantBlocks blocks;
  for (auto& B : blocks.B) B = Eigen::MatrixXd::Zero(s, s);
  // Row r of slice i_r (offset o = -i_r from slice 0) holds B_o(r, c) in its columns of slice 0, as
  // find_mismatch reads them (+= on zero, as there).
  const std::pair<int, int> row_slices[] = {{n_x - 1, 2}, {0, 1}, {1, 0}};  // (i_r, b)
  for (const auto& [i_r, b] : row_slices)
    for (int r = 0; r < s; ++r)
      for (Eigen::SparseMatrix<double, Eigen::RowMajor>::InnerIterator it(A, 2 * ((r / 2) * n_x + i_r) + r % 2); it;
           ++it) {
        const int col = static_cast<int>(it.index());
        if (col < n && (col / 2) % n_x == 0) blocks.B[b](r, 2 * ((col / 2) / n_x) + col % 2) += it.value();
      }
  blocks.bandwidth = bandwidth(significant_entries(blocks, kRelativeTolerance * scale));
  return blocks;
}

BlockCirculantSolver::BlockCirculantSolver(const Eigen::SparseMatrix<double>& A, int n_x, int n_y, int threads)
    : BlockCirculantSolver(checked_blocks(A, n_x, n_y), n_x, n_y, threads) {}

BlockCirculantSolver::BlockCirculantSolver(const CirculantBlocks& blocks, int n_x, int n_y, int threads)
    : n_x_(n_x),
      n_y_(n_y),
      s_(2 * n_y),
      p_(0),
      n_modes_(n_x / 2 + 1),
      lanes_((n_x / 2 + 2) / 2 * 2),
      threads_(threads) {
  if (threads < 1)
    throw std::invalid_argument("BlockCirculantSolver: threads must be >= 1 (got " + std::to_string(threads) + ")");
  // 1. The blocks of slice 0.
  if (n_x < 3 || n_y < 1 || blocks.B[1].rows() != 2 * n_y)
    throw std::invalid_argument("BlockCirculantSolver: blocks of " + std::to_string(blocks.B[1].rows()) +
                                " rows for n_x = " + std::to_string(n_x) + ", n_y = " + std::to_string(n_y));
  p_ = std::max(blocks.bandwidth, 1);  // p = 0 (diagonal blocks) runs through the same code
  const int s = s_, p = p_, lanes = lanes_;

  // 2. L D L^H of A(theta_m) for every m, band by band (row-oriented band LDL^T of Golub & Van Loan sec. 4.3
  //    transcribed to Hermitian matrices), then stored m-fastest for the vectorized sweeps.
  L_re_.assign(static_cast<std::size_t>(s + p) * p * lanes, 0.0);
  L_im_.assign(L_re_.size(), 0.0);
  inv_D_.assign(static_cast<std::size_t>(s) * lanes, 0.0);
  using Complex = std::complex<double>;
  std::vector<Complex> band(static_cast<std::size_t>(s) * (p + 1));
  const auto entry = [&band, p](int r, int c) -> Complex& { return band[r * (p + 1) + (r - c)]; };  // r-p <= c <= r
  std::vector<double> D(s);
  for (int m = 0; m < n_modes_; ++m) {
    // e^{i theta} exactly real at m = 0 and at the Nyquist mode, so that their imaginary parts vanish.
    const Complex phase = m == 0 ? Complex(1, 0) : 2 * m == n_x ? Complex(-1, 0) : std::polar(1.0, 2 * kPi * m / n_x);
    for (int r = 0; r < s; ++r)
      for (int c = std::max(0, r - p); c <= r; ++c)
        entry(r, c) = blocks.B[1](r, c) + blocks.B[2](r, c) * phase + blocks.B[0](r, c) * std::conj(phase);
    // Overwrite the band with L (strictly lower part) row by row; D apart.
    for (int r = 0; r < s; ++r) {
      const int first = std::max(0, r - p);
      for (int c = first; c < r; ++c) {
        Complex v = entry(r, c);
        for (int q = first; q < c; ++q) v -= entry(r, q) * D[q] * std::conj(entry(c, q));
        entry(r, c) = v / D[c];
      }
      double d = entry(r, r).real();
      for (int q = first; q < r; ++q) d -= std::norm(entry(r, q)) * D[q];
      if (!(d > 0) || !std::isfinite(d)) {
        std::ostringstream msg;
        msg << "BlockCirculantSolver: A(theta) is not positive definite at wavenumber m = " << m << " (pivot " << r
            << " = " << d << "): the matrix is not SPD";
        throw std::runtime_error(msg.str());
      }
      D[r] = d;
      inv_D_[static_cast<std::size_t>(r) * lanes + m] = 1.0 / (n_x * d);
      for (int k = 1; k <= p && k <= r; ++k) {
        const std::size_t at = (static_cast<std::size_t>(r) * p + k - 1) * lanes + m;
        L_re_[at] = entry(r, r - k).real();
        L_im_[at] = entry(r, r - k).imag();
      }
    }
  }

  // 3. Workspace and FFT plans. The transform runs along i (stride 2 in the DOF numbering) for each
  //    (j, d); the spectrum is written split (real, imaginary) with m fastest, row r = 2 j + d. A plan
  //    covers one mesh row j (d = 0, 1) and is executed once per j, so that the rows can be shared out
  //    to threads with the same plan for any thread count (for every n_x from 3 to 1100 this gives the
  //    bits of one plan over all rows, checked when the change was made).
  work_re_.assign(static_cast<std::size_t>(s + 2 * p) * lanes, 0.0);
  work_im_.assign(work_re_.size(), 0.0);
  kept_re_.assign(work_re_.size(), 0.0);
  kept_im_.assign(work_re_.size(), 0.0);
  contact_re_.assign(2 * static_cast<std::size_t>(lanes), 0.0);
  contact_im_.assign(contact_re_.size(), 0.0);
  plans_ = std::make_unique<FftPlans>();
  const int work = static_cast<int>(Spectrum::work), kept = static_cast<int>(Spectrum::kept),
            contact = static_cast<int>(Spectrum::contact);
  plans_->re[work] = work_re_.data() + static_cast<std::size_t>(p) * lanes;
  plans_->im[work] = work_im_.data() + static_cast<std::size_t>(p) * lanes;
  plans_->re[kept] = kept_re_.data() + static_cast<std::size_t>(p) * lanes;
  plans_->im[kept] = kept_im_.data() + static_cast<std::size_t>(p) * lanes;
  plans_->re[contact] = contact_re_.data();
  plans_->im[contact] = contact_im_.data();
  std::vector<double> data(2 * static_cast<std::size_t>(n_x), 0.0);
  // User vectors of any alignment are transformed in place of `data`, hence FFTW_UNALIGNED. The split
  // spectra are always the arrays of the plan: FFTW's new-array execution needs the same offset between
  // the real and imaginary arrays as at planning (FFTW manual, sec. 4.6), so each spectrum buffer has
  // plans of its own. ESTIMATE and NO_SIMD make the plan a function of the sizes alone: no timing, no
  // dependence on the CPU's vector extensions (FFTW's real-data codelets are scalar for the sizes here,
  // so this costs little).
  const unsigned flags = FFTW_ESTIMATE | FFTW_UNALIGNED | FFTW_NO_SIMD;
  {
    std::lock_guard<std::mutex> lock(fftw_planner_mutex());
    const fftw_iodim forward_dim{n_x, 2, 1};
    const fftw_iodim forward_loop{2, 1, lanes};  // d = 0, 1
    const fftw_iodim inverse_dim{n_x, 1, 2};
    const fftw_iodim inverse_loop{2, lanes, 1};
    // work: the solves; kept: the split solve; contact: the bottom row only (j = 0: loads and
    // displacements 2 i + d).
    for (int k : {work, kept, contact}) {
      plans_->forward[k] = fftw_plan_guru_split_dft_r2c(1, &forward_dim, 1, &forward_loop, data.data(), plans_->re[k],
                                                        plans_->im[k], flags);
      plans_->inverse[k] = fftw_plan_guru_split_dft_c2r(1, &inverse_dim, 1, &inverse_loop, plans_->re[k], plans_->im[k],
                                                        data.data(), flags);
      if (!plans_->forward[k] || !plans_->inverse[k])
        throw std::runtime_error("BlockCirculantSolver: FFTW planning failed");
    }
  }
  prepare_split();
}

BlockCirculantSolver::~BlockCirculantSolver() = default;
BlockCirculantSolver::BlockCirculantSolver(BlockCirculantSolver&&) noexcept = default;
BlockCirculantSolver& BlockCirculantSolver::operator=(BlockCirculantSolver&&) noexcept = default;

std::size_t BlockCirculantSolver::memory_bytes() const {
  return sizeof(double) *
         (L_re_.size() + L_im_.size() + inv_D_.size() + work_re_.size() + work_im_.size() + G_re_.size() +
          G_im_.size() + kept_re_.size() + kept_im_.size() + contact_re_.size() + contact_im_.size());
}

namespace {

/// Forward sweep L y = f (unit L) for all lanes m, then x = D^{-1} y - L^H x backward, in place on the
/// spectrum. Rows are offset by p in y (zero rows on either side). P is the half-bandwidth when it is a
/// compile-time constant (the loops over k unroll and the loop over m vectorizes), 0 for the general case.
/// Only the lanes m0 <= m < m1 are touched: each m is its own system, computed the same for any range.
template <int P>
__attribute__((always_inline)) inline void banded_sweeps(int s, int p_runtime, int lanes, int m0, int m1,
                                                         const double* __restrict L_re, const double* __restrict L_im,
                                                         const double* __restrict inv_D, double* __restrict y_re,
                                                         double* __restrict y_im) {
  const int p = P > 0 ? P : p_runtime;
  for (int r = 0; r < s; ++r) {
    double* __restrict out_re = y_re + static_cast<std::size_t>(r + p) * lanes;
    double* __restrict out_im = y_im + static_cast<std::size_t>(r + p) * lanes;
    const double* l_re = L_re + static_cast<std::size_t>(r) * p * lanes;
    const double* l_im = L_im + static_cast<std::size_t>(r) * p * lanes;
    for (int m = m0; m < m1; ++m) {
      double a_re = out_re[m], a_im = out_im[m];
      for (int k = 1; k <= p; ++k) {
        const double lr = l_re[(k - 1) * lanes + m], li = l_im[(k - 1) * lanes + m];
        const double br = out_re[m - k * lanes], bi = out_im[m - k * lanes];
        a_re -= lr * br - li * bi;
        a_im -= lr * bi + li * br;
      }
      out_re[m] = a_re;
      out_im[m] = a_im;
    }
  }
  for (int r = s - 1; r >= 0; --r) {
    double* __restrict out_re = y_re + static_cast<std::size_t>(r + p) * lanes;
    double* __restrict out_im = y_im + static_cast<std::size_t>(r + p) * lanes;
    const double* d = inv_D + static_cast<std::size_t>(r) * lanes;
    for (int m = m0; m < m1; ++m) {
      double a_re = out_re[m] * d[m], a_im = out_im[m] * d[m];
      for (int k = 1; k <= p; ++k) {  // x_r -= conj(L(r+k, r)) x_{r+k}
        const std::size_t at = (static_cast<std::size_t>(r + k) * p + k - 1) * lanes + m;
        const double lr = L_re[at], li = L_im[at];
        const double xr = out_re[m + k * lanes], xi = out_im[m + k * lanes];
        a_re -= lr * xr + li * xi;
        a_im -= lr * xi - li * xr;
      }
      out_re[m] = a_re;
      out_im[m] = a_im;
    }
  }
}

}  // namespace

// FFTW's new-array execute functions are thread-safe; each j writes its own rows of the spectrum and of x.
void BlockCirculantSolver::transform(Spectrum spectrum, const double* b, int j0, int j1) const {
  const int k = static_cast<int>(spectrum);
  for (int j = j0; j < j1; ++j) {
    const std::size_t row = 2 * static_cast<std::size_t>(j) * lanes_;
    // r2c does not write its input (FFTW's default for out-of-place real-to-complex transforms).
    fftw_execute_split_dft_r2c(plans_->forward[k], const_cast<double*>(b) + 2 * static_cast<std::size_t>(j) * n_x_,
                               plans_->re[k] + row, plans_->im[k] + row);
  }
}

void BlockCirculantSolver::inverse_transform(Spectrum spectrum, double* x, int j0, int j1) const {
  const int k = static_cast<int>(spectrum);
  for (int j = j0; j < j1; ++j) {
    const std::size_t row = 2 * static_cast<std::size_t>(j) * lanes_;
    fftw_execute_split_dft_c2r(plans_->inverse[k], plans_->re[k] + row, plans_->im[k] + row,
                               x + 2 * static_cast<std::size_t>(j) * n_x_);
  }
}

SLIDEWAVE_VECTOR_CLONES
void BlockCirculantSolver::sweep(double* y_re, double* y_im, int m0, int m1) const {
  if (p_ == 3)
    banded_sweeps<3>(s_, p_, lanes_, m0, m1, L_re_.data(), L_im_.data(), inv_D_.data(), y_re, y_im);
  else
    banded_sweeps<0>(s_, p_, lanes_, m0, m1, L_re_.data(), L_im_.data(), inv_D_.data(), y_re, y_im);
}

void BlockCirculantSolver::solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const {
  assert(b.size() == size() && x.size() == size());
  // Rows j to threads for the FFTs, wavenumbers m for the sweeps (which couple all rows of one m).
  run_team(threads_, [&](int t, int T) {
    const Share rows = share(n_y_, t, T), modes = share(lanes_, t, T, kLaneGranule);
    transform(Spectrum::work, b.data(), rows.begin, rows.end);
    team_barrier();
    sweep(work_re_.data(), work_im_.data(), modes.begin, modes.end);
    team_barrier();
    inverse_transform(Spectrum::work, x.data(), rows.begin, rows.end);
  });
}

Eigen::VectorXd BlockCirculantSolver::solve(const Eigen::VectorXd& b) const {
  if (b.size() != size()) throw std::invalid_argument("BlockCirculantSolver::solve: wrong right-hand side size");
  Eigen::VectorXd x(size());
  solve_into(b, x);
  return x;
}

Eigen::MatrixXd BlockCirculantSolver::solve(const Eigen::MatrixXd& B) const {
  if (B.rows() != size()) throw std::invalid_argument("BlockCirculantSolver::solve: wrong right-hand side size");
  Eigen::MatrixXd X(B.rows(), B.cols());
  for (Eigen::Index k = 0; k < B.cols(); ++k) solve_into(B.col(k), X.col(k));
  return X;
}

}  // namespace slidewave

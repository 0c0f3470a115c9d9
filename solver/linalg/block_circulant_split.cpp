// The split solve of BlockCirculantSolver (linalg/block_circulant_solver.hpp, linalg/split_solver.hpp):
// the free solve keeps its spectrum, the load on the bottom row is added per wavenumber through the
// precomputed G_m = A(theta_m)^{-1} E / n_x, and one inverse transform of all rows gives u.
#include <algorithm>
#include <cassert>
#include <stdexcept>

#include "linalg/block_circulant_solver.hpp"
#include "linalg/thread_team.hpp"
#include "linalg/vector_clones.hpp"

namespace slidewave {
namespace {

/// One spectrum row X += G_0 R_0 + G_1 R_1 (complex, lanes m < n): the response to the bottom row's loads.
SLIDEWAVE_VECTOR_CLONES
void add_loads(const double* __restrict G0_re, const double* __restrict G0_im, const double* __restrict G1_re,
               const double* __restrict G1_im, const double* __restrict R0_re, const double* __restrict R0_im,
               const double* __restrict R1_re, const double* __restrict R1_im, double* __restrict X_re,
               double* __restrict X_im, int n) {
  for (int m = 0; m < n; ++m) {
    X_re[m] += G0_re[m] * R0_re[m] - G0_im[m] * R0_im[m] + G1_re[m] * R1_re[m] - G1_im[m] * R1_im[m];
    X_im[m] += G0_re[m] * R0_im[m] + G0_im[m] * R0_re[m] + G1_re[m] * R1_im[m] + G1_im[m] * R1_re[m];
  }
}

}  // namespace

void BlockCirculantSolver::prepare_split() {
  // kept_ and contact_ are allocated (and their FFT plans made) by the constructor.
  const std::size_t rows = static_cast<std::size_t>(s_) * lanes_;
  // The DFT of a unit load at DOF b of slice 0 is e_b at every wavenumber; the sweeps turn it into
  // A(theta_m)^{-1} e_b / n_x, the same scaling as the spectrum of a solve.
  G_re_.assign(2 * rows, 0.0);
  G_im_.assign(2 * rows, 0.0);
  for (int b = 0; b < 2; ++b) {
    std::fill(kept_re_.begin(), kept_re_.end(), 0.0);
    std::fill(kept_im_.begin(), kept_im_.end(), 0.0);
    std::fill_n(kept_re_.begin() + static_cast<std::size_t>(p_ + b) * lanes_, lanes_, 1.0);
    sweep(kept_re_.data(), kept_im_.data(), 0, lanes_);
    std::copy_n(kept_re_.begin() + static_cast<std::size_t>(p_) * lanes_, rows, G_re_.begin() + b * rows);
    std::copy_n(kept_im_.begin() + static_cast<std::size_t>(p_) * lanes_, rows, G_im_.begin() + b * rows);
  }
  std::fill(kept_re_.begin(), kept_re_.end(), 0.0);  // the padding rows must stay zero for the sweeps
  std::fill(kept_im_.begin(), kept_im_.end(), 0.0);
  kept_valid_ = false;
}

void BlockCirculantSolver::solve_free(const Eigen::Ref<const Eigen::VectorXd>& b,
                                      Eigen::Ref<Eigen::VectorXd> u_contact) {
  assert(b.size() == size() && u_contact.size() == n_contact());
  double* X_re = kept_re_.data() + static_cast<std::size_t>(p_) * lanes_;
  double* X_im = kept_im_.data() + static_cast<std::size_t>(p_) * lanes_;
  // Rows j to threads for the FFTs, wavenumbers m for the sweeps (as in solve_into).
  run_team(threads_, [&](int t, int T) {
    const Share rows = share(n_y_, t, T), modes = share(lanes_, t, T, kLaneGranule);
    transform(Spectrum::kept, b.data(), rows.begin, rows.end);
    team_barrier();
    sweep(kept_re_.data(), kept_im_.data(), modes.begin, modes.end);
  });
  // Rows 0 and 1 only, through a copy: the inverse transform destroys its input and X is kept.
  std::copy_n(X_re, contact_re_.size(), contact_re_.begin());
  std::copy_n(X_im, contact_im_.size(), contact_im_.begin());
  inverse_transform(Spectrum::contact, u_contact.data(), 0, 1);
  kept_valid_ = true;
}

void BlockCirculantSolver::solve_loaded(const Eigen::Ref<const Eigen::VectorXd>& g, Eigen::Ref<Eigen::VectorXd> u) {
  assert(g.size() == n_contact() && u.size() == size());
  if (!kept_valid_) throw std::logic_error("BlockCirculantSolver::solve_loaded: no solve_free() before it");
  double* X_re = kept_re_.data() + static_cast<std::size_t>(p_) * lanes_;
  double* X_im = kept_im_.data() + static_cast<std::size_t>(p_) * lanes_;
  transform(Spectrum::contact, g.data(), 0, 1);
  const double* R0_re = contact_re_.data();
  const double* R0_im = contact_im_.data();
  const double* R1_re = R0_re + lanes_;
  const double* R1_im = R0_im + lanes_;
  const std::size_t rows = static_cast<std::size_t>(s_) * lanes_;
  const double* G0_re = G_re_.data();
  const double* G0_im = G_im_.data();
  const double* G1_re = G0_re + rows;
  const double* G1_im = G0_im + rows;
  const int n_modes = n_modes_;  // the padding lane is never read by the inverse transform
  // Each mesh row j (spectrum rows 2 j, 2 j + 1) needs only its own rows: rows to threads, no barrier.
  run_team(threads_, [&](int t, int T) {
    const Share mesh_rows = share(n_y_, t, T);
    for (int r = 2 * mesh_rows.begin; r < 2 * mesh_rows.end; ++r) {
      const std::size_t row = static_cast<std::size_t>(r) * lanes_;
      add_loads(G0_re + row, G0_im + row, G1_re + row, G1_im + row, R0_re, R0_im, R1_re, R1_im, X_re + row, X_im + row,
                n_modes);
    }
    inverse_transform(Spectrum::kept, u.data(), mesh_rows.begin,
                      mesh_rows.end);  // destroys X: one solve_loaded per solve_free
  });
  kept_valid_ = false;
}

}  // namespace slidewave

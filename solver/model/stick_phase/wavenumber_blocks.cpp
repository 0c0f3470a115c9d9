#include "model/stick_phase/wavenumber_blocks.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <string>
#include <vector>

namespace slidewave {
namespace {

constexpr int kHalfBandwidth = 3;  // Q4: a node couples to the rows j - 1, j, j + 1 (|r - c| <= 3)

/// e^{i theta_m b}, exactly real at m = 0 and at the Nyquist wavenumber.
std::complex<double> phase(int m, int b, int n_x) {
  if (m == 0 || b == 0) return {1, 0};
  if (2 * m == n_x) return {b % 2 == 0 ? 1.0 : -1.0, 0};
  return std::polar(1.0, 2 * M_PI * m * b / n_x);
}

/// Adds the free-free rows of mesh column 0 of A into the band of every lane, in the basis where u_y is
/// multiplied by -i (see the header), the couplings with the top into A_fd0 and A_dd0.
void read_blocks(const RowSparseMatrix& A, const LayerModel& model, BandedLanes& band, Eigen::MatrixXd& A_fd0,
                 Eigen::Matrix2d& A_dd0) {
  std::vector<std::complex<double>> entries(band.a.size());
  const int n_x = model.mesh.n_x, n_free = model.n_free, s = 2 * model.mesh.n_y;
  // phase(m, b, n_x) for b = -1, 0, 1 (index b + 1): the same values, made once per lane, not per entry.
  std::vector<std::complex<double>> phases(3 * static_cast<std::size_t>(band.lanes));
  for (int m = 0; m < band.lanes; ++m)
    for (int b = -1; b <= 1; ++b) phases[3 * static_cast<std::size_t>(m) + b + 1] = phase(m, b, n_x);
  A_fd0 = Eigen::MatrixXd::Zero(s, 2);
  A_dd0.setZero();
  for (int r = 0; r < s; ++r) {
    const int row = 2 * (r / 2) * n_x + r % 2;
    for (RowSparseMatrix::InnerIterator it(A, row); it; ++it) {
      const int col = static_cast<int>(it.col());
      if (col >= n_free) {
        A_fd0(r, (col - n_free) % 2) += it.value();
        continue;
      }
      const int node = col / 2, i = node % n_x, c = 2 * (node / n_x) + col % 2, k = c - r;
      const int b = i == 0 ? 0 : i == 1 ? 1 : i == n_x - 1 ? -1 : 2;
      if (b == 2 || std::abs(k) > kHalfBandwidth)
        throw std::invalid_argument("WavenumberBlocks: row " + std::to_string(row) + " couples to DOF " +
                                    std::to_string(col) + ", beyond the neighbouring columns or the band");
      for (int m = 0; m < band.lanes; ++m)
        entries[band.at(r, k, m)] += it.value() * phases[3 * static_cast<std::size_t>(m) + b + 1];
    }
  }
  // conj(d_r) A_m(r, c) d_c with d = 1 (u_x), i (u_y): real, since the square mesh and the isotropic
  // element are symmetric under x -> -x (the u_x-u_y couplings of A_m are odd in theta, so imaginary).
  // The check's scale is the largest squared modulus (a sanity bound: its last bit does not matter).
  double largest_squared = 0, imaginary = 0;
  for (int r = 0; r < s; ++r)
    for (int k = -band.p; k <= band.p; ++k) {
      if (r + k < 0 || r + k >= s) continue;
      const std::complex<double> i(0, 1);
      const std::complex<double> turn = (r % 2 == 0 ? 1.0 : -i) * ((r + k) % 2 == 0 ? 1.0 : i);  // conj(d_r) d_c
      for (int m = 0; m < band.lanes; ++m) {
        const std::complex<double> z = turn * entries[band.at(r, k, m)];
        band.a[band.at(r, k, m)] = z.real();
        largest_squared = std::max(largest_squared, std::norm(z));
        imaginary = std::max(imaginary, std::abs(z.imag()));
      }
    }
  const double largest = std::sqrt(largest_squared);
  if (imaginary > 1e-12 * largest)
    throw std::invalid_argument("WavenumberBlocks: the blocks are not real in the basis i u_y (imaginary part " +
                                std::to_string(imaginary / largest) + " of the largest entry)");
  for (int d = 0; d < 2; ++d)
    for (RowSparseMatrix::InnerIterator it(A, n_free + d); it; ++it)
      if (it.col() >= n_free) A_dd0(d, (it.col() - n_free) % 2) += it.value();
}

}  // namespace

WavenumberBlocks::WavenumberBlocks(const LayerModel& model)
    : n_x(model.mesh.n_x),
      s(2 * model.mesh.n_y),
      lanes(n_x / 2 + 1),
      K(s, kHalfBandwidth, lanes),
      M(s, kHalfBandwidth, lanes) {
  read_blocks(model.spectral_rows(LayerModel::FreeBlock::stiffness), model, K, K_fd0, K_dd0);
  read_blocks(model.spectral_rows(LayerModel::FreeBlock::mass), model, M, M_fd0, M_dd0);
  weight.assign(lanes, 2.0 / n_x);
  weight[0] = 1.0 / n_x;
  if (n_x % 2 == 0) weight[lanes - 1] = 1.0 / n_x;
}

BandedLanes mass_stiffness_band(const WavenumberBlocks& blocks, double mass_factor, double stiffness_factor) {
  BandedLanes A = blocks.K;
  for (std::size_t e = 0; e < A.a.size(); ++e) A.a[e] = mass_factor * blocks.M.a[e] + stiffness_factor * blocks.K.a[e];
  return A;
}

BandedLanes effective_band(const WavenumberBlocks& blocks, const HHTCoefficients& hht) {
  return mass_stiffness_band(blocks, hht.mass_factor(), 1 - hht.alpha);
}

}  // namespace slidewave

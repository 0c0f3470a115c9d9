#pragma once
// The layer's stiffness and mass as banded Hermitian blocks per wavenumber (docs/stick-phase.md):
// K and M of the free DOFs are block-circulant in the mesh column i (linalg/block_circulant_solver.hpp),
//     K_m = B_0 + B_{+1} e^{i theta_m} + B_{-1} e^{-i theta_m},   theta_m = 2 pi m / n_x,
// Hermitian and banded (half-bandwidth 3 in the local order r = 2 j + d of one column's s = 2 n_y free DOFs;
// r = 0, 1 are the contact DOFs). Their u_x-u_x and u_y-u_y entries are real and their u_x-u_y entries
// imaginary (the mesh and the isotropic element are symmetric under x -> -x), so in the basis where u_y is
// multiplied by -i (Y = D^H X, D = diag(1, i) per node) they are real symmetric: each lane's recurrence is
// real, acting on the real and imaginary parts of its state apart (half the work of complex arithmetic).
// The lanes' states are kept in that basis (model/stick_phase/row_transform.hpp turns them). The top row
// (prescribed, x-uniform) couples to the free rows through wavenumber 0 only: its summed couplings are kept
// as real s x 2 and 2 x 2 matrices, in the layer's basis.
#include <Eigen/Dense>

#include "model/layer_model.hpp"
#include "model/stick_phase/banded_lanes.hpp"
#include "time/hht.hpp"

namespace slidewave {

struct WavenumberBlocks {
  /// Reads the blocks from the rows of mesh column 0 of K and M (LayerModel::spectral_rows; std::invalid_argument if a
  /// row couples beyond the neighbouring columns or beyond half-bandwidth 3).
  explicit WavenumberBlocks(const LayerModel& model);

  int n_x, s, lanes;  ///< lanes m = 0..n_x/2
  BandedLanes K, M;   ///< D^H K_m D, D^H M_m D (s x s per lane, real symmetric)
  /// Wavenumber 0 of the couplings with the x-uniform top: (K u)_f gains K_fd0 u_top per column, and
  /// the sum over the top nodes of (K u)_top is K_fd0^T U_0 + n_x K_dd0 u_top (likewise M).
  Eigen::MatrixXd K_fd0, M_fd0;  ///< s x 2
  Eigen::Matrix2d K_dd0, M_dd0;
  /// Parseval weights: x.y = sum_m weight(m) Re(X_m^H Y_m) for real x, y (1/n_x or 2/n_x).
  std::vector<double> weight;
};

/// The lanes' mass_factor M_m + stiffness_factor K_m, entry by entry.
BandedLanes mass_stiffness_band(const WavenumberBlocks& blocks, double mass_factor, double stiffness_factor);
/// The lanes' effective matrices b M_m + (1 - a) K_m of the HHT step (b = 1 / (beta dt^2)).
BandedLanes effective_band(const WavenumberBlocks& blocks, const HHTCoefficients& hht);

/// Row r of lane 0 of the layer's vector (real: its column sum) from a lane-vector in the turned basis.
inline double lane_zero_value(const LaneVectors& X, int r) {
  return r % 2 == 0 ? X.re[X.at(r, 0)] : -X.im[X.at(r, 0)];  // u_y = i Y
}
/// Adds delta to row r of lane 0 of the layer's vector, in the turned basis.
inline void add_to_lane_zero(LaneVectors& X, int r, double delta) {
  if (r % 2 == 0)
    X.re[X.at(r, 0)] += delta;
  else
    X.im[X.at(r, 0)] -= delta;  // Y = -i u_y
}

}  // namespace slidewave

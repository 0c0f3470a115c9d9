#include "contact/gauss_seidel.hpp"

#include <algorithm>
#include <cmath>

namespace slidewave {

GaussSeidelReport solve_contact_gauss_seidel(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                             const std::vector<double>& bounds, const GaussSeidelSettings& settings,
                                             Eigen::VectorXd& r, Eigen::VectorXd& y,
                                             std::vector<ContactState>& state) {
  const int n_nodes = static_cast<int>(q.size() / 2);
  state.assign(n_nodes, ContactState::open);
  y = q + W * r;
  std::vector<Eigen::Matrix2d> diagonal_blocks(n_nodes);
  for (int k = 0; k < n_nodes; ++k) diagonal_blocks[k] = W.block<2, 2>(2 * k, 2 * k);

  GaussSeidelReport report{0, 0.0, false};
  std::vector<int> n_status_changes(bounds.empty() ? 0 : n_nodes, 0);
  while (report.iterations < settings.max_iterations) {
    ++report.iterations;
    double max_change = 0;
    for (int k = 0; k < n_nodes; ++k) {
      const Eigen::Vector2d r_old = r.segment<2>(2 * k);
      const Eigen::Vector2d b = y.segment<2>(2 * k) - diagonal_blocks[k] * r_old;
      const bool given_bound = !bounds.empty() && n_status_changes[k] <= kMaxStatusChanges;
      const auto local = given_bound ? solve_local_coulomb(diagonal_blocks[k], b, f, bounds[k])
                                     : solve_local_coulomb(diagonal_blocks[k], b, f);
      if (!bounds.empty() && report.iterations > 1 &&  // sweep 1 compares with the all-open start
          (local.state == ContactState::open) != (state[k] == ContactState::open) &&
          ++n_status_changes[k] == kMaxStatusChanges + 1)
        ++report.n_bounds_released;
      state[k] = local.state;
      const Eigen::Vector2d delta = local.r - r_old;
      if (delta.x() != 0 || delta.y() != 0) {
        r.segment<2>(2 * k) = local.r;
        y.noalias() += W.middleCols<2>(2 * k) * delta;
        max_change = std::max(max_change, delta.cwiseAbs().maxCoeff());
      }
    }
    report.residual = max_change / settings.force_scale;
    if (report.residual <= settings.tolerance) {
      report.converged = true;
      break;
    }
  }
  // Recompute y from scratch so that rounding drift of the in-place updates never reaches the output.
  y = q + W * r;
  return report;
}

}  // namespace slidewave

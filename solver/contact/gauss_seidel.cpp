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
  while (report.iterations < settings.max_iterations) {
    ++report.iterations;
    double max_change = 0;
    for (int k = 0; k < n_nodes; ++k) {
      const Eigen::Vector2d r_old = r.segment<2>(2 * k);
      const Eigen::Vector2d b = y.segment<2>(2 * k) - diagonal_blocks[k] * r_old;
      const auto local = bounds.empty() ? solve_local_coulomb(diagonal_blocks[k], b, f)
                                        : solve_local_coulomb(diagonal_blocks[k], b, f, bounds[k]);
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

#include "contact/gauss_seidel.hpp"

#include <algorithm>
#include <cmath>

#include "contact/delassus.hpp"

namespace slidewave {

namespace {

/// y = q + W r, from W's generating columns when it is block-circulant (the same numbers bit for bit).
void compute_local_variables(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, const Eigen::VectorXd& r,
                             const Eigen::MatrixXd* periodic_columns, Eigen::VectorXd& y) {
  if (periodic_columns)
    periodic_residual(*periodic_columns, static_cast<int>(q.size() / 2), q, r, y);
  else
    y = q + W * r;
}

/// One pass of at most settings.max_iterations sweeps from the r passed in, each node's reaction moved
/// by `relaxation` times the change of its exact local solve.
GaussSeidelReport sweep_until_converged(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                        const std::vector<double>& bounds, const GaussSeidelSettings& settings,
                                        double relaxation, Eigen::VectorXd& r, Eigen::VectorXd& y,
                                        std::vector<ContactState>& state, const Eigen::MatrixXd* periodic_columns) {
  const int n_nodes = static_cast<int>(q.size() / 2);
  state.assign(n_nodes, ContactState::open);
  compute_local_variables(W, q, r, periodic_columns, y);
  std::vector<Eigen::Matrix2d> diagonal_blocks(n_nodes);
  for (int k = 0; k < n_nodes; ++k) diagonal_blocks[k] = W.block<2, 2>(2 * k, 2 * k);

  GaussSeidelReport report{0, 0.0, false};
  report.relaxation = relaxation;
  std::vector<int> n_status_changes(bounds.empty() ? 0 : n_nodes, 0);
  // Period-2 orbit detection (plain pass only, from sweep kCycleWatchFrom on, so that the usual
  // 10-25-sweep solves pay nothing): r two sweeps back, and how many sweeps in a row came back to it
  // while still changing by more than the tolerance.
  Eigen::VectorXd r_previous, r_two_back;
  int n_cycle_sweeps = 0;
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
      const Eigen::Vector2d change = local.r - r_old;
      if (change.x() != 0 || change.y() != 0) {
        // relaxation 1 assigns local.r itself (r_old + change may differ from it in the last bit)
        const Eigen::Vector2d delta = relaxation == 1 ? change : Eigen::Vector2d(relaxation * change);
        r.segment<2>(2 * k) = relaxation == 1 ? local.r : Eigen::Vector2d(r_old + delta);
        if (periodic_columns)
          add_periodic_node_columns(*periodic_columns, n_nodes, k, delta.x(), delta.y(), y);
        else
          y.noalias() += W.middleCols<2>(2 * k) * delta;
        max_change = std::max(max_change, change.cwiseAbs().maxCoeff());
      }
    }
    report.residual = max_change / settings.force_scale;
    if (report.residual <= settings.tolerance) {
      report.converged = true;
      break;
    }
    if (relaxation == 1 && report.iterations >= kCycleWatchFrom) {
      // Back where it was two sweeps ago (to 1e-3 of this sweep's change) on kCycleSweeps sweeps in a
      // row: a period-2 orbit that will never converge, so stop now instead of at max_iterations.
      // A converging iteration cannot show this (its changes would have to alternate without decaying).
      const bool returned = report.iterations >= kCycleWatchFrom + 2 &&
                            (r - r_two_back).cwiseAbs().maxCoeff() <= 1e-3 * max_change;
      n_cycle_sweeps = returned ? n_cycle_sweeps + 1 : 0;
      if (n_cycle_sweeps >= kCycleSweeps) break;
      r_two_back.swap(r_previous);
      r_previous = r;
    }
  }
  return report;
}

}  // namespace

GaussSeidelReport solve_contact_gauss_seidel(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                             const std::vector<double>& bounds, const GaussSeidelSettings& settings,
                                             Eigen::VectorXd& r, Eigen::VectorXd* y_out,
                                             std::vector<ContactState>& state, const Eigen::MatrixXd* periodic_columns) {
  const Eigen::VectorXd r_start = r;
  Eigen::VectorXd y;  // updated in place by the sweeps
  GaussSeidelReport report = sweep_until_converged(W, q, f, bounds, settings, 1.0, r, y, state, periodic_columns);
  if (!report.converged) {
    // Plain sweeps cycled (or are too slow): restart from the warm start, under-relaxed.
    r = r_start;
    const int plain_iterations = report.iterations;
    report = sweep_until_converged(W, q, f, bounds, settings, kFallbackRelaxation, r, y, state, periodic_columns);
    report.iterations += plain_iterations;
  }
  // Recomputed from scratch (when asked for) so that rounding drift of the in-place updates never reaches it.
  if (y_out) compute_local_variables(W, q, r, periodic_columns, *y_out);
  return report;
}

}  // namespace slidewave

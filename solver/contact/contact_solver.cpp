#include "contact/contact_solver.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "contact/delassus.hpp"

namespace slidewave {

ContactSolver::ContactSolver(const Eigen::MatrixXd& W, const GaussSeidelSettings& settings, DelassusLayout layout)
    : W_(W), settings_(settings), n_nodes_(static_cast<int>(W.rows() / 2)) {
  diagonal_blocks_.reserve(n_nodes_);
  for (int k = 0; k < n_nodes_; ++k) diagonal_blocks_.emplace_back(W.block<2, 2>(2 * k, 2 * k));
  if (layout == DelassusLayout::block_circulant) {
    periodic_columns_ = delassus_periodic_columns(W);
    reach_ = delassus_periodic_reach(periodic_columns_, n_nodes_, kDelassusRoundOff);
    periodic_product_.emplace(W.leftCols<2>());
    all_stick_.emplace(W);
  }
}

void ContactSolver::local_variables(const Eigen::VectorXd& q, const Eigen::VectorXd& r, Eigen::VectorXd& y) const {
  if (periodic_product_)
    periodic_product_->residual(q, r, y);
  else
    y = q + W_ * r;
}

bool ContactSolver::solve_all_stick(const Eigen::VectorXd& q, const FrictionBounds& bounds, Eigen::VectorXd& r,
                                    std::vector<ContactState>& state) {
  if (!all_stick_) throw std::logic_error("ContactSolver: the exact all-stick solution needs a block-circulant W");
  return all_stick_->solve(q, bounds, r, state);
}

GaussSeidelReport ContactSolver::sweep_until_converged(const Eigen::VectorXd& q, FrictionBounds& bounds,
                                                       double relaxation, Eigen::VectorXd& r, Eigen::VectorXd& y,
                                                       std::vector<ContactState>& state) const {
  const int n_nodes = n_nodes_;
  const bool periodic = periodic_columns_.size() > 0;
  const double f = bounds.f();
  state.assign(n_nodes, ContactState::open);
  local_variables(q, r, y);
  bounds.start_pass(n_nodes);

  GaussSeidelReport report{0, 0.0, false};
  report.relaxation = relaxation;
  // Period-2 orbit detection (plain pass only, from sweep kCycleWatchFrom on, so that the usual
  // 10-25-sweep solves pay nothing): r two sweeps back, and how many sweeps in a row came back to it
  // while still changing by more than the tolerance.
  Eigen::VectorXd r_previous, r_two_back;
  int n_cycle_sweeps = 0;
  // Stall detection (plain pass): the sweep at which the smallest change last fell below half the one before.
  double halved_change = std::numeric_limits<double>::infinity();
  int halved_at = 0;
  while (report.iterations < settings_.max_iterations) {
    ++report.iterations;
    double max_change = 0;
    for (int k = 0; k < n_nodes; ++k) {
      const Eigen::Vector2d r_old = r.segment<2>(2 * k);
      const Eigen::Vector2d b = y.segment<2>(2 * k) - diagonal_blocks_[k].D * r_old;
      const std::optional<double> given_bound = bounds.given_bound(k);
      const auto local = given_bound ? solve_local_coulomb(diagonal_blocks_[k], b, f, *given_bound)
                                     : solve_local_coulomb(diagonal_blocks_[k], b, f);
      if (report.iterations > 1 &&  // sweep 1 compares with the all-open start
          (local.state == ContactState::open) != (state[k] == ContactState::open))
        bounds.status_changed(k);
      state[k] = local.state;
      const Eigen::Vector2d change = local.r - r_old;
      if (change.x() != 0 || change.y() != 0) {
        // relaxation 1 assigns local.r itself (r_old + change may differ from it in the last bit)
        const Eigen::Vector2d delta = relaxation == 1 ? change : Eigen::Vector2d(relaxation * change);
        r.segment<2>(2 * k) = relaxation == 1 ? local.r : Eigen::Vector2d(r_old + delta);
        if (periodic)
          add_periodic_node_columns(periodic_columns_, n_nodes, k, reach_, delta.x(), delta.y(), y);
        else
          y.noalias() += W_.middleCols<2>(2 * k) * delta;
        max_change = std::max(max_change, change.cwiseAbs().maxCoeff());
      }
    }
    report.residual = max_change / settings_.force_scale;
    if (report.residual <= settings_.tolerance) {
      report.converged = true;
      break;
    }
    if (relaxation == 1 && max_change < 0.5 * halved_change) {
      halved_change = max_change;
      halved_at = report.iterations;
    }
    if (relaxation == 1 && report.iterations - halved_at >= kStallSweeps) break;
    if (relaxation == 1 && report.iterations >= kCycleWatchFrom) {
      // Back where it was two sweeps ago (to 1e-3 of this sweep's change) on kCycleSweeps sweeps in a
      // row: a period-2 orbit that will never converge, so stop now instead of at max_iterations.
      // A converging iteration cannot show this (its changes would have to alternate without decaying).
      const bool returned =
          report.iterations >= kCycleWatchFrom + 2 && (r - r_two_back).cwiseAbs().maxCoeff() <= 1e-3 * max_change;
      n_cycle_sweeps = returned ? n_cycle_sweeps + 1 : 0;
      if (n_cycle_sweeps >= kCycleSweeps) break;
      r_two_back.swap(r_previous);
      r_previous = r;
    }
  }
  report.n_bounds_released = bounds.n_released();
  return report;
}

GaussSeidelReport ContactSolver::solve(const Eigen::VectorXd& q, FrictionBounds& bounds, Eigen::VectorXd& r,
                                       std::vector<ContactState>& state) const {
  const Eigen::VectorXd r_start = r;
  Eigen::VectorXd y;  // updated in place by the sweeps
  GaussSeidelReport report = sweep_until_converged(q, bounds, 1.0, r, y, state);
  if (!report.converged) {
    // Plain sweeps cycled (or are too slow): restart from the warm start, under-relaxed.
    r = r_start;
    const int plain_iterations = report.iterations;
    report = sweep_until_converged(q, bounds, kFallbackRelaxation, r, y, state);
    report.iterations += plain_iterations;
  }
  return report;
}

}  // namespace slidewave

#include "contact/all_stick.hpp"

#include <cmath>
#include <stdexcept>

#include "contact/delassus.hpp"

namespace slidewave {

AllStickSolution::AllStickSolution(const Eigen::MatrixXd& W) : n_nodes_(static_cast<int>(W.rows() / 2)) {
  const Eigen::LLT<Eigen::MatrixXd> factor(W);
  if (factor.info() != Eigen::Success)
    throw std::invalid_argument("AllStickSolution: the Delassus operator is not positive definite");
  const Eigen::MatrixXd first_columns = factor.solve(Eigen::MatrixXd::Identity(W.rows(), 2));
  inverse_columns_.resize(2 * W.rows(), 2);
  inverse_columns_.topRows(W.rows()) = first_columns;
  inverse_columns_.bottomRows(W.rows()) = first_columns;
  zero_ = Eigen::VectorXd::Zero(W.rows());
  minus_q_.resize(W.rows());
  trial_.resize(W.rows());
}

bool AllStickSolution::solve(const Eigen::VectorXd& q, const FrictionBounds& bounds, Eigen::VectorXd& r,
                             std::vector<ContactState>& state) {
  minus_q_ = -q;
  periodic_residual(inverse_columns_, n_nodes_, zero_, minus_q_, trial_);
  for (int k = 0; k < n_nodes_; ++k) {
    const double r_x = trial_(2 * k), r_y = trial_(2 * k + 1);
    if (!(r_y >= 0 && std::fabs(r_x) <= bounds.bound(k, r_y))) return false;
  }
  r.swap(trial_);
  state.assign(n_nodes_, ContactState::stick);
  return true;
}

}  // namespace slidewave

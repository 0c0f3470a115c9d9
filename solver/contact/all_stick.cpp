#include "contact/all_stick.hpp"

#include <cmath>

namespace slidewave {

AllStickSolution::AllStickSolution(const Eigen::MatrixXd& W)
    : n_nodes_(static_cast<int>(W.rows() / 2)), inverse_(BlockCirculantProduct(W.leftCols<2>()).inverse()) {}

bool AllStickSolution::solve(const Eigen::VectorXd& q, const FrictionBounds& bounds, Eigen::VectorXd& r,
                             std::vector<ContactState>& state) {
  inverse_.apply(q, trial_);
  trial_ = -trial_;
  for (int k = 0; k < n_nodes_; ++k) {
    const double r_x = trial_(2 * k), r_y = trial_(2 * k + 1);
    if (!(r_y >= 0 && std::fabs(r_x) <= bounds.bound(k, r_y))) return false;
  }
  r.swap(trial_);
  state.assign(n_nodes_, ContactState::stick);
  return true;
}

}  // namespace slidewave

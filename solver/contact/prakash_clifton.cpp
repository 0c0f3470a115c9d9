#include "contact/prakash_clifton.hpp"

#include <cmath>

namespace slidewave {

PrakashClifton::PrakashClifton(double f, double slip_length, double reference_velocity)
    : f_(f), slip_length_(slip_length), reference_velocity_(reference_velocity) {}

FrictionState PrakashClifton::initial_state(const Eigen::VectorXd& r) const {
  FrictionState state;
  const Eigen::Index n_nodes = r.size() / 2;
  state.per_node.resize(n_nodes);
  for (Eigen::Index k = 0; k < n_nodes; ++k) state.per_node[k] = r(2 * k + 1);
  return state;
}

void PrakashClifton::bounds(const FrictionState& state, std::vector<double>& bounds) const {
  const auto& sigma = state.per_node;
  bounds.resize(sigma.size());
  for (size_t k = 0; k < sigma.size(); ++k) bounds[k] = f_ * sigma[k];
}

void PrakashClifton::update(const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r, double dt,
                            FrictionState& state) const {
  auto& sigma = state.per_node;
  for (size_t k = 0; k < sigma.size(); ++k) {
    const double theta = (std::fabs(du_contact(2 * k)) + reference_velocity_ * dt) / slip_length_;
    sigma[k] = (sigma[k] + theta * r(2 * k + 1)) / (1 + theta);
  }
}

}  // namespace slidewave

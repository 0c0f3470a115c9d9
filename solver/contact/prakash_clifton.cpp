#include "contact/prakash_clifton.hpp"

#include <cmath>
#include <utility>

namespace slidewave {

PrakashCliftonBounds::PrakashCliftonBounds(double f, std::vector<double> given)
    : FrictionBounds(f), given_(std::move(given)), n_status_changes_(given_.size(), 0) {}

std::optional<double> PrakashCliftonBounds::given_bound(int k) const {
  if (n_status_changes_[k] > kMaxStatusChanges) return std::nullopt;
  return given_[k];
}

void PrakashCliftonBounds::start_pass(int n_nodes) {
  n_status_changes_.assign(n_nodes, 0);
  n_released_ = 0;
}

void PrakashCliftonBounds::status_changed(int k) {
  if (++n_status_changes_[k] == kMaxStatusChanges + 1) ++n_released_;
}

PrakashClifton::PrakashClifton(double f, double slip_length, double reference_velocity)
    : f_(f), slip_length_(slip_length), reference_velocity_(reference_velocity) {}

FrictionState PrakashClifton::initial_state(const Eigen::VectorXd& r) const {
  FrictionState state;
  const Eigen::Index n_nodes = r.size() / 2;
  state.per_node.resize(n_nodes);
  for (Eigen::Index k = 0; k < n_nodes; ++k) state.per_node[k] = r(2 * k + 1);
  return state;
}

std::unique_ptr<FrictionBounds> PrakashClifton::bounds(const FrictionState& state) const {
  const auto& sigma = state.per_node;
  std::vector<double> given(sigma.size());
  for (size_t k = 0; k < sigma.size(); ++k) given[k] = f_ * sigma[k];
  return std::make_unique<PrakashCliftonBounds>(f_, std::move(given));
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

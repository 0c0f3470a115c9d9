#pragma once
// Prakash–Clifton regularization of Coulomb friction (`friction.regularization = prakash_clifton`):
// the friction strength follows the pressure with a memory, |R_t| <= f sigma while closed, where the
// regularized normal force sigma of each node relaxes towards R_n over a slip length L:
//     d sigma / dt = -(|v_x| + v*) / L (sigma - R_n),
// discretized implicitly over a step: theta = (|du_x| + v* dt) / L,
//     sigma(n+1) = (sigma(n) + theta R_n(n+1)) / (1 + theta).
// sigma starts at the preload reaction. State: sigma per node (N).
//
// Grazing. The bound f sigma makes the local law discontinuous at opening: |r_x| <= f sigma_k while
// closed, however small r_y, and r = 0 once open. A node at grazing then can have no solution other than
// the grazing one (u_y = r_y = 0), which exact local solves never hit: through the coupling of W, its
// friction force opens it, opening removes the force, and it closes again, so the contact solver's
// sweeps cycle for ever. A node whose open/closed status has changed more than kMaxStatusChanges times
// in one pass of sweeps therefore gets the Coulomb bound f r_y (the Prakash–Clifton strength with the
// memory relaxed onto the current pressure, continuous at opening) for the rest of that pass.
#include <vector>

#include "contact/friction_bounds.hpp"
#include "contact/friction_law.hpp"

namespace slidewave {

/// Status changes (open <-> closed) of one node in one pass after which its bound f sigma is replaced
/// by f r_y. Genuine changes during convergence are one or two; cycles repeat without end.
inline constexpr int kMaxStatusChanges = 4;

/// The bound f sigma_k of each closed node, released to f r_y at grazing (see above).
class PrakashCliftonBounds : public FrictionBounds {
 public:
  /// @param given  f sigma_k per node (N)
  PrakashCliftonBounds(double f, std::vector<double> given);
  std::optional<double> given_bound(int k) const override;
  void start_pass(int n_nodes) override;
  void status_changed(int k) override;
  int n_released() const override { return n_released_; }

 private:
  std::vector<double> given_;
  std::vector<int> n_status_changes_;
  int n_released_ = 0;
};

class PrakashClifton : public FrictionLaw {
 public:
  /// @param f                friction coefficient
  /// @param slip_length      L (m), > 0
  /// @param reference_velocity v* (m/s), >= 0
  PrakashClifton(double f, double slip_length, double reference_velocity);

  FrictionState initial_state(const Eigen::VectorXd& r) const override;
  std::unique_ptr<FrictionBounds> bounds(const FrictionState& state) const override;
  void update(const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r, double dt,
              FrictionState& state) const override;

 private:
  double f_, slip_length_, reference_velocity_;
};

}  // namespace slidewave

#pragma once
// Prakash–Clifton regularization of Coulomb friction (`friction.regularization = prakash_clifton`):
// the friction strength follows the pressure with a memory, |R_t| <= f sigma while closed, where the
// regularized normal force sigma of each node relaxes towards R_n over a slip length L:
//     d sigma / dt = -(|v_x| + v*) / L (sigma - R_n),
// discretized implicitly over a step: theta = (|du_x| + v* dt) / L,
//     sigma(n+1) = (sigma(n) + theta R_n(n+1)) / (1 + theta).
// sigma starts at the preload reaction. State: sigma per node (N).
#include "contact/friction_law.hpp"

namespace slidewave {

class PrakashClifton : public FrictionLaw {
 public:
  /// @param f                friction coefficient
  /// @param slip_length      L (m), > 0
  /// @param reference_velocity v* (m/s), >= 0
  PrakashClifton(double f, double slip_length, double reference_velocity);

  FrictionState initial_state(const Eigen::VectorXd& r) const override;
  void bounds(const FrictionState& state, std::vector<double>& bounds) const override;
  void update(const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r, double dt,
              FrictionState& state) const override;

 private:
  double f_, slip_length_, reference_velocity_;
};

}  // namespace slidewave

#pragma once
// Coulomb friction, |R_t| <= f R_n (`friction.regularization = none`, the paper's law): memoryless, the
// bound is f r_y of the current solve, which the contact solver applies when given no bounds.
#include "contact/friction_law.hpp"

namespace slidewave {

class CoulombFriction : public FrictionLaw {
 public:
  FrictionState initial_state(const Eigen::VectorXd& r) const override;
  void bounds(const FrictionState& state, std::vector<double>& bounds) const override;
  void update(const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r, double dt,
              FrictionState& state) const override;
};

}  // namespace slidewave

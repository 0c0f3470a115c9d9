#pragma once
// Coulomb friction, |R_t| <= f R_n (`friction.regularization = none`, the paper's law): memoryless, the
// bound of every closed node is f r_y of the current solve.
#include "contact/friction_bounds.hpp"
#include "contact/friction_law.hpp"

namespace slidewave {

/// The Coulomb bound f r_y at every node (also the quasi-static preload's, whatever the law).
class CoulombBounds : public FrictionBounds {
 public:
  explicit CoulombBounds(double f) : FrictionBounds(f) {}
  std::optional<double> given_bound(int) const override { return std::nullopt; }
};

class CoulombFriction : public FrictionLaw {
 public:
  /// @param f friction coefficient
  explicit CoulombFriction(double f) : f_(f) {}

  FrictionState initial_state(const Eigen::VectorXd& r) const override;
  std::unique_ptr<FrictionBounds> bounds(const FrictionState& state) const override;
  void update(const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r, double dt,
              FrictionState& state) const override;

 private:
  double f_;
};

}  // namespace slidewave

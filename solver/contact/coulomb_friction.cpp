#include "contact/coulomb_friction.hpp"

namespace slidewave {

FrictionState CoulombFriction::initial_state(const Eigen::VectorXd&) const { return {}; }

std::unique_ptr<FrictionBounds> CoulombFriction::bounds(const FrictionState&) const {
  return std::make_unique<CoulombBounds>(f_);
}

void CoulombFriction::update(const Eigen::VectorXd&, const Eigen::VectorXd&, double, FrictionState&) const {}

}  // namespace slidewave

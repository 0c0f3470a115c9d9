#include "contact/coulomb_friction.hpp"

namespace slidewave {

FrictionState CoulombFriction::initial_state(const Eigen::VectorXd&) const { return {}; }

void CoulombFriction::bounds(const FrictionState&, std::vector<double>& bounds) const { bounds.clear(); }

void CoulombFriction::update(const Eigen::VectorXd&, const Eigen::VectorXd&, double, FrictionState&) const {}

}  // namespace slidewave

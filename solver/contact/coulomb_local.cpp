#include "contact/coulomb_local.hpp"

#include <cmath>

namespace slidewave {

LocalContactSolution solve_local_coulomb(const LocalOperator& A, const Eigen::Vector2d& b, double f,
                                         std::optional<double> fixed_bound) {
  const Eigen::Matrix2d& D = A.D;
  // Open: no reaction, the free gap is non-negative.
  if (b.y() >= 0) return {Eigen::Vector2d::Zero(), ContactState::open, true};

  const auto bound = [&](double r_y) { return fixed_bound ? *fixed_bound : f * r_y; };

  // Stick: du_x = 0 and u_y = 0.
  const Eigen::Vector2d r_stick = -A.D_ldlt.solve(b);
  const double slack = 1e-14 * std::fabs(r_stick.y());
  if (r_stick.y() >= 0 && std::fabs(r_stick.x()) <= bound(r_stick.y()) + slack)
    return {r_stick, ContactState::stick, true};

  // Slip in direction s (sign of du_x): r_x = -s mu, u_y = 0. Try the direction the stick trial points
  // to first (friction saturated against the stick force), then the other one.
  const double s_first = r_stick.x() > 0 ? -1.0 : 1.0;
  LocalContactSolution fallback{r_stick, ContactState::stick, false};
  for (double s : {s_first, -s_first}) {
    Eigen::Vector2d r;
    if (fixed_bound) {
      r.x() = -s * *fixed_bound;
      r.y() = -(b.y() + D(1, 0) * r.x()) / D(1, 1);
    } else {
      const double denominator = D(1, 1) - s * f * D(1, 0);
      if (denominator <= 0) continue;
      r.y() = -b.y() / denominator;
      r.x() = -s * f * r.y();
    }
    const double du_x = b.x() + D(0, 0) * r.x() + D(0, 1) * r.y();
    if (r.y() >= 0 && s * du_x >= 0) return {r, ContactState::slip, true};
    fallback = {r, ContactState::slip, false};
  }
  return fallback;
}

}  // namespace slidewave

#include "contact/coulomb_local.hpp"

#include <cmath>

#include <limits>
#include <utility>

namespace slidewave {

LocalOperator::LocalOperator(const Eigen::Matrix2d& block) : D(block) {
  const Eigen::LDLT<Eigen::Matrix2d> ldlt(block);
  swapped_ = ldlt.transpositionsP().indices()(0) == 1;  // indices()(1) is 1: nothing left to exchange
  l_ = ldlt.matrixLDLT()(1, 0);
  d0_ = ldlt.vectorD()(0);
  d1_ = ldlt.vectorD()(1);
}

Eigen::Vector2d LocalOperator::solve(const Eigen::Vector2d& b) const {
  // Eigen's LDLT::_solve_impl_transposed: x = P b; x = L^-1 x; x = D^+ x (a pivot of magnitude at most the
  // smallest normal double gives 0, its pseudo-inverse); x = L^-T x; x = P^T x.
  double x0 = b.x(), x1 = b.y();
  if (swapped_) std::swap(x0, x1);
  x1 -= l_ * x0;
  constexpr double tiny = std::numeric_limits<double>::min();
  x0 = std::fabs(d0_) > tiny ? x0 / d0_ : 0.0;
  x1 = std::fabs(d1_) > tiny ? x1 / d1_ : 0.0;
  x0 -= l_ * x1;
  if (swapped_) std::swap(x0, x1);
  return {x0, x1};
}

LocalContactSolution solve_local_coulomb(const LocalOperator& A, const Eigen::Vector2d& b, double f,
                                         std::optional<double> fixed_bound) {
  const Eigen::Matrix2d& D = A.D;
  // Open: no reaction, the free gap is non-negative.
  if (b.y() >= 0) return {Eigen::Vector2d::Zero(), ContactState::open, true};

  const auto bound = [&](double r_y) { return fixed_bound ? *fixed_bound : f * r_y; };

  // Stick: du_x = 0 and u_y = 0.
  const Eigen::Vector2d r_stick = -A.solve(b);
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

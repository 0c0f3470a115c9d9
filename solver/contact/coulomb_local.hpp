#pragma once
// Exact solution of the frictional contact problem of ONE node with a rigid flat, given the
// linear response of its local variables to its own reaction:
//     y = b + D r,   y = (du_x, u_y) = (slip increment over the step, gap),
//                    r = (r_x, r_y)  = reaction of the flat on the node (r_y > 0 pushes the body up).
// Signorini:  u_y >= 0, r_y >= 0, u_y r_y = 0.
// Coulomb:    |r_x| <= mu(r_y), and du_x != 0 implies r_x = -mu sign(du_x)  (friction opposes the slip
//             increment over the step), with mu(r_y) = f r_y, or mu = f * sigma_reg (a fixed bound,
//             Prakash–Clifton) while the node is closed.
// D must be symmetric positive definite (a 2x2 block of the Delassus operator).
// Cases are enumerated (open, stick, slip forward, slip backward); the first consistent one is returned.
#include <Eigen/Dense>
#include <algorithm>
#include <optional>
#include <vector>

namespace slidewave {

enum class ContactState : signed char { open = 0, stick = 1, slip = 2 };

/// Every node sticks.
inline bool all_stuck(const std::vector<ContactState>& state) {
  return std::all_of(state.begin(), state.end(), [](ContactState s) { return s == ContactState::stick; });
}

struct LocalContactSolution {
  Eigen::Vector2d r;
  ContactState state;
  bool consistent;  ///< false only if no case satisfied every condition (not expected for SPD D)
};

/// D and its L D L^T (Eigen's LDLT, pivoting included), factorized once for the many local solves of a node.
class LocalOperator {
 public:
  explicit LocalOperator(const Eigen::Matrix2d& block);
  Eigen::Matrix2d D;
  /// D^-1 b from the factors: Eigen's LDLT<Matrix2d>::solve written out for two unknowns, the same operations on
  /// the same numbers in the same order, so the same bits, without its general loops (2 % of an H/64 run went
  /// into them).
  Eigen::Vector2d solve(const Eigen::Vector2d& b) const;

 private:
  bool swapped_;    ///< the pivot P exchanges the two unknowns
  double l_;        ///< L(1, 0)
  double d0_, d1_;  ///< the diagonal of D in the factorization
};

/// @param f            friction coefficient (>= 0)
/// @param fixed_bound  if set, the friction bound while closed is this value instead of f * r_y
LocalContactSolution solve_local_coulomb(const LocalOperator& A, const Eigen::Vector2d& b, double f,
                                         std::optional<double> fixed_bound = std::nullopt);

}  // namespace slidewave

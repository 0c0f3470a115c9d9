#pragma once
// The exact solution of a step's contact problem while the whole interface sticks.
// Every node sticking means y = q + W r = 0, so r = -W^{-1} q: one product with W^{-1}, where projected
// Gauss–Seidel (contact_solver.hpp) needs 9-27 sweeps to reach the same r to its tolerance (before slip
// onset, most of a Table-1 run). That r solves the problem whenever every node of it is closed and inside
// its friction bound (r_y >= 0, |r_x| <= the law's bound, contact/friction_bounds.hpp): the stick
// conditions then hold at every node with y = 0 exactly. Otherwise it is not a solution and the step is left to
// Gauss–Seidel.
//
// W^{-1} of a block-circulant W is block-circulant too, with the inverse 2 x 2 block per wavenumber: one
// product by FFT (contact/block_circulant_product.hpp), O(n log n) where the dense product is O(n^2).
// The r found differs from the Gauss–Seidel one only within that solve's tolerance; the run's results move
// by what that round-off grows to (contact.all_stick, docs/contact-solver.md).
#include <Eigen/Dense>
#include <vector>

#include "contact/block_circulant_product.hpp"
#include "contact/coulomb_local.hpp"
#include "contact/friction_bounds.hpp"

namespace slidewave {

class AllStickSolution {
 public:
  /// @param W block-circulant Delassus operator (2n x 2n, SPD), as delassus_operator_periodic makes it
  explicit AllStickSolution(const Eigen::MatrixXd& W);

  /// r = -W^{-1} q if it is closed and inside the friction bound at every node: then r holds it, every
  /// state is stick and true is returned. Otherwise false, and r and state are left as they were.
  /// @param bounds the friction law's bounds of this solve
  bool solve(const Eigen::VectorXd& q, const FrictionBounds& bounds, Eigen::VectorXd& r,
             std::vector<ContactState>& state);

 private:
  int n_nodes_;
  BlockCirculantProduct inverse_;  ///< products with W^{-1}
  Eigen::VectorXd trial_;
};

}  // namespace slidewave

#pragma once
// A solver of K u = b + C^T g that can be run in two halves around a contact solve, C picking the first
// n_contact DOFs (the contact DOFs):
//     solve_free(b)    the free response u_free = K^{-1} b at the contact DOFs (all the contact solve needs);
//     solve_loaded(g)  u = K^{-1} (b + C^T g) for the b of the last solve_free, all DOFs.
// An implementation keeps what the second half needs from the first, so that the pair costs about one
// solve (BlockCirculantSolver keeps the spectrum of b) instead of the two solves of
// K^{-1} b and K^{-1} (b + C^T g). Same discrete solution to round-off, not bitwise.
#include <Eigen/Dense>

#include "linalg/linear_solver.hpp"

namespace slidewave {

class SplitSolver : public LinearSolver {
 public:
  /// Number of leading DOFs that carry the load g of solve_loaded().
  virtual int n_contact() const = 0;
  /// u_contact = (K^{-1} b) on the first n_contact() DOFs; b has size() entries, u_contact n_contact().
  virtual void solve_free(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> u_contact) = 0;
  /// u = K^{-1} (b + C^T g), b that of the last solve_free(), which must precede it (once: the kept state is
  /// consumed); g has n_contact() entries, u size(). A solve_into() in between does not disturb the kept state.
  virtual void solve_loaded(const Eigen::Ref<const Eigen::VectorXd>& g, Eigen::Ref<Eigen::VectorXd> u) = 0;
};

}  // namespace slidewave

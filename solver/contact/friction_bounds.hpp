#pragma once
// The friction bound of each node for one contact solve, as the friction law sets it
// (FrictionLaw::bounds, contact/friction_law.hpp): while node k is closed, |r_x| <= f r_y (Coulomb) or
// |r_x| <= g_k, a bound the law gives (contact/coulomb_local.hpp solves a node either way).
//
// The contact solver (contact/contact_solver.hpp) asks for node k's bound before each local solve and
// tells the bounds when a node opened or closed between two sweeps; a law whose bound is discontinuous
// at opening uses that to change the node's bound for the rest of the pass (contact/prakash_clifton.hpp).
// The solver itself knows no law.
#include <optional>

namespace slidewave {

class FrictionBounds {
 public:
  /// @param f friction coefficient of the bound f r_y
  explicit FrictionBounds(double f) : f_(f) {}
  virtual ~FrictionBounds() = default;

  /// f of the bound f r_y.
  double f() const { return f_; }
  /// Node k's bound while closed if the law gives one (N), or nothing for f r_y.
  virtual std::optional<double> given_bound(int k) const = 0;
  /// Node k's bound while closed at the normal reaction r_y: given_bound(k), or f r_y.
  double bound(int k, double r_y) const {
    const std::optional<double> given = given_bound(k);
    return given ? *given : f_ * r_y;
  }

  /// A pass of sweeps starts (the solver's fallback pass starts again from the warm start): what the
  /// bounds learnt from the status changes of an earlier pass is forgotten.
  virtual void start_pass(int n_nodes) { (void)n_nodes; }
  /// Node k opened or closed between two sweeps of the pass.
  virtual void status_changed(int k) { (void)k; }
  /// Nodes whose given bound this pass has replaced by f r_y (the solver reports it).
  virtual int n_released() const { return 0; }

 private:
  double f_;
};

}  // namespace slidewave

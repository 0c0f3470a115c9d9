#pragma once
// What the time loop needs of a friction law, beyond the local Signorini–Coulomb solve
// (contact/coulomb_local.hpp) that every law shares: the friction bound of each closed node for the
// contact solve of a step (contact/friction_bounds.hpp), and the update of the law's state after the step.
//
// Adding a law: one file pair that implements FrictionLaw (and its FrictionBounds), plus one line in the
// registry of contact/friction_law.cpp (keyed by the config value `friction.regularization`). The contact
// solver and the loop do not change.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "config/run_config.hpp"
#include "contact/friction_bounds.hpp"

namespace slidewave {

/// The law's state, carried from step to step (a checkpoint saves it): one value per contact node, whose
/// meaning the law defines (empty for a memoryless law).
struct FrictionState {
  std::vector<double> per_node;
};

class FrictionLaw {
 public:
  virtual ~FrictionLaw() = default;

  /// State at the start of the dynamics, from the reactions r of the preload (2 per node: x, y).
  virtual FrictionState initial_state(const Eigen::VectorXd& r) const = 0;

  /// Friction bound of each closed node for the next contact solve.
  virtual std::unique_ptr<FrictionBounds> bounds(const FrictionState& state) const = 0;

  /// Moves the state over a step that ended with the reactions r and the contact displacement increment
  /// du_contact (2 per node: du_x, du_y), dt long.
  virtual void update(const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r, double dt,
                      FrictionState& state) const = 0;
};

/// The law named by config.regularization, with its parameters.
std::unique_ptr<FrictionLaw> make_friction_law(const FrictionConfig& config);

}  // namespace slidewave

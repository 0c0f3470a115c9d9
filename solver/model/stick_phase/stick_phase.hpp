#pragma once
// The stick phase of the dynamic stage stepped in wavenumbers (docs/stick-phase.md): from the layer's
// seeded state at t = 0 (or any all-stick state), while every contact node sticks, the same discrete
// solution as the plain HHT step with the exact all-stick contact solve, to round-off, at the cost of the
// active wavenumbers (model/stick_phase/wavenumber_stepper.hpp) instead of a layer step. Each step gives
// what the recorder needs: the contact reactions at every node (the all-stick solution's friction test is
// made on them), the energies and the ledger's running sums; the layer's state in full on demand (output
// rows, snapshots) and at hand-over (reconstruct(), then plain stepping continues).
// Rigid flat only (no substrate); friction bounds as the law gives them.
#include <Eigen/Dense>
#include <cstdint>

#include "contact/friction_bounds.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/stick_phase/row_transform.hpp"
#include "model/stick_phase/stick_phase_ledger.hpp"
#include "model/stick_phase/wavenumber_blocks.hpp"
#include "model/stick_phase/wavenumber_stepper.hpp"

namespace slidewave {

class StickPhase {
 public:
  /// Retirement tolerance of the default: a wavenumber retires when it can no longer change a double of
  /// an entry of the layer's size (half an ulp: 2^-54 of the scale).
  static constexpr double kRetireTolerance = 0x1p-54;

  /// @param layer  the layer and its blocks per wavenumber (both must outlive this object); u_x_top: the preload's
  ///               top shear displacement
  /// @param retire_tolerance 0: never retire (also what any hht_alpha but the paper's 0.1 gets)
  StickPhase(const LayerModel& layer, const WavenumberBlocks& blocks, double u_x_top,
             double retire_tolerance = kRetireTolerance);

  /// Starts from the layer's loop state (all contact nodes sticking), e.g. the seeded state at t = 0.
  void start(const LoopState& loop);
  /// One all-stick step. Returns false, and leaves the state at its step, if the all-stick reactions of
  /// the step leave a friction bound (or a node would open): the step at which plain stepping slips.
  bool step(const FrictionBounds& bounds);

  std::int64_t step_count() const { return step_; }
  int n_active() const { return stepper_.n_active(); }
  /// The row length of the step's arrays (the active wavenumbers rounded up to a cache line).
  int array_width() const { return stepper_.width(); }
  /// The reactions of the current step (2 per contact node), as the all-stick solution gives them.
  const Eigen::VectorXd& reactions() const { return r_; }
  /// The contact displacements of the current step (2 per contact node; the interface rows need them).
  const Eigen::VectorXd& contact_displacement() const { return u_contact_; }
  /// The reactions the last failed step() found (the trial solution that left a bound).
  const Eigen::VectorXd& trial_reactions() const { return r_trial_; }
  double kinetic() const;
  double elastic() const;
  /// The running sums of the energy ledger (energy_start as at start(); F_top and the HHT vectors are filled
  /// by reconstruct()).
  const EnergySums& sums() const { return sums_; }
  /// The layer's loop state at the current step, in full: dynamics, energy sums, contact states, step.
  void reconstruct(LoopState& loop) const;

 private:
  Eigen::Vector2d top_after(std::int64_t step) const;

  const LayerModel& layer_;
  HHTCoefficients hht_;
  double u_x_top_;
  const WavenumberBlocks& blocks_;
  RowTransform transform_;
  WavenumberStepper stepper_;
  StickPhaseLedger ledger_;
  std::int64_t step_ = 0;
  EnergySums sums_;
  Eigen::VectorXd r_, r_trial_, u_contact_, u_contact_held_, du_contact_;
  bool contact_held_ = false;                        ///< the first step has moved the contact rows to their held values
  Eigen::Vector2d F_top_ = Eigen::Vector2d::Zero();  ///< the ledger's top force at the current step
};

}  // namespace slidewave

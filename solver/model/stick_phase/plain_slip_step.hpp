#pragma once
// simulate()'s slip step on the rigid flat (model/simulation.cpp, section 6: predictor and free solve,
// contact solve, correction with the Newmark update, friction memory) outside simulate(), from a captured
// loop state: the reference the wavenumber slip step (model/stick_phase/wavenumber_slip_step.hpp) is
// compared and timed against. The same operations in the same order as the loop, so the same bits; not
// the recorder, the energy ledger or the opening detection (the prototype has none of them either).
// Rigid flat only (no substrate).
#include <Eigen/Dense>
#include <cstdint>
#include <memory>

#include "contact/friction_law.hpp"
#include "model/contact_step.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/run_observer.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

/// The loop state of a rigid-flat run of `m` from the arrays a RunObserver captured (its vectors sized as
/// simulate()'s setup sizes them; std::runtime_error if the arrays do not fit).
LoopState captured_loop_state(const LayerModel& m, const StateArrays& arrays);

class PlainSlipStep {
 public:
  /// The stepper, its Delassus operator W and the contact settings, built as simulate() builds them.
  /// @param u_x_top the preload's top shear displacement (RunRecord::u_x_preshear)
  PlainSlipStep(const LayerModel& m, double u_x_top);

  /// W = w C K_eff^-1 C^T, as simulate() makes it (the wavenumber step solves its contact problems with it).
  const Eigen::MatrixXd& delassus() const { return W_; }
  const GaussSeidelSettings& settings() const { return settings_; }
  const FrictionLaw& friction() const { return *friction_; }

  /// From a captured state. Restarting: from a state of another step than the one the last step() ended at
  /// (HHTStepper keeps the predictor of that step and reuses it for the same top displacement).
  void start(const LoopState& loop);
  /// The three parts of a step (timed apart by the bench), in this order; step() does all three.
  void solve_free();
  GaussSeidelReport solve_contact();
  void correct();
  GaussSeidelReport step();

  const LoopState& state() const { return loop_; }

 private:
  const LayerModel& m_;
  double u_x_top_;
  HHTCoefficients hht_;
  PartitionedSystem system_;
  HHTStepper stepper_;
  Eigen::MatrixXd W_;
  GaussSeidelSettings settings_;
  std::unique_ptr<FrictionLaw> friction_;
  ContactStep contact_;
  LoopState loop_;
  const Eigen::VectorXd* u_free_ = nullptr;
  Eigen::VectorXd u_d_next_, u_d_following_, du_;
  Eigen::VectorXd top_after(std::int64_t step) const;
};

}  // namespace slidewave

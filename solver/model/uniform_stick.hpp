#pragma once
// The stick phase of the dynamic stage, computed on the layer's x-uniform column (docs/stick-phase.md).
//
// Until the first slip every contact node sticks: the contact DOFs stay where they are (y = q + W r = 0,
// r = -W^{-1} q) and the discrete problem is linear. The preloaded layer and its loading (the top moving
// at V0) are uniform in x, so the HHT solution of the unperturbed layer stays uniform: every mesh column
// moves as one column, the layer one element wide whose periodic assembly sums each row of K and M over x
// (the x-uniform block of the block-circulant matrices). A step of that column costs O(n_y), no FFT.
//
// The stage steps the column with the layer's own HHT step, all-stick contact solve and friction law until
// the all-stick solution first leaves a friction bound (or opens): step n_slip. The layer takes over at
//     n_handover = n_slip - 1 - n_lead,   n_lead = round(4 H / (c_s dt))  (four shear transits),
// where simulate() broadcasts the column to every mesh column and adds the seeded perturbation: it then
// radiates through the layer, and HHT damps its kick to the level of the layer's low modes, before the
// first slip, as the seed at t = 0 was when it was carried through the whole stick phase. (The seed is no longer carried through
// the stick phase: results move within the seed spread, not to round-off; docs/stick-phase.md.)
// Rows before the handover are the uniform layer's: every node shows its column's node, forces and
// energies are n_x times the column's. A frictionless interface (no stick) has no stick stage.
#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "contact/all_stick.hpp"
#include "contact/friction_law.hpp"
#include "model/energy_ledger.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/recorder.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

class UniformStick {
 public:
  /// @param layer    the layer (must outlive this object)
  /// @param preload  its preload state (x-uniform: the column takes mesh column 0), copied
  UniformStick(const LayerModel& layer, const PreloadState& preload);
  UniformStick(const UniformStick&) = delete;
  UniformStick& operator=(const UniformStick&) = delete;

  /// The step at which the layer takes over (n_handover above, or 0 without a stick stage), found by
  /// stepping the column from t = 0 to its first slip; n_steps_max if it never slips before. Returns
  /// early (0) when *stop becomes true.
  std::int64_t handover_step(std::int64_t n_steps_max, const std::atomic<bool>* stop);

  /// The column at t = 0 (preload, top moving at V0); the layer's energy_start; the rows of t = 0.
  void start(LoopState& layer, Recorder& recorder, int preload_contact_iterations);
  /// The column from a layer state of the stick stage (every mesh column equal, e.g. a checkpoint).
  void resume_from(const LoopState& layer);
  /// One column step: the layer's running sums grow by n_x times the column's, the rows are recorded.
  /// False if the column's all-stick solution failed (only after n_handover, which the caller never passes).
  bool step(LoopState& layer, Recorder& recorder);
  /// The layer's vectors, contact and friction states and recording from the column's (its sums kept).
  void expand_into(LoopState& layer) const;

  std::int64_t step_count() const { return column_loop_.step; }
  const LoopState& column() const { return column_loop_; }

 private:
  /// The column state at t = 0.
  LoopState initial_column() const;
  /// Steps `loop` once; false (loop unchanged but for the predictor) if a node would not stick.
  /// sums_increment: the column's sums of the step (scalars from zero).
  bool advance(LoopState& loop, EnergySums* sums_increment);
  Eigen::VectorXd top_after(std::int64_t step) const;

  const LayerModel& layer_;
  const PreloadState preload_;  ///< a copy: the caller may pass a temporary
  LayerModel column_;
  PartitionedSystem system_;
  HHTStepper stepper_;
  std::unique_ptr<FrictionLaw> friction_;
  AllStickSolution all_stick_;
  EnergyLedger ledger_;
  int n_x_;
  bool applies_;  ///< the preload sticks everywhere (not a frictionless interface)
  LoopState column_loop_;
  Eigen::VectorXd q_, r_next_, du_;
  std::vector<double> bounds_;
};

}  // namespace slidewave

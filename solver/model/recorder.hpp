#pragma once
// Recording and diagnostics of the dynamic stage: the one place that appends output rows (the layout of
// run.h5, docs/contracts.md section 2). Called by the loop of model/simulation.cpp after every step:
//   /global     every step: forces T, N, T/N, energies (model/energy_ledger.hpp; the HHT terms when asked),
//               contact sweeps;
//   /interface  every output.interface_stride steps: slip velocity, slip, opening, tractions, states;
//   /snapshots  the bulk fields at output.snapshot_times (the first step at or after each, within dt/2);
// and it watches for the first opening of the interface (which drives time.stop_after_opening).
// The rows go into an in-memory RunRecord that finish() hands over (or that a streaming writer drains
// as the run goes, through rows()).
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "contact/contact_solver.hpp"
#include "model/energy_ledger.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/run_record.hpp"

namespace slidewave {

/// Threshold above which a contact node counts as open (m): 1 % of the preload displacement |Uy|
/// (the same as analysis/opening.py, which documents the evidence for it). Written to /setup.
double opening_threshold(const RunConfig& config);

/// What a row is read from: the state, the running sums and the energies of the step.
struct RowSource {
  const LoopState& state;
  const EnergySums& sums;                      ///< the layer's running sums
  double e_kin, e_el;                          ///< energies of the layer (J/m)
  const EnergySums* substrate_sums = nullptr;  ///< the substrate's running sums (null: rigid flat)
  double e_kin_substrate = 0, e_el_substrate = 0;
};

class Recorder {
 public:
  /// Keeps references to model and ledger (they must outlive the recorder).
  Recorder(const LayerModel& model, const EnergyLedger& ledger, const PreloadState& preload);

  /// With a substrate (docs/substrate.md): its ledger (must outlive the recorder); from then on the interface
  /// rows are relative (layer minus substrate), the energies both bodies', the snapshots include it.
  void attach_substrate(const EnergyLedger& substrate_ledger);
  /// Rows at t = 0, before the first step; initializes loop.recording.
  void record_start(LoopState& loop, int contact_iterations);
  /// Rows of the step just done (t = loop.step dt); u_previous: all DOFs one step before.
  /// u_previous_substrate: the substrate's DOFs one step before (null without a substrate).
  void record_step(LoopState& loop, const Eigen::VectorXd& u_previous, const GaussSeidelReport& report,
                   const Eigen::VectorXd* u_previous_substrate = nullptr);
  /// Rows of a step taken in wavenumbers (model/stick_phase/): `view` holds the step, the contact
  /// displacements (dynamics.u, n_contact entries), the reactions, the contact states and the sums;
  /// u_contact_previous: the contact displacements one step before; `report`: the step's contact solve;
  /// `full`: called for the whole state when a snapshot is due.
  void record_wavenumber_step(LoopState& view, double e_kin, double e_el, const Eigen::VectorXd& u_contact_previous,
                              const GaussSeidelReport& report, const std::function<LoopState()>& full);
  /// True at the first step at which a contact node opens more than opening_threshold (then records its time).
  bool detect_first_opening(LoopState& loop);
  /// Last apparent friction T/N recorded (for progress reports).
  double last_T_over_N() const { return last_T_over_N_; }
  /// The rows recorded so far, which an observer may move elsewhere (model/run_observer.hpp).
  RunRecord& rows() { return record_; }

  /// The record, with the outcome of the run: n_steps_done = loop.step.
  RunRecord finish(const LoopState& loop, bool complete, const std::string& end_reason);

 private:
  RowSource layer_source(const LoopState& loop) const;
  void record_global(double t, const RowSource& source, int contact_iterations, double contact_residual);
  void record_interface(double t, const RowSource& source, const Eigen::VectorXd& u_previous,
                        const Eigen::VectorXd* u_previous_substrate = nullptr);
  void record_due_snapshots(double t, const RowSource& source, RecorderState& recording);

  const LayerModel& model_;
  const EnergyLedger& ledger_;
  const EnergyLedger* substrate_ledger_ = nullptr;
  double dt_, opening_threshold_;
  std::vector<double> snapshot_times_;  ///< sorted
  RunRecord record_;
  double last_T_over_N_ = 0;
};

}  // namespace slidewave

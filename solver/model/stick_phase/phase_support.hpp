#pragma once
// What the phases stepped in wavenumbers (model/stick_phase/stick_phase_run.hpp, slip_phase_run.hpp) share
// with simulate()'s loop: the hooks by which simulate() times, paces and observes them, the loop's end
// condition, and the recorder's view of a state held in wavenumbers (the contact rows and the running sums:
// all that the rows of /global and /interface read).
#include <cstdint>
#include <functional>
#include <utility>

#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/run_observer.hpp"
#include "model/step_profile.hpp"

namespace slidewave {

/// What a phase asks of simulate() each step.
struct PhaseHooks {
  std::function<bool()> stop_requested;  ///< polled before each step: true ends the phase
  /// Ends a timed part of the step (StepProfile's free_solve, contact, correction, diagnostics).
  std::function<void(double StepProfile::*part)> lap;
  /// After each step's rows: `view` holds the step, the contact displacements, reactions and states and
  /// the running sums; `capture` gives the full state (checkpoints).
  std::function<void(const LoopState& view, int contact_sweeps, const RunObserver::Capture& capture)> after_step;
};

/// True where a run may step in wavenumbers at all: the layer on the rigid flat with the default linear solver
/// (`numerics.linear_solver = "cholmod"` is the oracle: every step plainly on CHOLMOD's factorization), unless
/// the model asks for plain steps (LayerModel::steps_in_wavenumbers, the tests' oracle).
bool may_step_in_wavenumbers(const LayerModel& m);

/// The step condition of simulate()'s loop: before n_steps_max and before loop.t_end.
bool before_end(std::int64_t step, std::int64_t n_steps_max, const LoopState& loop, double dt);

/// time.stop_after_opening: once the interface has opened at t, the run ends that long after.
void shorten_after_opening(const TimeConfig& time, double t, LoopState& loop);

/// The recorder's view of `loop`: its step, sums, recorder state, contact states, and of its dynamics the
/// contact displacements (dynamics.u, n_contact_dofs entries) and reactions.
LoopState contact_view(const LayerModel& m, const LoopState& loop);

/// The full state of a phase that holds the dynamics itself: `loop` (t_end, end reason, ...) with the phase's
/// reconstruct() and the recorder state `recording` (the view's).
template <class Phase>
LoopState full_state(const Phase& phase, const LoopState& loop, const RecorderState& recording) {
  LoopState full = loop;
  phase.reconstruct(full);
  full.recording = recording;
  return full;
}

/// At the end of a phase: `loop` becomes its full state (as full_state()).
template <class Phase>
void take_full_state(const Phase& phase, RecorderState recording, LoopState& loop) {
  phase.reconstruct(loop);
  loop.recording = std::move(recording);
}

/// The running sums a row reads (the energies booked so far; not F_top or the HHT vectors).
void copy_running_sums(const EnergySums& from, EnergySums& to);

}  // namespace slidewave

#pragma once
// The slip phase inside simulate() (docs/stick-phase.md, "The slip phase in wavenumbers"): after the stick
// phase (or from t = 0 where it does not apply), every step of the layer on the rigid flat is taken with its
// state in wavenumbers (model/stick_phase/wavenumber_slip_step.hpp) and recorded like a plain step, to the
// end of the run. The solution is the plain one to round-off.
//
// Where it applies: the rigid flat with the default linear solver (phase_support.hpp), any friction law,
// unless output.energy_decomposition = hht asks for the HHT terms of the ledger (booked by the plain step
// only). The substrate pair steps plainly.
//
// Checkpoints taken in the phase carry the lanes' state (WavenumberSlipStep::save), and a run resumed from
// one goes on from it: the uninterrupted run, bit for bit.
#include <cstdint>
#include <string>

#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/recorder.hpp"
#include "model/stick_phase/phase_support.hpp"
#include "model/stick_phase/wavenumber_slip_step.hpp"

namespace slidewave {

/// True where the phase applies (above).
bool slip_phase_applies(const LayerModel& m);

/// Runs the phase from the state `slip` holds (started from `loop`, or restored) to the end of the run, as
/// simulate()'s loop would: steps stop before n_steps_max and before loop.t_end (which stop_after_opening
/// may shorten), or when a stop is requested. On return `loop` is the full state after the last step (if
/// the phase stepped or was restored; else as it was). Returns "" or why the run stopped early
/// ("contact_not_converged", "interrupted").
std::string run_slip_phase(WavenumberSlipStep& slip, const LayerModel& m, std::int64_t n_steps_max, Recorder& recorder,
                           const PhaseHooks& hooks, LoopState& loop);

}  // namespace slidewave

#pragma once
// The stick phase inside simulate() (docs/stick-phase.md): from the seeded state at t = 0, while every
// contact node sticks, the steps are taken in wavenumbers (model/stick_phase/stick_phase.hpp) and recorded
// like plain steps; at the step on which a node would slip (or at t_end, or on a stop), the layer's full
// state is rebuilt and the slip phase (model/stick_phase/slip_phase_run.hpp) goes on from it. The solution
// is the plain one to round-off.
//
// Where it applies: the rigid flat with the default linear solver (phase_support.hpp), Coulomb friction
// without regularization (bounds that no state moves), every node sticking. The substrate pair steps
// plainly from t = 0; Prakash–Clifton goes into the slip phase from t = 0.
//
// A run resumed from a checkpoint taken inside the phase replays the phase from t = 0 without recording
// (cheap, and deterministic), and goes on in the phase only if the replay reaches the checkpoint's state
// bit for bit: then the resumed run is the uninterrupted one, bit for bit. Otherwise (a checkpoint after
// the phase, or from another build) the slip phase goes on from the checkpoint.
#include <cstdint>

#include "contact/friction_law.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/recorder.hpp"
#include "model/stick_phase/phase_support.hpp"
#include "model/stick_phase/wavenumber_blocks.hpp"

namespace slidewave {

/// True where the phase applies (above) to a run in state `loop`.
bool stick_phase_applies(const LayerModel& m, const LoopState& loop);

/// Runs the phase on the layer's blocks per wavenumber. `seeded`: the state at t = 0; `loop`: the state to go on from
/// (the seeded state, or a checkpoint's; it may be the same object), on return the full state after the phase's last
/// step. Steps stop before n_steps_max and before t_end as simulate()'s loop does.
void run_stick_phase(const LayerModel& m, const WavenumberBlocks& blocks, double u_x_top, const FrictionLaw& friction,
                     const LoopState& seeded, std::int64_t n_steps_max, Recorder& recorder, const PhaseHooks& hooks,
                     LoopState& loop);

}  // namespace slidewave

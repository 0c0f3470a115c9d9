#include "model/stick_phase/stick_phase_run.hpp"

#include <memory>

#include "model/loop_state_arrays.hpp"
#include "model/stick_phase/phase_support.hpp"
#include "model/stick_phase/stick_phase.hpp"

namespace slidewave {
namespace {

/// Replays the phase silently up to the checkpoint's step; true if it gets there with the checkpoint's
/// state bit for bit.
bool replay_to(StickPhase& stick, const FrictionBounds& bounds, const LoopState& checkpoint) {
  while (stick.step_count() < checkpoint.step)
    if (!stick.step(bounds)) return false;
  LoopState replayed = checkpoint;
  stick.reconstruct(replayed);
  const StateArrays a = to_arrays(replayed), b = to_arrays(checkpoint);
  return a.reals == b.reals && a.integers == b.integers;
}

}  // namespace

bool stick_phase_applies(const LayerModel& m, const LoopState& loop) {
  const FrictionConfig& f = m.config.friction;
  return may_step_in_wavenumbers(m) && f.f > 0 && f.regularization == Regularization::none && all_stuck(loop.contact);
}

void run_stick_phase(const LayerModel& m, const WavenumberBlocks& blocks, double u_x_top, const FrictionLaw& friction,
                     const LoopState& seeded, std::int64_t n_steps_max, Recorder& recorder, const PhaseHooks& hooks,
                     LoopState& loop) {
  StickPhase stick(m, blocks, u_x_top);
  stick.start(seeded);
  const std::unique_ptr<FrictionBounds> bounds = friction.bounds(loop.friction);
  if (loop.step > 0 && !replay_to(stick, *bounds, loop)) return;

  // The recorder reads the contact part of the state only: the view carries that.
  LoopState view = contact_view(m, loop);
  Eigen::VectorXd u_contact_previous = view.dynamics.u;
  const auto full = [&] { return full_state(stick, loop, view.recording); };
  const RunObserver::Capture capture = [&] { return to_arrays(full()); };
  const double dt = m.d.dt;
  while (before_end(stick.step_count(), n_steps_max, loop, dt) && !hooks.stop_requested()) {
    if (!stick.step(*bounds)) break;
    view.step = stick.step_count();
    view.dynamics.r = stick.reactions();
    copy_running_sums(stick.sums(), view.energy);
    u_contact_previous.swap(view.dynamics.u);
    view.dynamics.u = stick.contact_displacement();
    recorder.record_wavenumber_step(view, stick.kinetic(), stick.elastic(), u_contact_previous,
                                    GaussSeidelReport{0, 0.0, true}, full);
    hooks.after_step(view, 0, capture);
  }
  take_full_state(stick, view.recording, loop);
}

}  // namespace slidewave

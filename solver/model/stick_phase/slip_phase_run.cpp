#include "model/stick_phase/slip_phase_run.hpp"

#include "model/loop_state_arrays.hpp"

namespace slidewave {

bool slip_phase_applies(const LayerModel& m) {
  return may_step_in_wavenumbers(m) && !m.config.output.energy_decomposition;
}

std::string run_slip_phase(WavenumberSlipStep& slip, const LayerModel& m, std::int64_t n_steps_max, Recorder& recorder,
                           const PhaseHooks& hooks, LoopState& loop) {
  LoopState view = contact_view(m, loop);
  Eigen::VectorXd u_contact_previous = view.dynamics.u;
  const auto full = [&] { return full_state(slip, loop, view.recording); };
  const RunObserver::Capture capture = [&] {
    StateArrays arrays = to_arrays(full());
    slip.save(arrays);
    return arrays;
  };
  const double dt = m.d.dt;
  std::string failure;
  while (before_end(slip.step_count(), n_steps_max, loop, dt)) {
    if (hooks.stop_requested()) {
      failure = "interrupted";
      break;
    }
    slip.solve_free();
    hooks.lap(&StepProfile::free_solve);
    const GaussSeidelReport report = slip.solve_contact();
    if (!report.converged) {
      failure = "contact_not_converged";
      break;
    }
    hooks.lap(&StepProfile::contact);
    slip.correct();
    hooks.lap(&StepProfile::correction);
    view.step = slip.step_count();
    view.dynamics.r = slip.reactions();
    view.contact = slip.contact_states();
    copy_running_sums(slip.sums(), view.energy);
    u_contact_previous.swap(view.dynamics.u);
    view.dynamics.u = slip.contact_displacement();
    recorder.record_wavenumber_step(view, slip.kinetic(), slip.elastic(), u_contact_previous, report, full);
    if (recorder.detect_first_opening(view)) shorten_after_opening(m.config.time, view.step * dt, loop);
    hooks.lap(&StepProfile::diagnostics);
    hooks.after_step(view, report.iterations, capture);
  }
  if (slip.owns_state()) take_full_state(slip, view.recording, loop);
  return failure;
}

}  // namespace slidewave

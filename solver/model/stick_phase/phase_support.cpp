#include "model/stick_phase/phase_support.hpp"

namespace slidewave {

bool may_step_in_wavenumbers(const LayerModel& m) {
  return m.steps_in_wavenumbers && !m.substrate && m.config.numerics.linear_solver == LinearSolverKind::spectral;
}

bool before_end(std::int64_t step, std::int64_t n_steps_max, const LoopState& loop, double dt) {
  return step < n_steps_max && !(step * dt >= loop.t_end - 1e-9 * dt);
}

void shorten_after_opening(const TimeConfig& time, double t, LoopState& loop) {
  if (time.stop_after_opening && t + *time.stop_after_opening < loop.t_end) {
    loop.t_end = t + *time.stop_after_opening;
    loop.end_reason = "stop_after_opening";
  }
}

LoopState contact_view(const LayerModel& m, const LoopState& loop) {
  LoopState view;
  view.step = loop.step;
  view.t_end = loop.t_end;
  view.energy = loop.energy;
  view.recording = loop.recording;
  view.contact = loop.contact;
  view.dynamics.u = loop.dynamics.u.head(m.n_contact_dofs);
  view.dynamics.r = loop.dynamics.r;
  return view;
}

void copy_running_sums(const EnergySums& from, EnergySums& to) {
  to.work_external = from.work_external;
  to.dissipation_friction = from.dissipation_friction;
  to.work_contact_normal = from.work_contact_normal;
  to.hht.gamma = from.hht.gamma;
  to.hht.beta = from.hht.beta;
  to.hht.shift = from.hht.shift;
}

}  // namespace slidewave

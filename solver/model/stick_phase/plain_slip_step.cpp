#include "model/stick_phase/plain_slip_step.hpp"

#include "contact/delassus.hpp"
#include "model/loop_state_arrays.hpp"

namespace slidewave {

LoopState captured_loop_state(const LayerModel& m, const StateArrays& arrays) {
  LoopState loop;
  const int n = m.n_free + m.n_top, n_f = m.n_free;
  HHTState& s = loop.dynamics;
  for (Eigen::VectorXd* v : {&s.u, &s.v, &s.acc, &s.Ku}) v->resize(n);
  for (Eigen::VectorXd* v : {&s.Mu_f, &s.Mv_f, &s.Ma_f}) v->resize(n_f);
  s.r.resize(m.n_contact_dofs);
  loop.energy.F_top.resize(m.n_top);
  loop.recording.u_contact_start.resize(m.n_contact_dofs);
  if (m.config.output.energy_decomposition) {
    HhtDissipation& h = loop.energy.hht;
    for (Eigen::VectorXd* v : {&h.v_f, &h.acc_f, &h.Ma_f, &h.Ku_f, &h.shift_f}) v->resize(n_f);
  }
  loop.contact.resize(m.mesh.n_contact());
  loop.friction = make_friction_law(m.config.friction)->initial_state(Eigen::VectorXd::Zero(m.n_contact_dofs));
  restore_from_arrays(arrays, loop);
  return loop;
}

PlainSlipStep::PlainSlipStep(const LayerModel& m, double u_x_top)
    : m_(m),
      u_x_top_(u_x_top),
      hht_(m.config.time.hht_alpha, m.d.dt),
      system_(m.partitioned()),
      stepper_(system_, hht_, m.config.time.contact_weighting == ContactWeighting::alpha,
               m.factorize_split(effective_matrix(hht_, system_))),
      W_(stepper_.contact_weight() * delassus_operator_periodic(stepper_.K_eff(), m.n_contact_dofs / 2)),
      settings_{m.config.contact.tolerance, m.config.contact.max_iterations, m.d.p0 * m.d.h},
      friction_(make_friction_law(m.config.friction)),
      contact_(m.n_contact_dofs, W_, settings_) {}

Eigen::VectorXd PlainSlipStep::top_after(std::int64_t step) const {
  // simulate()'s top_after.
  return m_.top_displacement(u_x_top_ + m_.d.V0 * (step * hht_.dt), m_.config.loading.Uy_over_H * m_.d.H);
}

void PlainSlipStep::start(const LoopState& loop) {
  loop_ = loop;
  u_d_next_ = top_after(loop.step + 1);
}

void PlainSlipStep::solve_free() {
  stepper_.predict(loop_.dynamics, u_d_next_);
  u_free_ = &stepper_.solve_free();
}

GaussSeidelReport PlainSlipStep::solve_contact() {
  return contact_.solve(*u_free_, loop_.dynamics.u, loop_.dynamics.r, *friction_, loop_.friction, loop_.contact);
}

void PlainSlipStep::correct() {
  HHTState& s = loop_.dynamics;
  const int n_c = m_.n_contact_dofs;
  u_d_following_ = top_after(loop_.step + 2);
  stepper_.correct(contact_.r_next, s, &u_d_following_);
  u_d_next_.swap(u_d_following_);
  ++loop_.step;
  du_ = s.u.head(n_c) - stepper_.u_previous().head(n_c);
  friction_->update(du_, s.r, hht_.dt, loop_.friction);
}

GaussSeidelReport PlainSlipStep::step() {
  solve_free();
  const GaussSeidelReport report = solve_contact();
  correct();
  return report;
}

}  // namespace slidewave

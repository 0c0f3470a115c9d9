#include "model/stick_phase/stick_phase.hpp"

#include <cmath>

namespace slidewave {

StickPhase::StickPhase(const LayerModel& layer, const WavenumberBlocks& blocks, double u_x_top, double retire_tolerance)
    : layer_(layer),
      hht_(layer.config.time.hht_alpha, layer.d.dt),
      u_x_top_(u_x_top),
      blocks_(blocks),
      transform_(layer.mesh.n_x),
      // The transient factor of the retirement test is measured for the paper's hht_alpha = 0.1 (at a smaller
      // alpha the high frequencies decay slower and grow more before they do) and bounds sqrt(cond M) by 3, which
      // the consistent and the lumped mass keep and the redistributed one need not: elsewhere, no retirement.
      stepper_(blocks_, hht_, layer.config.time.contact_weighting == ContactWeighting::alpha,
               layer.config.time.hht_alpha == 0.1 && layer.config.mesh.mass != MassKind::redistributed
                   ? retire_tolerance
                   : 0.0),
      ledger_(blocks_, hht_, layer.d.V0) {}

Eigen::Vector2d StickPhase::top_after(std::int64_t step) const {
  // The formula of simulate()'s top_after, for one top node.
  return {u_x_top_ + layer_.d.V0 * (step * hht_.dt), layer_.config.loading.Uy_over_H * layer_.d.H};
}

void StickPhase::start(const LoopState& loop) {
  stepper_.start(loop.dynamics, loop.energy.hht.on() ? &loop.energy.hht.shift_f : nullptr, transform_);
  step_ = loop.step;
  sums_ = loop.energy;
  r_ = loop.dynamics.r;
  r_trial_ = r_;
  u_contact_ = loop.dynamics.u.head(layer_.n_contact_dofs);
  u_contact_held_.resize(u_contact_.size());
  du_contact_.resize(u_contact_.size());
  contact_held_ = false;
  F_top_ = ledger_.top_force(stepper_.current(), top_after(step_));
}

bool StickPhase::step(const FrictionBounds& bounds) {
  stepper_.step(top_after(step_ + 1));
  transform_.inverse(stepper_.next_reactions(), 1, r_trial_.data());
  for (Eigen::Index k = 0; k < r_trial_.size() / 2; ++k) {  // the test of AllStickSolution::solve
    const double r_x = r_trial_(2 * k), r_y = r_trial_(2 * k + 1);
    if (!(r_y >= 0 && std::fabs(r_x) <= bounds.bound(static_cast<int>(k), r_y))) return false;
  }
  // The contact rows are held: they move on the first step only (u_y from the preload's round-off to 0),
  // and stay the same bits after it, so their increment is transformed once.
  if (!contact_held_) {
    transform_.inverse(stepper_.next_displacement(), 1, u_contact_held_.data(), &stepper_.static_displacement());
    du_contact_ = u_contact_held_ - u_contact_;
  }
  stepper_.advance();
  const Eigen::Vector2d F_top_next = ledger_.top_force(stepper_.current(), top_after(step_ + 1));
  if (sums_.hht.on())
    ledger_.book_step(stepper_.previous(), stepper_.current(), stepper_.n_active(), top_after(step_),
                      top_after(step_ + 1), du_contact_, r_, r_trial_, sums_);
  else
    ledger_.book_work(F_top_, F_top_next, top_after(step_), top_after(step_ + 1), du_contact_, r_, r_trial_, sums_);
  stepper_.retire_settled();
  F_top_ = F_top_next;
  ++step_;
  r_ = r_trial_;
  if (!contact_held_) {
    u_contact_.swap(u_contact_held_);
    du_contact_.setZero();
    contact_held_ = true;
  }
  return true;
}

double StickPhase::kinetic() const {
  const ModeState& x = stepper_.current();
  const int n = stepper_.n_active();
  return x.v_M_v.empty() ? ledger_.kinetic(x, n) : ledger_.kinetic(x.v_M_v.data(), n, x.V);
}

double StickPhase::elastic() const {
  const ModeState& x = stepper_.current();
  const int n = stepper_.n_active();
  const double retired = stepper_.retired_elastic();
  return x.u_K_u.empty() ? ledger_.elastic(x, n, retired, top_after(step_))
                         : ledger_.elastic(x.u_K_u.data(), n, x.U, retired, top_after(step_));
}

void StickPhase::reconstruct(LoopState& loop) const {
  const int n_f = layer_.n_free, n_t = layer_.n_top, n_y = layer_.mesh.n_y;
  const ModeState& x = stepper_.current();
  HHTState& s = loop.dynamics;
  rebuild_dynamics(layer_, transform_, x, top_after(step_), s, &stepper_.static_displacement());
  s.r = r_;
  loop.energy = sums_;
  loop.energy.F_top = s.Ku.tail(n_t) + layer_.M_top_rows * s.acc;
  if (sums_.hht.on()) {
    HhtDissipation& h = loop.energy.hht;
    h.v_f = s.v.head(n_f);
    h.acc_f = s.acc.head(n_f);
    h.Ma_f = s.Ma_f;
    h.Ku_f = s.Ku.head(n_f);
    h.shift_f.resize(n_f);
    transform_.inverse(x.S, n_y, h.shift_f.data());
  }
  loop.contact.assign(layer_.mesh.n_contact(), ContactState::stick);
  loop.step = step_;
}

}  // namespace slidewave

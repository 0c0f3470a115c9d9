#include "model/stick_phase/wavenumber_slip_step.hpp"

#include <utility>

#include "linalg/vector_clones.hpp"

namespace slidewave {

WavenumberSlipStep::WavenumberSlipStep(const LayerModel& layer, double u_x_top, const Eigen::MatrixXd& W,
                                       const GaussSeidelSettings& settings, const FrictionLaw& law)
    : layer_(layer),
      hht_(layer.config.time.hht_alpha, layer.d.dt),
      u_x_top_(u_x_top),
      w_(layer.config.time.contact_weighting == ContactWeighting::alpha ? 1 - hht_.alpha : 1.0),
      w_previous_(layer.config.time.contact_weighting == ContactWeighting::alpha ? hht_.alpha : 0.0),
      law_(law),
      blocks_(layer),
      transform_(layer.mesh.n_x),
      A_eff_(effective_band(blocks_, hht_), 0),
      state_a_(blocks_.s, blocks_.lanes),
      state_b_(blocks_.s, blocks_.lanes),
      contact_(layer.n_contact_dofs, W, settings),
      u_free_contact_(layer.n_contact_dofs),
      u_contact_(layer.n_contact_dofs),
      u_contact_next_(layer.n_contact_dofs),
      r_(layer.n_contact_dofs),
      du_(layer.n_contact_dofs) {
  // The response of every lane to a unit load on its contact row c (real: a real symmetric A_eff,m and a real
  // load in the turned basis), scaled by w.
  const int s = blocks_.s, lanes = blocks_.lanes;
  for (int c = 0; c < 2; ++c) {
    LaneVectors unit(s, lanes);
    for (int m = 0; m < lanes; ++m) unit.re[unit.at(c, m)] = 1.0;
    A_eff_.solve(unit, lanes);
    std::vector<double>& G = c == 0 ? G0_ : G1_;
    G.resize(unit.re.size());
    for (std::size_t e = 0; e < G.size(); ++e) G[e] = w_ * unit.re[e];
  }
}

Eigen::Vector2d WavenumberSlipStep::top_after(std::int64_t step) const {
  // The formula of simulate()'s top_after, for one top node.
  return {u_x_top_ + layer_.d.V0 * (step * hht_.dt), layer_.config.loading.Uy_over_H * layer_.d.H};
}

void WavenumberSlipStep::start(const LoopState& loop) {
  const HHTState& layer = loop.dynamics;
  ModeState& x = state_a_;
  transform_.forward(layer.u.data(), x.U);
  transform_.forward(layer.v.data(), x.V);
  transform_.forward(layer.acc.data(), x.A);
  transform_.forward(layer.Ku.data(), x.KU);
  transform_.forward(layer.r.data(), x.R);
  transform_.forward(layer.Mu_f.data(), x.MU);
  transform_.forward(layer.Mv_f.data(), x.MV);
  transform_.forward(layer.Ma_f.data(), x.MA);
  state_b_ = state_a_;
  current_ = &state_a_;
  next_ = &state_b_;
  step_ = loop.step;
  contact_states_ = loop.contact;
  friction_ = loop.friction;
  u_contact_ = layer.u.head(layer_.n_contact_dofs);
  r_ = layer.r;
}

SLIDEWAVE_VECTOR_CLONES
void WavenumberSlipStep::solve_free() {
  const int s = blocks_.s, lanes = blocks_.lanes, n_x = blocks_.n_x;
  const double dt = hht_.dt, b = hht_.mass_factor(), c2 = dt * dt * (0.5 - hht_.beta), a = hht_.alpha;
  const double a_previous = w_previous_;
  const ModeState& x = *current_;
  ModeState& y = *next_;
  // b M u~ - a K u(n) (+ a' R(n) on the contact rows), M u~ = M u + dt M v + c M a.
  for (int r = 0; r < s; ++r)
    for (int part = 0; part < 2; ++part) {
      const std::size_t e = static_cast<std::size_t>(r) * lanes;
      const double* Mu = (part ? x.MU.im : x.MU.re).data() + e;
      const double* Mv = (part ? x.MV.im : x.MV.re).data() + e;
      const double* Ma = (part ? x.MA.im : x.MA.re).data() + e;
      const double* Ku = (part ? x.KU.im : x.KU.re).data() + e;
      double* __restrict rhs = (part ? y.U.im : y.U.re).data() + e;
      for (int m = 0; m < lanes; ++m) rhs[m] = b * (Mu[m] + dt * Mv[m] + c2 * Ma[m]) - a * Ku[m];
      if (r < 2) {
        const double* R = (part ? x.R.im : x.R.re).data() + e;
        for (int m = 0; m < lanes; ++m) rhs[m] += a_previous * R[m];
      }
    }
  u_top_next_ = top_after(step_ + 1);
  for (int r = 0; r < s; ++r)  // wavenumber 0: the top's share (1-a) K_fd u_d(n+1)
    add_to_lane_zero(y.U, r, -(1 - a) * n_x * blocks_.K_fd0.row(r).dot(u_top_next_));
  A_eff_.solve(y.U, lanes);
  transform_.inverse(y.U, 1, u_free_contact_.data());
}

GaussSeidelReport WavenumberSlipStep::solve_contact() {
  const GaussSeidelReport report =
      contact_.solve(u_free_contact_, u_contact_, r_, law_, friction_, contact_states_);
  transform_.forward(contact_.r_next.data(), next_->R);
  return report;
}

SLIDEWAVE_VECTOR_CLONES
void WavenumberSlipStep::correct() {
  const int s = blocks_.s, lanes = blocks_.lanes, n_x = blocks_.n_x;
  const double dt = hht_.dt, b = hht_.mass_factor(), c2 = dt * dt * (0.5 - hht_.beta), a = hht_.alpha;
  const double g = hht_.gamma, g_old = 1 - hht_.gamma, beta_dt2 = hht_.beta * dt * dt;
  const double w = w_, a_previous = w_previous_;
  const ModeState& x = *current_;
  ModeState& y = *next_;
  // U(n+1) = U_free + w (G_0 R_0 + G_1 R_1); u~ = u + dt v + c a, a(n+1) = b (u(n+1) - u~),
  // v += dt ((1-gamma) a + gamma a(n+1)).
  for (int r = 0; r < s; ++r)
    for (int part = 0; part < 2; ++part) {
      const std::size_t e = static_cast<std::size_t>(r) * lanes;
      const double* G0 = G0_.data() + e;
      const double* G1 = G1_.data() + e;
      const double* R0 = (part ? y.R.im : y.R.re).data();
      const double* R1 = R0 + lanes;
      const double* u = (part ? x.U.im : x.U.re).data() + e;
      const double* acc = (part ? x.A.im : x.A.re).data() + e;
      const double* v = (part ? x.V.im : x.V.re).data() + e;
      double* __restrict u_next = (part ? y.U.im : y.U.re).data() + e;
      double* __restrict acc_next = (part ? y.A.im : y.A.re).data() + e;
      double* __restrict v_next = (part ? y.V.im : y.V.re).data() + e;
      for (int m = 0; m < lanes; ++m) {
        u_next[m] += G0[m] * R0[m] + G1[m] * R1[m];
        const double u_tilde = u[m] + dt * v[m] + c2 * acc[m];
        acc_next[m] = b * (u_next[m] - u_tilde);
        v_next[m] = v[m] + dt * (g_old * acc[m] + g * acc_next[m]);
      }
    }
  blocks_.K.multiply(y.U, y.KU, 0, s, lanes);
  for (int r = 0; r < s; ++r) add_to_lane_zero(y.KU, r, n_x * blocks_.K_fd0.row(r).dot(u_top_next_));
  // M a(n+1) = -(1-a) K u(n+1) - a K u(n) + [contact rows] (w R(n+1) + a' R(n)) (K u with the top's share; the
  // top has a = 0); M v += dt ((1-gamma) M a + gamma M a(n+1)); M u = M u~ + beta dt^2 M a(n+1).
  for (int r = 0; r < s; ++r)
    for (int part = 0; part < 2; ++part) {
      const std::size_t e = static_cast<std::size_t>(r) * lanes;
      const double* Ku_next = (part ? y.KU.im : y.KU.re).data() + e;
      const double* Ku = (part ? x.KU.im : x.KU.re).data() + e;
      const double* Mu = (part ? x.MU.im : x.MU.re).data() + e;
      const double* Mv = (part ? x.MV.im : x.MV.re).data() + e;
      const double* Ma = (part ? x.MA.im : x.MA.re).data() + e;
      double* __restrict Ma_next = (part ? y.MA.im : y.MA.re).data() + e;
      double* __restrict Mv_next = (part ? y.MV.im : y.MV.re).data() + e;
      double* __restrict Mu_next = (part ? y.MU.im : y.MU.re).data() + e;
      for (int m = 0; m < lanes; ++m) Ma_next[m] = -(1 - a) * Ku_next[m] - a * Ku[m];
      if (r < 2) {
        const double* R_next = (part ? y.R.im : y.R.re).data() + e;
        const double* R = (part ? x.R.im : x.R.re).data() + e;
        for (int m = 0; m < lanes; ++m) Ma_next[m] += w * R_next[m] + a_previous * R[m];
      }
      for (int m = 0; m < lanes; ++m) {
        const double Mu_tilde = Mu[m] + dt * Mv[m] + c2 * Ma[m];
        Mv_next[m] = Mv[m] + dt * (g_old * Ma[m] + g * Ma_next[m]);
        Mu_next[m] = Mu_tilde + beta_dt2 * Ma_next[m];
      }
    }
  // The contact displacement in real space: the next contact problem's q, the friction law's increment.
  transform_.inverse(y.U, 1, u_contact_next_.data());
  du_ = u_contact_next_ - u_contact_;
  r_ = contact_.r_next;
  law_.update(du_, r_, dt, friction_);
  u_contact_.swap(u_contact_next_);
  std::swap(current_, next_);
  ++step_;
}

GaussSeidelReport WavenumberSlipStep::step() {
  solve_free();
  const GaussSeidelReport report = solve_contact();
  correct();
  return report;
}

void WavenumberSlipStep::reconstruct(LoopState& loop) const {
  HHTState& s = loop.dynamics;
  rebuild_dynamics(layer_, transform_, *current_, top_after(step_), s);
  s.r = r_;
  loop.contact = contact_states_;
  loop.friction = friction_;
  loop.step = step_;
}

}  // namespace slidewave

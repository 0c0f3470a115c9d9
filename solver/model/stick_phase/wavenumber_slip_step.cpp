#include "model/stick_phase/wavenumber_slip_step.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "contact/delassus.hpp"
#include "linalg/vector_clones.hpp"

namespace slidewave {

WavenumberSlipStep::WavenumberSlipStep(const LayerModel& layer, const WavenumberBlocks& blocks, double u_x_top,
                                       const GaussSeidelSettings& settings, const FrictionLaw& law)
    : layer_(layer),
      hht_(layer.config.time.hht_alpha, layer.d.dt),
      u_x_top_(u_x_top),
      w_(layer.config.time.contact_weighting == ContactWeighting::alpha ? 1 - hht_.alpha : 1.0),
      w_previous_(layer.config.time.contact_weighting == ContactWeighting::alpha ? hht_.alpha : 0.0),
      law_(law),
      blocks_(blocks),
      transform_(layer.mesh.n_x),
      A_eff_(effective_band(blocks_, hht_), 0),
      state_(blocks_.s, blocks_.lanes, false),
      U_next_(blocks_.s, blocks_.lanes),
      KU_next_(blocks_.s, blocks_.lanes),
      R_next_(2, blocks_.lanes),
      ledger_(blocks_, hht_, layer.d.V0),
      u_free_contact_(layer.n_contact_dofs),
      u_contact_(layer.n_contact_dofs),
      u_contact_next_(layer.n_contact_dofs),
      r_(layer.n_contact_dofs),
      du_(layer.n_contact_dofs),
      v_M_v_(blocks_.lanes),
      u_K_u_(blocks_.lanes) {
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
  // W = w C A_eff^-1 C^T from the same responses: a unit load on DOF b of contact node 0, transformed as the
  // correction transforms r, gives the contact displacement the correction would add.
  Eigen::VectorXd z[2];
  for (int b = 0; b < 2; ++b) {
    Eigen::VectorXd load = Eigen::VectorXd::Zero(layer.n_contact_dofs);
    load(b) = 1;
    LaneVectors R(2, lanes), U(2, lanes);
    transform_.forward(load.data(), R);
    for (int r = 0; r < 2; ++r)
      for (int m = 0; m < lanes; ++m) {
        const std::size_t e = U.at(r, m);
        U.re[e] = G0_[e] * R.re[R.at(0, m)] + G1_[e] * R.re[R.at(1, m)];
        U.im[e] = G0_[e] * R.im[R.at(0, m)] + G1_[e] * R.im[R.at(1, m)];
      }
    z[b].resize(layer.n_contact_dofs);
    transform_.inverse(U, 1, z[b].data());
  }
  W_ = delassus_from_node_responses(z[0], z[1], layer.mesh.n_contact());
  contact_ = std::make_unique<ContactStep>(layer.n_contact_dofs, W_, settings);
}

Eigen::Vector2d WavenumberSlipStep::top_after(std::int64_t step) const {
  // The formula of simulate()'s top_after, for one top node.
  return {u_x_top_ + layer_.d.V0 * (step * hht_.dt), layer_.config.loading.Uy_over_H * layer_.d.H};
}

void WavenumberSlipStep::start(const LoopState& loop) {
  transform_state(loop.dynamics, transform_, state_);
  adopt(loop, false);
}

void WavenumberSlipStep::adopt(const LoopState& loop, bool owns_state) {
  step_ = loop.step;
  contact_states_ = loop.contact;
  friction_ = loop.friction;
  r_ = loop.dynamics.r;
  sums_ = loop.energy;
  owns_state_ = owns_state;
  // The next free solve makes its right-hand side from the state, with the operations by which correct()
  // would have made it: the same bits.
  predicted_ = false;
  F_top_ = ledger_.top_force(state_, top_after(step_));
  kinetic_ = ledger_.kinetic(state_, blocks_.lanes);
  elastic_ = ledger_.elastic(state_, blocks_.lanes, 0.0, top_after(step_));
  transform_.inverse(state_.U, 1, u_contact_.data());
}

namespace {

/// The lanes' state in a checkpoint: its vectors by name (the same list writes and reads them).
template <typename State, typename F>
void for_each_lane_vector(State& x, F&& visit) {
  visit("U", x.U);
  visit("V", x.V);
  visit("A", x.A);
  visit("KU", x.KU);
  visit("MU", x.MU);
  visit("MV", x.MV);
  visit("MA", x.MA);
  visit("R", x.R);
}

const std::string kArrayPrefix = "wavenumber_slip_";

}  // namespace

void WavenumberSlipStep::save(StateArrays& arrays) const {
  for_each_lane_vector(state_, [&](const char* name, const LaneVectors& X) {
    arrays.reals[kArrayPrefix + name + "_re"] = X.re;
    arrays.reals[kArrayPrefix + name + "_im"] = X.im;
  });
}

bool WavenumberSlipStep::saved_in(const StateArrays& arrays) { return arrays.reals.count(kArrayPrefix + "U_re") > 0; }

void WavenumberSlipStep::restore(const LoopState& loop, const StateArrays& arrays) {
  for_each_lane_vector(state_, [&](const char* name, LaneVectors& X) {
    for (const char* part : {"_re", "_im"}) {
      const auto found = arrays.reals.find(kArrayPrefix + name + part);
      std::vector<double>& values = part[1] == 'r' ? X.re : X.im;
      if (found == arrays.reals.end() || found->second.size() != values.size())
        throw std::runtime_error("checkpoint: " + kArrayPrefix + name + part + " is missing or has another size");
      values = found->second;
    }
  });
  adopt(loop, true);
}

namespace {

/// The step's coefficients (time/hht.hpp; w, a' of the contact forces).
struct StepCoefficients {
  double dt, b, c2, a, g, g_old, beta_dt2, w, a_previous;
};

StepCoefficients step_coefficients(const HHTCoefficients& hht, double w, double a_previous) {
  const double dt = hht.dt;
  return {dt, hht.mass_factor(), dt * dt * (0.5 - hht.beta), hht.alpha, hht.gamma, 1 - hht.gamma, hht.beta * dt * dt,
          w,  a_previous};
}

/// Pointer to row r, part `part` (0: real, 1: imaginary) of a lane-vector.
inline double* row(LaneVectors& X, int r, int part) { return (part ? X.im : X.re).data() + X.at(r, 0); }
inline const double* row(const LaneVectors& X, int r, int part) { return (part ? X.im : X.re).data() + X.at(r, 0); }

/// Row r of the free solve's right-hand side, b M u~ - a K u(n) (+ a' R(n) on the contact rows),
/// M u~ = M u + dt M v + c M a, from the mass products, K u and R of time n (R null off the contact rows).
__attribute__((always_inline)) inline void free_rhs_row(const ModeState& x, const LaneVectors& KU, const LaneVectors* R,
                                                        int r, int lanes, const StepCoefficients k, LaneVectors& rhs) {
  for (int part = 0; part < 2; ++part) {
    const double* __restrict Mu = row(x.MU, r, part);
    const double* __restrict Mv = row(x.MV, r, part);
    const double* __restrict Ma = row(x.MA, r, part);
    const double* __restrict Ku = row(KU, r, part);
    double* __restrict out = row(rhs, r, part);
    for (int m = 0; m < lanes; ++m) out[m] = k.b * (Mu[m] + k.dt * Mv[m] + k.c2 * Ma[m]) - k.a * Ku[m];
    if (R) {
      const double* __restrict R_r = row(*R, r, part);
      for (int m = 0; m < lanes; ++m) out[m] += k.a_previous * R_r[m];
    }
  }
}

/// The lanes of one row and part of the correction U(n+1) = U_free + (G_0 R_0 + G_1 R_1) (w folded into G) and
/// the Newmark update in place: u~ = u + dt v + c a, a(n+1) = b (u(n+1) - u~), v += dt ((1-gamma) a + gamma a(n+1)).
/// Pointers and coefficients as parameters, so that the loop vectorizes.
__attribute__((always_inline)) inline void correct_lanes(const double* __restrict G0, const double* __restrict G1,
                                                         const double* __restrict R0, const double* __restrict R1,
                                                         const double* __restrict u, double* __restrict u_next,
                                                         double* __restrict acc, double* __restrict v, int lanes,
                                                         const StepCoefficients k) {
  for (int m = 0; m < lanes; ++m) {
    const double u_new = u_next[m] + (G0[m] * R0[m] + G1[m] * R1[m]);
    const double u_tilde = u[m] + k.dt * v[m] + k.c2 * acc[m];
    const double acc_new = k.b * (u_new - u_tilde);
    u_next[m] = u_new;
    v[m] = v[m] + k.dt * (k.g_old * acc[m] + k.g * acc_new);
    acc[m] = acc_new;
  }
}

/// The lanes of one row and part of the mass products, in place: M a(n+1) = -(1-a) K u(n+1) - a K u(n)
/// [+ w R(n+1) + a' R(n) on the contact rows: R_next, R non-null] (K u with the top's share; the top has a = 0);
/// M v += dt ((1-gamma) M a + gamma M a(n+1)); M u = M u~ + beta dt^2 M a(n+1).
__attribute__((always_inline)) inline void mass_lanes(const double* __restrict Ku_next, const double* __restrict Ku,
                                                      const double* __restrict R_next, const double* __restrict R,
                                                      double* __restrict Ma, double* __restrict Mv,
                                                      double* __restrict Mu, int lanes, const StepCoefficients k) {
  for (int m = 0; m < lanes; ++m) {
    double Ma_new = -(1 - k.a) * Ku_next[m] - k.a * Ku[m];
    if (R_next) Ma_new += k.w * R_next[m] + k.a_previous * R[m];
    const double Mu_tilde = Mu[m] + k.dt * Mv[m] + k.c2 * Ma[m];
    Mv[m] = Mv[m] + k.dt * (k.g_old * Ma[m] + k.g * Ma_new);
    Ma[m] = Ma_new;
    Mu[m] = Mu_tilde + k.beta_dt2 * Ma_new;
  }
}

/// The lanes of one row and part of the energies' forms, accumulated: v.M v and u.K u.
__attribute__((always_inline)) inline void energy_lanes(const double* __restrict v, const double* __restrict Mv,
                                                        const double* __restrict u, const double* __restrict Ku,
                                                        double* __restrict v_M_v, double* __restrict u_K_u, int lanes) {
  for (int m = 0; m < lanes; ++m) {
    v_M_v[m] += v[m] * Mv[m];
    u_K_u[m] += u[m] * Ku[m];
  }
}

}  // namespace

SLIDEWAVE_VECTOR_CLONES
void WavenumberSlipStep::solve_free() {
  const int s = blocks_.s, lanes = blocks_.lanes, n_x = blocks_.n_x;
  if (!predicted_) {  // else the last correct() made it
    const StepCoefficients k = step_coefficients(hht_, w_, w_previous_);
    for (int r = 0; r < s; ++r) free_rhs_row(state_, state_.KU, r < 2 ? &state_.R : nullptr, r, lanes, k, U_next_);
    u_top_next_ = top_after(step_ + 1);
    for (int r = 0; r < s; ++r)  // wavenumber 0: the top's share (1-a) K_fd u_d(n+1)
      add_to_lane_zero(U_next_, r, -(1 - hht_.alpha) * n_x * blocks_.K_fd0.row(r).dot(u_top_next_));
  }
  predicted_ = false;
  A_eff_.solve(U_next_, lanes);
  transform_.inverse(U_next_, 1, u_free_contact_.data());
}

GaussSeidelReport WavenumberSlipStep::solve_contact() {
  const GaussSeidelReport report = contact_->solve(u_free_contact_, u_contact_, r_, law_, friction_, contact_states_);
  transform_.forward(contact_->r_next.data(), R_next_);
  return report;
}

SLIDEWAVE_VECTOR_CLONES
void WavenumberSlipStep::correct() {
  const int s = blocks_.s, lanes = blocks_.lanes, n_x = blocks_.n_x, p = blocks_.K.p;
  const StepCoefficients k = step_coefficients(hht_, w_, w_previous_);
  ModeState& x = state_;
  const Eigen::Vector2d u_top_following = top_after(step_ + 2);
  std::fill(v_M_v_.begin(), v_M_v_.end(), 0.0);
  std::fill(u_K_u_.begin(), u_K_u_.end(), 0.0);
  // One sweep down the rows, so that the rows it works on stay in cache: row r corrected (U_next_ from U_free
  // to U(n+1); A, V in place), then row q = r - p, whose band reaches row r at most: K U(n+1) into KU_next_,
  // the mass products in place, and the next step's right-hand side into x.U (U(n) is not read after its
  // row's correction), with the top at u_d(n+2).
  for (int r = 0; r < s + p; ++r) {
    if (r < s)
      for (int part = 0; part < 2; ++part) {
        const double* R0 = row(R_next_, 0, part);
        correct_lanes(G0_.data() + x.U.at(r, 0), G1_.data() + x.U.at(r, 0), R0, R0 + lanes, row(x.U, r, part),
                      row(U_next_, r, part), row(x.A, r, part), row(x.V, r, part), lanes, k);
      }
    const int q = r - p;
    if (q < 0) continue;
    blocks_.K.multiply(U_next_, KU_next_, q, q + 1, lanes);
    add_to_lane_zero(KU_next_, q, n_x * blocks_.K_fd0.row(q).dot(u_top_next_));
    for (int part = 0; part < 2; ++part)
      mass_lanes(row(KU_next_, q, part), row(x.KU, q, part), q < 2 ? row(R_next_, q, part) : nullptr,
                 q < 2 ? row(x.R, q, part) : nullptr, row(x.MA, q, part), row(x.MV, q, part), row(x.MU, q, part), lanes,
                 k);
    for (int part = 0; part < 2; ++part)
      energy_lanes(row(x.V, q, part), row(x.MV, q, part), row(U_next_, q, part), row(KU_next_, q, part), v_M_v_.data(),
                   u_K_u_.data(), lanes);
    free_rhs_row(x, KU_next_, q < 2 ? &R_next_ : nullptr, q, lanes, k, x.U);
    add_to_lane_zero(x.U, q, -(1 - k.a) * n_x * blocks_.K_fd0.row(q).dot(u_top_following));
  }
  // The contact displacement in real space: the next contact problem's q, the friction law's increment.
  transform_.inverse(U_next_, 1, u_contact_next_.data());
  std::swap(x.U, U_next_);  // U_next_: the next free solve's right-hand side
  std::swap(x.KU, KU_next_);
  std::swap(x.R, R_next_);
  du_ = u_contact_next_ - u_contact_;
  kinetic_ = ledger_.kinetic(v_M_v_.data(), lanes, x.V);
  elastic_ = ledger_.elastic(u_K_u_.data(), lanes, x.U, 0.0, u_top_next_);
  const Eigen::Vector2d F_top_next = ledger_.top_force(x, u_top_next_);
  ledger_.book_work(F_top_, F_top_next, top_after(step_), u_top_next_, du_, r_, contact_->r_next, sums_);
  F_top_ = F_top_next;
  r_ = contact_->r_next;
  law_.update(du_, r_, k.dt, friction_);
  u_contact_.swap(u_contact_next_);
  u_top_next_ = u_top_following;
  predicted_ = true;
  owns_state_ = true;
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
  rebuild_dynamics(layer_, transform_, state_, top_after(step_), s);
  s.r = r_;
  loop.energy = sums_;
  loop.energy.F_top = s.Ku.tail(layer_.n_top) + layer_.M_top_rows * s.acc;
  loop.contact = contact_states_;
  loop.friction = friction_;
  loop.step = step_;
}

}  // namespace slidewave

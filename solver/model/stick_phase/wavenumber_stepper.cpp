#include "model/stick_phase/wavenumber_stepper.hpp"

#include <algorithm>
#include <cmath>
#include <complex>
#include <stdexcept>
#include <utility>

#include "linalg/vector_clones.hpp"

namespace slidewave {
namespace {

/// y(rows [r0, r1)) -= (A restricted to the columns 0, 1) x_c, all lanes: the load of the held contact DOFs.
void subtract_contact_columns(const BandedLanes& A, const LaneVectors& x_c, LaneVectors& y, int r0, int r1) {
  for (int r = r0; r < r1; ++r)
    for (int c = 0; c < 2; ++c) {
      const int k = c - r;
      if (std::abs(k) > A.p) continue;
      for (int m = 0; m < A.lanes; ++m) y.set(r, m, y.get(r, m) - A.get(r, k, m) * x_c.get(c, m));
    }
}

/// Largest std::abs (a hypot) over the rows [r0, r1) of lane m of a - b (b null: of a), bit for bit, with
/// one hypot per candidate instead of per row: the squared moduli re^2 + im^2 (within a few ulps of the
/// true ones) pick the rows within 1e-12 of the largest, and only those are measured with std::abs.
double max_distance(const LaneVectors& a, const LaneVectors* b, int m, int r0 = 0, int r1 = -1) {
  if (r1 < 0) r1 = a.rows;
  const auto z = [&](int r) { return a.get(r, m) - (b ? b->get(r, m) : 0.0); };
  double largest_squared = 0;
  for (int r = r0; r < r1; ++r) largest_squared = std::max(largest_squared, std::norm(z(r)));
  // Squares near underflow or overflow lose their precision: then every row is a candidate.
  const bool precise = largest_squared > 0x1p-900 && largest_squared < 0x1p900;
  const double candidate = precise ? largest_squared * (1 - 1e-12) : 0.0;
  double d = 0;
  for (int r = r0; r < r1; ++r)
    if (!(std::norm(z(r)) < candidate)) d = std::max(d, std::abs(z(r)));  // NaN: as std::max ignores it
  return d;
}

/// dt sqrt(lambda_min) of K_II x = lambda M_II x for lanes [0, m_end), by inverse iteration (the interior of K
/// factorized; each lane on its own).
std::vector<double> lowest_frequencies(const WavenumberBlocks& blocks, const BandedLaneFactor& K_interior, double dt,
                                       int m_end) {
  const int s = blocks.s, lanes = blocks.lanes;
  LaneVectors x(s, lanes), Mx(s, lanes), Kx(s, lanes);
  for (int r = 2; r < s; ++r)
    for (int m = 0; m < m_end; ++m) x.set(r, m, 1.0 + 0.1 * r);  // any start with a share of the lowest mode
  std::vector<double> lambda(m_end, 0.0);
  for (int iteration = 0; iteration < 60; ++iteration) {
    blocks.M.multiply(x, Mx, 0, s, m_end);
    for (int c = 0; c < 2; ++c)
      for (int m = 0; m < m_end; ++m) Mx.set(c, m, 0.0);
    K_interior.solve(Mx, m_end);  // x <- K_II^-1 M_II x, normalized
    for (int m = 0; m < m_end; ++m) {
      const double norm = max_distance(Mx, nullptr, m, 2, s);
      for (int r = 2; r < s; ++r) x.set(r, m, Mx.get(r, m) / norm);
    }
  }
  blocks.M.multiply(x, Mx, 0, s, m_end);
  blocks.K.multiply(x, Kx, 0, s, m_end);
  for (int m = 0; m < m_end; ++m) {
    double xKx = 0, xMx = 0;
    for (int r = 2; r < s; ++r) {
      xKx += (std::conj(x.get(r, m)) * Kx.get(r, m)).real();
      xMx += (std::conj(x.get(r, m)) * Mx.get(r, m)).real();
    }
    lambda[m] = dt * std::sqrt(xKx / xMx);
  }
  return lambda;
}

/// The transient growth factor of each lane's retirement test (docs/stick-phase.md, "Retirement"): HHT's
/// amplification of one frequency Omega = omega dt, in the units (u, dt v, beta dt^2 a), grows a start by at
/// most max(6.3, 1.65 / Omega) (measured over Omega, all powers), times 3 >= sqrt(cond M) from the modes to the
/// DOFs; Omega the lane's slowest frequency. Where that frequency is above 1.65 / 6.3 the factor is the floor
/// 3 x 6.3 whatever its value: a lane whose K_II - sigma M_II is positive definite (sigma at that frequency,
/// with a margin of 1e-9 for round-off) has it there by Sylvester's law of inertia, one band factorization
/// instead of the inverse iteration, which runs on the lanes below the highest uncertified one only.
std::vector<double> transient_factors(const WavenumberBlocks& blocks, const BandedLaneFactor& K_interior, double dt) {
  constexpr double floor_growth = 6.3, low_frequency_growth = 1.65;
  const double omega_floor = low_frequency_growth / floor_growth * (1 + 1e-9), sigma = std::pow(omega_floor / dt, 2);
  const std::vector<bool> above_floor = positive_definite_lanes(mass_stiffness_band(blocks, -sigma, 1.0), 2);
  int m_end = blocks.lanes;
  while (m_end > 0 && above_floor[m_end - 1]) --m_end;
  const std::vector<double> omega = lowest_frequencies(blocks, K_interior, dt, m_end);
  std::vector<double> factor(blocks.lanes, 3 * floor_growth);
  for (int m = 0; m < m_end; ++m) factor[m] = 3 * std::max(floor_growth, low_frequency_growth / omega[m]);
  return factor;
}

}  // namespace

WavenumberStepper::WavenumberStepper(const WavenumberBlocks& blocks, const HHTCoefficients& hht, bool alpha_weighted,
                                     double retire_tolerance)
    : blocks_(blocks),
      hht_(hht),
      w_(alpha_weighted ? 1 - hht.alpha : 1.0),
      w_previous_(alpha_weighted ? hht.alpha : 0.0),
      retire_tolerance_(retire_tolerance),
      A_eff_interior_(effective_band(blocks, hht), 2),
      K_interior_(blocks.K, 2),
      state_(blocks.s, blocks.lanes),
      previous_(0, 0),
      U_next_(blocks.s, blocks.lanes),
      KU_next_(blocks.s, blocks.lanes),
      R_next_(2, blocks.lanes),
      A_contact_(std::min(blocks.s, 2 + blocks.M.p), blocks.lanes),
      MA_contact_(2, blocks.lanes),
      hold_load_(blocks.s, blocks.lanes),
      U_static_(blocks.s, blocks.lanes),
      KU_static_(blocks.s, blocks.lanes),
      MU_static_(blocks.s, blocks.lanes) {
  transient_factor_ = transient_factors(blocks, K_interior_, hht.dt);
}

void WavenumberStepper::start(const HHTState& layer, const Eigen::VectorXd* shift_f, const RowTransform& transform) {
  if (K_narrow_.lanes > 0) throw std::logic_error("WavenumberStepper::start: its arrays have narrowed (start once)");
  const int s = blocks_.s, lanes = blocks_.lanes;
  ModeState& x = state_;
  transform_state(layer, transform, x);
  x.v_M_v.clear();  // not made by a step
  x.u_K_u.clear();
  track_shift_ = shift_f != nullptr;
  rhs_ready_ = false;
  if (track_shift_) transform.forward(shift_f->data(), x.S);
  // The held contact DOFs: u_x as at the start, u_y = 0 (what the all-stick solution imposes).
  hold_ = LaneVectors(2, lanes);
  for (int m = 0; m < lanes; ++m) hold_.set(0, m, x.U.get(0, m));
  hold_load_ = LaneVectors(s, lanes);
  subtract_contact_columns(effective_band(blocks_, hht_), hold_, hold_load_, 2, s);  // -(b M_Ic + (1-a) K_Ic) U_c
  // Static states: K_II U*_I = -K_Ic U_c, U*_c = U_c.
  U_static_ = LaneVectors(s, lanes);
  subtract_contact_columns(blocks_.K, hold_, U_static_, 2, s);
  K_interior_.solve(U_static_, lanes);
  for (int c = 0; c < 2; ++c)
    for (int m = 0; m < lanes; ++m) U_static_.set(c, m, hold_.get(c, m));
  blocks_.K.multiply(U_static_, KU_static_, 0, s, lanes);
  blocks_.M.multiply(U_static_, MU_static_, 0, s, lanes);
  n_active_ = lanes;
  width_ = lanes;
  retired_elastic_ = 0;
  u_scale_ = layer.u.head(2 * (s / 2) * blocks_.n_x).lpNorm<Eigen::Infinity>();
  r_scale_ = layer.r.lpNorm<Eigen::Infinity>();
}

__attribute__((always_inline)) inline void WavenumberStepper::interior_rhs_row(const ModeState& x,
                                                                               const LaneVectors& KU, int r,
                                                                               LaneVectors& rhs_out) const {
  const int me = n_active_, lanes = width_;
  const double dt = hht_.dt, b = hht_.mass_factor(), c2 = dt * dt * (0.5 - hht_.beta), a = hht_.alpha;
  for (int part = 0; part < 2; ++part) {
    const std::size_t e = static_cast<std::size_t>(r) * lanes;
    const double* Mu = (part ? x.MU.im : x.MU.re).data() + e;
    const double* Mv = (part ? x.MV.im : x.MV.re).data() + e;
    const double* Ma = (part ? x.MA.im : x.MA.re).data() + e;
    const double* Ku = (part ? KU.im : KU.re).data() + e;
    double* __restrict rhs = (part ? rhs_out.im : rhs_out.re).data() + e;
    for (int m = 0; m < me; ++m) rhs[m] = b * (Mu[m] + dt * Mv[m] + c2 * Ma[m]) - a * Ku[m];
    if (r < 2 + K().p) {  // the held contact DOFs load the rows within the band of them
      const double* load = (part ? hold_load_.im : hold_load_.re).data() + e;
      for (int m = 0; m < me; ++m) rhs[m] += load[m];
    }
  }
}

SLIDEWAVE_VECTOR_CLONES
void WavenumberStepper::step(const Eigen::Vector2d& u_top_next) {
  // lanes: the row length of every array but R (whose rows hold every lane: r_lanes).
  const int s = blocks_.s, me = n_active_, n_x = blocks_.n_x, lanes = width_, r_lanes = state_.R.lanes;
  const double dt = hht_.dt, b = hht_.mass_factor(), c2 = dt * dt * (0.5 - hht_.beta), a = hht_.alpha;
  const ModeState& x = state_;
  // The interior right-hand side b M u~ - a K u(n) + the held contact's load, M u~ = M u + dt M v + c M a:
  // made by the last advance() while each row was in cache (interior_rhs_row), else here.
  if (!rhs_ready_)
    for (int r = 2; r < s; ++r) interior_rhs_row(x, x.KU, r, U_next_);
  rhs_ready_ = false;
  for (int r = 2; r < s; ++r)  // wavenumber 0: the top's share (1-a) K_fd u_d(n+1)
    add_to_lane_zero(U_next_, r, -(1 - a) * n_x * blocks_.K_fd0.row(r).dot(u_top_next));
  A_eff_interior_.solve(U_next_, me);
  for (int c = 0; c < 2; ++c) {
    std::copy_n(hold_.re.data() + hold_.at(c, 0), me, U_next_.re.data() + U_next_.at(c, 0));
    std::copy_n(hold_.im.data() + hold_.at(c, 0), me, U_next_.im.data() + U_next_.at(c, 0));
  }
  u_top_next_ = u_top_next;
  // a(n+1) = b (u(n+1) - u~) of the rows that the contact rows' mass band reaches (advance() makes the same
  // numbers on every row), K u(n+1) of the contact rows.
  for (int r = 0; r < A_contact_.rows; ++r)
    for (int part = 0; part < 2; ++part) {
      const std::size_t e = static_cast<std::size_t>(r) * lanes;
      const double* u_next = (part ? U_next_.im : U_next_.re).data() + e;
      const double* u = (part ? x.U.im : x.U.re).data() + e;
      const double* acc = (part ? x.A.im : x.A.re).data() + e;
      const double* v = (part ? x.V.im : x.V.re).data() + e;
      double* __restrict acc_next = (part ? A_contact_.im : A_contact_.re).data() + e;
      for (int m = 0; m < me; ++m) {
        const double u_tilde = u[m] + dt * v[m] + c2 * acc[m];
        acc_next[m] = b * (u_next[m] - u_tilde);
      }
    }
  K().multiply(U_next_, KU_next_, 0, 2, me);
  for (int r = 0; r < 2; ++r) add_to_lane_zero(KU_next_, r, n_x * blocks_.K_fd0.row(r).dot(u_top_next));
  // Reactions from the contact rows of the equation of motion.
  M().multiply(A_contact_, MA_contact_, 0, 2, me);
  for (int c = 0; c < 2; ++c)
    for (int part = 0; part < 2; ++part) {
      const std::size_t e = static_cast<std::size_t>(c) * lanes, e_r = static_cast<std::size_t>(c) * r_lanes;
      const double* Ma_c = (part ? MA_contact_.im : MA_contact_.re).data() + e;
      const double* Ku_next = (part ? KU_next_.im : KU_next_.re).data() + e;
      const double* Ku = (part ? x.KU.im : x.KU.re).data() + e;
      const double* R = (part ? x.R.im : x.R.re).data() + e_r;
      double* __restrict R_next = (part ? R_next_.im : R_next_.re).data() + e_r;
      for (int m = 0; m < me; ++m) R_next[m] = (Ma_c[m] + (1 - a) * Ku_next[m] + a * Ku[m] - w_previous_ * R[m]) / w_;
    }
}

SLIDEWAVE_VECTOR_CLONES
void WavenumberStepper::advance() {
  if (track_shift_) previous_ = state_;  // the ledger's HHT terms are forms of both states
  const int s = blocks_.s, me = n_active_, n_x = blocks_.n_x, lanes = width_, r_lanes = state_.R.lanes;
  const double dt = hht_.dt, b = hht_.mass_factor(), c2 = dt * dt * (0.5 - hht_.beta), a = hht_.alpha;
  const double g = hht_.gamma, g_old = 1 - hht_.gamma, beta_dt2 = hht_.beta * dt * dt;
  ModeState& x = state_;
  x.v_M_v.assign(lanes, 0.0);
  x.u_K_u.assign(lanes, 0.0);
  double* __restrict v_M_v = x.v_M_v.data();
  double* __restrict u_K_u = x.u_K_u.data();
  // Row by row, in place (u(n+1) is whole: K u(n+1) of a row needs its neighbours').
  for (int r = 0; r < s; ++r) {
    // u~ = u + dt v + c a,  a(n+1) = b (u(n+1) - u~),  v += dt ((1-gamma) a + gamma a(n+1)).
    for (int part = 0; part < 2; ++part) {
      const std::size_t e = static_cast<std::size_t>(r) * lanes;
      const double* u_next = (part ? U_next_.im : U_next_.re).data() + e;
      const double* u = (part ? x.U.im : x.U.re).data() + e;
      double* __restrict acc = (part ? x.A.im : x.A.re).data() + e;
      double* __restrict v = (part ? x.V.im : x.V.re).data() + e;
      for (int m = 0; m < me; ++m) {
        const double u_tilde = u[m] + dt * v[m] + c2 * acc[m];
        const double acc_next = b * (u_next[m] - u_tilde);
        v[m] = v[m] + dt * (g_old * acc[m] + g * acc_next);
        acc[m] = acc_next;
      }
    }
    if (r >= 2) {  // (step() made the contact rows')
      K().multiply(U_next_, KU_next_, r, r + 1, me);
      add_to_lane_zero(KU_next_, r, n_x * blocks_.K_fd0.row(r).dot(u_top_next_));
    }
    // The mass products: M a(n+1) of the interior rows from their equation of motion, -(1-a) K u(n+1) - a K u(n)
    // (K u with the top's share; the top has a = 0), of the contact rows the band product the reactions came
    // from; M v += dt ((1-gamma) M a + gamma M a(n+1)); M u = M u~ + beta dt^2 M a(n+1).
    for (int part = 0; part < 2; ++part) {
      const std::size_t e = static_cast<std::size_t>(r) * lanes;
      const double* Ku_next = (part ? KU_next_.im : KU_next_.re).data() + e;
      const double* Ku = (part ? x.KU.im : x.KU.re).data() + e;
      const double* Ma_contact = r < 2 ? (part ? MA_contact_.im : MA_contact_.re).data() + e : nullptr;
      double* __restrict Mu = (part ? x.MU.im : x.MU.re).data() + e;
      double* __restrict Mv = (part ? x.MV.im : x.MV.re).data() + e;
      double* __restrict Ma = (part ? x.MA.im : x.MA.re).data() + e;
      for (int m = 0; m < me; ++m) {
        const double Ma_next = Ma_contact ? Ma_contact[m] : -(1 - a) * Ku_next[m] - a * Ku[m];
        const double Mu_tilde = Mu[m] + dt * Mv[m] + c2 * Ma[m];
        Mv[m] = Mv[m] + dt * (g_old * Ma[m] + g * Ma_next);
        Mu[m] = Mu_tilde + beta_dt2 * Ma_next;
        Ma[m] = Ma_next;
      }
      // The energies' forms (the recorder reads them every step).
      const double* v_next = (part ? x.V.im : x.V.re).data() + e;
      const double* u_next = (part ? U_next_.im : U_next_.re).data() + e;
      for (int m = 0; m < me; ++m) {
        v_M_v[m] += v_next[m] * Mv[m];
        u_K_u[m] += u_next[m] * Ku_next[m];
      }
    }
    if (track_shift_)  // s(n+1) = a (K u(n+1) - K u(n)) - a' C^T (r(n+1) - r(n)).
      for (int part = 0; part < 2; ++part) {
        const std::size_t e = static_cast<std::size_t>(r) * lanes;
        const double* Ku_next = (part ? KU_next_.im : KU_next_.re).data() + e;
        const double* Ku = (part ? x.KU.im : x.KU.re).data() + e;
        double* __restrict shift = (part ? x.S.im : x.S.re).data() + e;
        for (int m = 0; m < me; ++m) shift[m] = a * (Ku_next[m] - Ku[m]);
        if (r < 2) {
          const std::size_t e_r = static_cast<std::size_t>(r) * r_lanes;
          const double* R = (part ? x.R.im : x.R.re).data() + e_r;
          const double* R_next = (part ? R_next_.im : R_next_.re).data() + e_r;
          for (int m = 0; m < me; ++m) shift[m] -= w_previous_ * (R_next[m] - R[m]);
        }
      }
    // The next step's right-hand side of the row, from its new mass products and K u, into u(n)'s place (not read
    // again: K u(n+1) reads u(n+1)), which the swap below makes U_next_.
    if (r >= 2) interior_rhs_row(x, KU_next_, r, x.U);
  }
  rhs_ready_ = true;
  std::swap(x.U, U_next_);
  std::swap(x.KU, KU_next_);
  std::swap(x.R, R_next_);
}

void WavenumberStepper::retire_settled() {
  while (retire_tolerance_ > 0 && n_active_ > 1 && may_retire(n_active_ - 1)) {
    retire(n_active_ - 1);
    --n_active_;
  }
  narrow_to_active();
}

void WavenumberStepper::narrow_to_active() {
  constexpr int kLine = 8;  // doubles per 64-byte cache line
  const int width = std::min(blocks_.lanes, (n_active_ + kLine - 1) / kLine * kLine);
  if (width > width_ - kLine) return;  // not a whole line of each row to gain
  for (LaneVectors* v : {&state_.U, &state_.V, &state_.A, &state_.KU, &state_.MU, &state_.MV, &state_.MA, &state_.S,
                         &U_next_, &KU_next_, &A_contact_, &MA_contact_, &hold_load_})
    v->narrow(width);
  A_eff_interior_.narrow(width);
  if (K_narrow_.lanes == 0) {
    K_narrow_ = blocks_.K.first_lanes(width);
    // The step multiplies M by a on the contact rows 0, 1 only (their band reaches row 1 + p).
    M_narrow_ = blocks_.M.first_lanes(width, std::min(blocks_.M.rows, 2 + blocks_.M.p));
  } else {
    K_narrow_.narrow(width);
    M_narrow_.narrow(width);
  }
  width_ = width;
}

bool WavenumberStepper::may_retire(int m) const {
  const ModeState& x = state_;
  const double dt = hht_.dt;
  const double distance = std::max({max_distance(x.U, &U_static_, m), dt * max_distance(x.V, nullptr, m),
                                    hht_.beta * dt * dt * max_distance(x.A, nullptr, m)});
  double reaction_distance = 0;
  for (int c = 0; c < 2; ++c)
    reaction_distance = std::max(reaction_distance, std::abs(x.R.get(c, m) - KU_static_.get(c, m)));
  // Lane m adds at most weight(m) |X_m| to an entry of the layer's vector (the inverse DFT).
  const double share = transient_factor_[m] * blocks_.weight[m];
  return share * distance <= retire_tolerance_ * u_scale_ && share * reaction_distance <= retire_tolerance_ * r_scale_;
}

void WavenumberStepper::retire(int m) {
  // The buffers that advance() swaps with U, K u and R too: the step no longer writes lane m of either.
  ModeState& x = state_;
  for (int r = 0; r < blocks_.s; ++r) {
    for (LaneVectors* u : {&x.U, &U_next_}) u->set(r, m, U_static_.get(r, m));
    for (LaneVectors* ku : {&x.KU, &KU_next_}) ku->set(r, m, KU_static_.get(r, m));
    x.MU.set(r, m, MU_static_.get(r, m));
    for (LaneVectors* zero : {&x.V, &x.A, &x.S, &x.MV, &x.MA}) zero->set(r, m, 0.0);
  }
  for (int c = 0; c < 2; ++c)
    for (LaneVectors* reaction : {&x.R, &R_next_}) reaction->set(c, m, KU_static_.get(c, m));
  double elastic = 0;
  for (int r = 0; r < blocks_.s; ++r) elastic += (std::conj(U_static_.get(r, m)) * KU_static_.get(r, m)).real();
  retired_elastic_ += 0.5 * blocks_.weight[m] * elastic;
}

void transform_state(const HHTState& layer, const RowTransform& transform, ModeState& x) {
  transform.forward(layer.u.data(), x.U);
  transform.forward(layer.v.data(), x.V);
  transform.forward(layer.acc.data(), x.A);
  transform.forward(layer.Ku.data(), x.KU);
  transform.forward(layer.r.data(), x.R);
  transform.forward(layer.Mu_f.data(), x.MU);
  transform.forward(layer.Mv_f.data(), x.MV);
  transform.forward(layer.Ma_f.data(), x.MA);
}

void rebuild_dynamics(const LayerModel& layer, const RowTransform& transform, const ModeState& x,
                      const Eigen::Vector2d& u_top, HHTState& s, const LaneVectors* U_beyond) {
  const int n_f = layer.n_free, n_t = layer.n_top, n_y = layer.mesh.n_y;
  s.u.resize(n_f + n_t);
  transform.inverse(x.U, n_y, s.u.data(), U_beyond);
  s.u.tail(n_t) = layer.top_displacement(u_top.x(), u_top.y());
  s.v = Eigen::VectorXd::Zero(n_f + n_t);
  transform.inverse(x.V, n_y, s.v.data());
  for (int k = n_f; k < n_f + n_t; k += 2) s.v(k) = layer.d.V0;
  s.acc = Eigen::VectorXd::Zero(n_f + n_t);
  transform.inverse(x.A, n_y, s.acc.data());
  s.Ku = layer.stiffness_product(s.u);
  s.Mu_f = layer.free_mass_product(s.u.head(n_f));
  s.Mv_f = layer.free_mass_product(s.v.head(n_f));
  s.Ma_f = layer.free_mass_product(s.acc.head(n_f));
}

}  // namespace slidewave

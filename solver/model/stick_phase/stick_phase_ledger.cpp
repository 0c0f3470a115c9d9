#include "model/stick_phase/stick_phase_ledger.hpp"

namespace slidewave {
namespace {

/// Lane 0 of rows 0..s-1 (real: the column sums of the layer's vector).
Eigen::VectorXd lane_zero(const LaneVectors& X) {
  Eigen::VectorXd x(X.rows);
  for (int r = 0; r < X.rows; ++r) x(r) = lane_zero_value(X, r);
  return x;
}

/// x + c y on lanes [0, n).
LaneVectors combine(const LaneVectors& x, const LaneVectors& y, double c, int n) {
  LaneVectors z(x.rows, x.lanes);
  for (int r = 0; r < x.rows; ++r)
    for (int m = 0; m < n; ++m) {
      const std::size_t e = x.at(r, m);
      z.re[e] = x.re[e] + c * y.re[e];
      z.im[e] = x.im[e] + c * y.im[e];
    }
  return z;
}

}  // namespace

StickPhaseLedger::StickPhaseLedger(const WavenumberBlocks& blocks, const HHTCoefficients& hht, double V0)
    : blocks_(blocks), hht_(hht) {
  const Eigen::Vector2d v_top(V0, 0);
  M_fd_v_top_ = blocks.M_fd0 * v_top;
  kinetic_top_ = blocks.n_x * v_top.dot(blocks.M_dd0 * v_top);
}

double StickPhaseLedger::dot(const LaneVectors& X, const LaneVectors* X2, double cx, const LaneVectors& Y,
                             const LaneVectors* Y2, double cy, int n) const {
  const double* w = blocks_.weight.data();
  double sum = 0;
  for (int r = 0; r < X.rows; ++r) {
    const std::size_t e = X.at(r, 0);
    const double *x_re = X.re.data() + e, *x_im = X.im.data() + e, *y_re = Y.re.data() + e, *y_im = Y.im.data() + e;
    const double* x2_re = X2 ? X2->re.data() + e : nullptr;
    const double* x2_im = X2 ? X2->im.data() + e : nullptr;
    const double* y2_re = Y2 ? Y2->re.data() + e : nullptr;
    const double* y2_im = Y2 ? Y2->im.data() + e : nullptr;
    for (int m = 0; m < n; ++m) {
      const double a_re = X2 ? x_re[m] + cx * x2_re[m] : x_re[m], a_im = X2 ? x_im[m] + cx * x2_im[m] : x_im[m];
      const double b_re = Y2 ? y_re[m] + cy * y2_re[m] : y_re[m], b_im = Y2 ? y_im[m] + cy * y2_im[m] : y_im[m];
      sum += w[m] * (a_re * b_re + a_im * b_im);
    }
  }
  return sum;
}

double StickPhaseLedger::kinetic(const ModeState& x, int n_active) const {
  return 0.5 * (blocks_.M.bilinear(x.V, x.V, n_active, blocks_.weight.data()) + 2 * M_fd_v_top_.dot(lane_zero(x.V)) +
                kinetic_top_);
}

double StickPhaseLedger::elastic(const ModeState& x, int n_active, double retired_elastic,
                                 const Eigen::Vector2d& u_top) const {
  const Eigen::Vector2d top = blocks_.K_fd0.transpose() * lane_zero(x.U) + blocks_.n_x * (blocks_.K_dd0 * u_top);
  return 0.5 * (dot(x.U, nullptr, 0, x.KU, nullptr, 0, n_active) + u_top.dot(top)) + retired_elastic;
}

Eigen::Vector2d StickPhaseLedger::top_force(const ModeState& x, const Eigen::Vector2d& u_top) const {
  return blocks_.K_fd0.transpose() * lane_zero(x.U) + blocks_.n_x * (blocks_.K_dd0 * u_top) +
         blocks_.M_fd0.transpose() * lane_zero(x.A);
}

void StickPhaseLedger::book_step(const ModeState& before, const ModeState& after, int n_active,
                                 const Eigen::Vector2d& u_top_before, const Eigen::Vector2d& u_top_after,
                                 const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r_before,
                                 const Eigen::VectorXd& r_after, EnergySums& sums) const {
  for (Eigen::Index k = 0; k < du_contact.size() / 2; ++k) {
    sums.dissipation_friction -= 0.5 * (r_before(2 * k) + r_after(2 * k)) * du_contact(2 * k);
    sums.work_contact_normal -= 0.5 * (r_before(2 * k + 1) + r_after(2 * k + 1)) * du_contact(2 * k + 1);
  }
  sums.work_external +=
      0.5 * (top_force(before, u_top_before) + top_force(after, u_top_after)).dot(u_top_after - u_top_before);
  if (!sums.hht.on()) return;
  // The three HHT terms of EnergyLedger::book_hht_terms, each a quadratic form of the two states.
  const double dt = hht_.dt;
  const LaneVectors v_sum = combine(before.V, after.V, 1, n_active),
                    a_change = combine(after.A, before.A, -1, n_active),
                    a_sum = combine(before.A, after.A, 1, n_active);
  const double* w = blocks_.weight.data();
  const double v_M_da = 0.5 * blocks_.M.bilinear(v_sum, a_change, n_active, w) +
                        M_fd_v_top_.dot(lane_zero(after.A) - lane_zero(before.A));
  const double da_M_a = 0.5 * blocks_.M.bilinear(a_change, a_sum, n_active, w);
  const double du_s = 0.5 * dot(after.U, &before.U, -1, before.S, &after.S, 1, n_active);
  sums.hht.gamma -= dt * (hht_.gamma - 0.5) * v_M_da;
  sums.hht.beta += dt * dt * (hht_.beta - 0.5 * hht_.gamma) * da_M_a;
  sums.hht.shift -= du_s;
}

}  // namespace slidewave

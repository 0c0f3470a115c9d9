#include "model/stick_phase/stick_phase_ledger.hpp"

#include <array>

#include "linalg/vector_clones.hpp"

namespace slidewave {
namespace {

/// Lane 0 of rows 0..s-1 (real: the column sums of the layer's vector).
Eigen::VectorXd lane_zero(const LaneVectors& X) {
  Eigen::VectorXd x(X.rows);
  for (int r = 0; r < X.rows; ++r) x(r) = lane_zero_value(X, r);
  return x;
}

}  // namespace

StickPhaseLedger::StickPhaseLedger(const WavenumberBlocks& blocks, const HHTCoefficients& hht, double V0)
    : blocks_(blocks), hht_(hht) {
  const Eigen::Vector2d v_top(V0, 0);
  M_fd_v_top_ = blocks.M_fd0 * v_top;
  kinetic_top_ = blocks.n_x * v_top.dot(blocks.M_dd0 * v_top);
}

double StickPhaseLedger::dot(const LaneVectors& X, const LaneVectors& Y, int n) const {
  double sums[1];
  const std::array<LaneProduct, 1> product{{{&X, nullptr, 1, &Y, nullptr, 1}}};
  lane_products(product.data(), 1, n, sums);
  return sums[0];
}

SLIDEWAVE_VECTOR_CLONES
void StickPhaseLedger::lane_products(const LaneProduct* products, int count, int n, double* sums) const {
  // Per-lane partial sums (independent, so the loop over the lanes vectorizes), weighted at the end.
  per_lane_.assign(static_cast<std::size_t>(count) * n, 0.0);
  for (int q = 0; q < count; ++q) {
    const LaneProduct& p = products[q];
    double* __restrict sum = per_lane_.data() + static_cast<std::size_t>(q) * n;
    for (int r = 0; r < p.X->rows; ++r)
      for (int part = 0; part < 2; ++part) {
        const std::size_t e = p.X->at(r, 0);
        const auto row = [part, e](const LaneVectors* Z) { return Z ? (part ? Z->im : Z->re).data() + e : nullptr; };
        const double *x = row(p.X), *x2 = row(p.X2), *y = row(p.Y), *y2 = row(p.Y2);
        const double cx = p.cx, cy = p.cy;
        if (x2 && y2)
          for (int m = 0; m < n; ++m) sum[m] += (x[m] + cx * x2[m]) * (y[m] + cy * y2[m]);
        else
          for (int m = 0; m < n; ++m) sum[m] += x[m] * y[m];
      }
  }
  for (int q = 0; q < count; ++q) sums[q] = weighted(per_lane_.data() + static_cast<std::size_t>(q) * n, n);
}

double StickPhaseLedger::weighted(const double* per_lane, int n) const {
  const double* w = blocks_.weight.data();
  double total = 0;
  for (int m = 0; m < n; ++m) total += w[m] * per_lane[m];
  return total;
}

double StickPhaseLedger::kinetic(const ModeState& x, int n_active) const {
  return kinetic_from(dot(x.V, x.MV, n_active), x.V);
}

double StickPhaseLedger::kinetic(const double* v_M_v_per_lane, int n, const LaneVectors& V) const {
  return kinetic_from(weighted(v_M_v_per_lane, n), V);
}

double StickPhaseLedger::kinetic_from(double v_M_v, const LaneVectors& V) const {
  return 0.5 * (v_M_v + 2 * M_fd_v_top_.dot(lane_zero(V)) + kinetic_top_);
}

double StickPhaseLedger::elastic(const ModeState& x, int n_active, double retired_elastic,
                                 const Eigen::Vector2d& u_top) const {
  return elastic_from(dot(x.U, x.KU, n_active), x.U, retired_elastic, u_top);
}

double StickPhaseLedger::elastic(const double* u_K_u_per_lane, int n, const LaneVectors& U, double retired_elastic,
                                 const Eigen::Vector2d& u_top) const {
  return elastic_from(weighted(u_K_u_per_lane, n), U, retired_elastic, u_top);
}

double StickPhaseLedger::elastic_from(double u_K_u, const LaneVectors& U, double retired_elastic,
                                      const Eigen::Vector2d& u_top) const {
  const Eigen::Vector2d top = blocks_.K_fd0.transpose() * lane_zero(U) + blocks_.n_x * (blocks_.K_dd0 * u_top);
  return 0.5 * (u_K_u + u_top.dot(top)) + retired_elastic;
}

Eigen::Vector2d StickPhaseLedger::top_force(const ModeState& x, const Eigen::Vector2d& u_top) const {
  return blocks_.K_fd0.transpose() * lane_zero(x.U) + blocks_.n_x * (blocks_.K_dd0 * u_top) +
         blocks_.M_fd0.transpose() * lane_zero(x.A);
}

void StickPhaseLedger::book_step(const ModeState& before, const ModeState& after, int n_active,
                                 const Eigen::Vector2d& u_top_before, const Eigen::Vector2d& u_top_after,
                                 const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r_before,
                                 const Eigen::VectorXd& r_after, EnergySums& sums) const {
  book_work(top_force(before, u_top_before), top_force(after, u_top_after), u_top_before, u_top_after, du_contact,
            r_before, r_after, sums);
  if (!sums.hht.on()) return;
  // The three HHT terms of EnergyLedger::book_hht_terms, each a quadratic form of the two states, the mass
  // products carried: v.M da = (v_b + v_a).(M a_a - M a_b), da.M a = (a_a - a_b).(M a_b + M a_a).
  const double dt = hht_.dt;
  const std::array<LaneProduct, 3> forms{{{&before.V, &after.V, 1, &after.MA, &before.MA, -1},
                                          {&after.A, &before.A, -1, &before.MA, &after.MA, 1},
                                          {&after.U, &before.U, -1, &before.S, &after.S, 1}}};
  double form[3];
  lane_products(forms.data(), 3, n_active, form);
  const double v_M_da = 0.5 * form[0] + M_fd_v_top_.dot(lane_zero(after.A) - lane_zero(before.A));
  const double da_M_a = 0.5 * form[1];
  const double du_s = 0.5 * form[2];
  sums.hht.gamma -= dt * (hht_.gamma - 0.5) * v_M_da;
  sums.hht.beta += dt * dt * (hht_.beta - 0.5 * hht_.gamma) * da_M_a;
  sums.hht.shift -= du_s;
}

void StickPhaseLedger::book_work(const Eigen::Vector2d& F_top_before, const Eigen::Vector2d& F_top_after,
                                 const Eigen::Vector2d& u_top_before, const Eigen::Vector2d& u_top_after,
                                 const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r_before,
                                 const Eigen::VectorXd& r_after, EnergySums& sums) const {
  for (Eigen::Index k = 0; k < du_contact.size() / 2; ++k) {
    sums.dissipation_friction -= 0.5 * (r_before(2 * k) + r_after(2 * k)) * du_contact(2 * k);
    sums.work_contact_normal -= 0.5 * (r_before(2 * k + 1) + r_after(2 * k + 1)) * du_contact(2 * k + 1);
  }
  sums.work_external += 0.5 * (F_top_before + F_top_after).dot(u_top_after - u_top_before);
}

}  // namespace slidewave

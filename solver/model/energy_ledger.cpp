#include "model/energy_ledger.hpp"

namespace slidewave {

EnergyLedger::EnergyLedger(const LayerModel& m, const Eigen::VectorXd& v_top)
    : model_(m),
      hht_(m.config.time.hht_alpha, m.d.dt),
      weight_previous_(m.config.time.contact_weighting == ContactWeighting::alpha ? m.config.time.hht_alpha : 0.0) {
  M_fd_v_top_ = m.M_fd * v_top;
  kinetic_top_ = v_top.dot(m.top_mass_product(v_top));
}

double EnergyLedger::kinetic(const HHTState& s) const {
  return 0.5 * (s.v.head(model_.n_free).dot(s.Mv_f + 2 * M_fd_v_top_) + kinetic_top_);
}

double EnergyLedger::elastic(const HHTState& s) const { return 0.5 * s.u.dot(s.Ku); }

EnergySums EnergyLedger::start(const HHTState& s) const {
  EnergySums sums;
  sums.F_top = s.Ku.tail(model_.n_top) + model_.M_top_rows * s.acc;
  sums.energy_start = kinetic(s) + elastic(s);
  if (model_.config.output.energy_decomposition) {
    const int n_f = model_.n_free;
    HhtDissipation& h = sums.hht;
    h.v_f = s.v.head(n_f);
    h.acc_f = s.acc.head(n_f);
    h.Ma_f = s.Ma_f;
    h.Ku_f = s.Ku.head(n_f);
    h.shift_f = Eigen::VectorXd::Zero(n_f);  // the initial acceleration satisfies M a + K u = C^T r
  }
  return sums;
}

void EnergyLedger::book_step(const HHTState& s, const Eigen::VectorXd& u_previous, const Eigen::VectorXd& r_previous,
                             const Eigen::VectorXd& du_contact, EnergySums& sums) const {
  const int n_t = model_.n_top;
  const Eigen::VectorXd& r = s.r;
  for (Eigen::Index k = 0; k < du_contact.size() / 2; ++k) {
    sums.dissipation_friction -= 0.5 * (r_previous(2 * k) + r(2 * k)) * du_contact(2 * k);
    sums.work_contact_normal -= 0.5 * (r_previous(2 * k + 1) + r(2 * k + 1)) * du_contact(2 * k + 1);
  }
  const Eigen::VectorXd F_top_next = s.Ku.tail(n_t) + model_.M_top_rows * s.acc;
  sums.work_external += 0.5 * (sums.F_top + F_top_next).dot(s.u.tail(n_t) - u_previous.tail(n_t));
  sums.F_top = F_top_next;
  if (sums.hht.on()) book_hht_terms(s, u_previous, r_previous, sums.hht);
}

// Each term from the step's quantities, never from the balance (docs/energy-balance.md): the carried
// M_ff a stands for M [a] on the free rows, M_fd v_top for the top rows' share of <v>.M [a].
void EnergyLedger::book_hht_terms(const HHTState& s, const Eigen::VectorXd& u_previous,
                                  const Eigen::VectorXd& r_previous, HhtDissipation& h) const {
  const int n_f = model_.n_free, n_c = model_.n_contact_dofs;
  const double dt = hht_.dt;
  const auto acc_next = s.acc.head(n_f), v_next = s.v.head(n_f), Ku_next = s.Ku.head(n_f);
  const Eigen::VectorXd d_acc = acc_next - h.acc_f;
  const Eigen::VectorXd d_Ma = s.Ma_f - h.Ma_f;
  const double v_M_da = 0.5 * (h.v_f + v_next).dot(d_Ma) + M_fd_v_top_.dot(d_acc);
  const double da_M_a = 0.5 * d_acc.dot(h.Ma_f + s.Ma_f);
  Eigen::VectorXd shift_next = hht_.alpha * (Ku_next - h.Ku_f);
  shift_next.head(n_c) -= weight_previous_ * (s.r - r_previous);
  const double du_s = 0.5 * (s.u.head(n_f) - u_previous.head(n_f)).dot(h.shift_f + shift_next);
  // The residual grows by the three terms; the dissipation is their opposite.
  h.gamma -= dt * (hht_.gamma - 0.5) * v_M_da;
  h.beta += dt * dt * (hht_.beta - 0.5 * hht_.gamma) * da_M_a;
  h.shift -= du_s;
  h.v_f = v_next;
  h.acc_f = acc_next;
  h.Ma_f = s.Ma_f;
  h.Ku_f = Ku_next;
  h.shift_f.swap(shift_next);
}

double EnergyLedger::balance_residual(double kinetic, double elastic, const EnergySums& sums) const {
  return kinetic + elastic + sums.dissipation_friction + sums.work_contact_normal - sums.energy_start -
         sums.work_external;
}

}  // namespace slidewave

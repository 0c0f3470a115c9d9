#include "model/energy_ledger.hpp"

namespace slidewave {

EnergyLedger::EnergyLedger(const LayerModel& m, const Eigen::VectorXd& v_top) : model_(m) {
  const int n_t = m.n_top;
  M_fd_v_top_ = m.M_fd * v_top;
  kinetic_top_ = v_top.dot(m.M.bottomRightCorner(n_t, n_t) * v_top);
}

double EnergyLedger::kinetic(const HHTState& s) const {
  return 0.5 * (s.v.head(model_.n_free).dot(s.Mv_f + 2 * M_fd_v_top_) + kinetic_top_);
}

double EnergyLedger::elastic(const HHTState& s) const { return 0.5 * s.u.dot(s.Ku); }

EnergySums EnergyLedger::start(const HHTState& s) const {
  EnergySums sums;
  sums.F_top = s.Ku.tail(model_.n_top) + model_.M_top_rows * s.acc;
  sums.energy_start = kinetic(s) + elastic(s);
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
}

double EnergyLedger::balance_residual(double kinetic, double elastic, const EnergySums& sums) const {
  return kinetic + elastic + sums.dissipation_friction + sums.work_contact_normal - sums.energy_start -
         sums.work_external;
}

}  // namespace slidewave

#pragma once
// Energy balance of the dynamic stage (docs/contracts.md, section 2, /global):
//     E_kin + E_el + D_fric + W_normal - E(0) - W_ext = residual
// (round-off for hht_alpha = 0, minus the algorithmic dissipation of HHT otherwise), with
//     E_kin = 1/2 v.M v,  E_el = 1/2 u.K u (K u and M_ff v are carried by the stepper),
//     D_fric   = -sum 1/2 (R_t(n) + R_t(n+1)) du_x,   W_normal = -sum 1/2 (R_n(n) + R_n(n+1)) du_y,
//     W_ext    =  sum 1/2 (F_top(n) + F_top(n+1)).du_top,  F_top = (K u + M a) on the top rows.
// The contact work is booked with the trapezoid: the discrete energy identity of the trapezoidal rule
// (exact at hht_alpha = 0, either weighting). For hht_alpha > 0 no exact identity exists; with "end"
// weighting the booked residual can then be slightly positive (2e-6 of the energy scale measured at H/8),
// with "alpha" weighting it stays negative (HHT dissipation).
#include <Eigen/Dense>

#include "model/layer_model.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

/// The running sums (a checkpoint saves them).
struct EnergySums {
  double energy_start = 0;          ///< E_kin + E_el at t = 0 (J/m)
  double work_external = 0;         ///< W_ext since t = 0 (J/m)
  double dissipation_friction = 0;  ///< D_fric since t = 0 (J/m)
  double work_contact_normal = 0;   ///< W_normal since t = 0 (J/m)
  Eigen::VectorXd F_top;            ///< top reaction at the current time (N/m per DOF)
};

class EnergyLedger {
 public:
  /// @param v_top  the constant velocity of the top DOFs
  EnergyLedger(const LayerModel& model, const Eigen::VectorXd& v_top);

  double kinetic(const HHTState& s) const;
  double elastic(const HHTState& s) const;
  /// Sums at t = 0.
  EnergySums start(const HHTState& s) const;
  /// Books the step that ended in s, from u_previous and r_previous; du_contact = C (u - u_previous).
  void book_step(const HHTState& s, const Eigen::VectorXd& u_previous, const Eigen::VectorXd& r_previous,
                 const Eigen::VectorXd& du_contact, EnergySums& sums) const;
  /// E_kin + E_el + D_fric + W_normal - E(0) - W_ext.
  double balance_residual(double kinetic, double elastic, const EnergySums& sums) const;

 private:
  const LayerModel& model_;
  Eigen::VectorXd M_fd_v_top_;  ///< M_fd v_top (constant)
  double kinetic_top_;          ///< v_top.M_top v_top (constant)
};

}  // namespace slidewave

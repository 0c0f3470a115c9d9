#pragma once
// Energy balance of the dynamic stage (docs/contracts.md, section 2, /global):
//     E_kin + E_el + D_fric + W_normal - E(0) - W_ext = residual
// (round-off for hht_alpha = 0, minus the algorithmic dissipation of HHT otherwise), with
//     E_kin = 1/2 v.M v,  E_el = 1/2 u.K u (K u and M_ff v are carried by the stepper),
//     D_fric   = -sum 1/2 (R_t(n) + R_t(n+1)) du_x,   W_normal = -sum 1/2 (R_n(n) + R_n(n+1)) du_y,
//     W_ext    =  sum 1/2 (F_top(n) + F_top(n+1)).du_top,  F_top = (K u + M a) on the top rows.
// The contact work is booked with the trapezoid: the discrete energy identity of the trapezoidal rule
// (exact at hht_alpha = 0, either weighting).
//
// With output.energy_decomposition = hht the ledger also books, from the step's own quantities, the
// three terms by which HHT departs from that identity (docs/energy-balance.md derives them):
//     residual(n+1) - residual(n) = dt (gamma - 1/2) <v>.M [a] - dt^2 (beta - gamma/2) [a].M <a> + [u_f].<s>,
//     s(n+1) = alpha (K [u])_f - a' C^T [r],  s(0) = 0,
// with [x] = x(n+1) - x(n), <x> = (x(n) + x(n+1))/2, a' the weight of r(n) (alpha or 0). Their sum with
// the opposite sign is the HHT dissipation, which must equal -residual to round-off.
#include <Eigen/Dense>

#include "model/layer_model.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

/// The HHT terms booked so far and what the next step needs of the current time (all empty/zero when
/// output.energy_decomposition is none).
struct HhtDissipation {
  double gamma = 0, beta = 0, shift = 0;   ///< each term's dissipation since t = 0 (J/m)
  Eigen::VectorXd v_f, acc_f, Ma_f, Ku_f;  ///< v, a, M_ff a, K u of the free rows at the current time
  Eigen::VectorXd shift_f;                 ///< s at the current time (free rows)
  double total() const { return gamma + beta + shift; }
  bool on() const { return v_f.size() > 0; }
};

/// The running sums (a checkpoint saves them).
struct EnergySums {
  double energy_start = 0;          ///< E_kin + E_el at t = 0 (J/m)
  double work_external = 0;         ///< W_ext since t = 0 (J/m)
  double dissipation_friction = 0;  ///< D_fric since t = 0 (J/m)
  double work_contact_normal = 0;   ///< W_normal since t = 0 (J/m)
  Eigen::VectorXd F_top;            ///< top reaction at the current time (N/m per DOF)
  HhtDissipation hht;               ///< only with output.energy_decomposition = hht
};

class EnergyLedger {
 public:
  /// @param v_top  the constant velocity of the top DOFs
  EnergyLedger(const LayerModel& model, const Eigen::VectorXd& v_top);

  double kinetic(const HHTState& s) const;
  double elastic(const HHTState& s) const;
  /// Sums at t = 0 (with the HHT terms when the configuration asks for them).
  EnergySums start(const HHTState& s) const;
  /// Books the step that ended in s, from u_previous and r_previous; du_contact = C (u - u_previous).
  void book_step(const HHTState& s, const Eigen::VectorXd& u_previous, const Eigen::VectorXd& r_previous,
                 const Eigen::VectorXd& du_contact, EnergySums& sums) const;
  /// E_kin + E_el + D_fric + W_normal - E(0) - W_ext.
  double balance_residual(double kinetic, double elastic, const EnergySums& sums) const;

 private:
  void book_hht_terms(const HHTState& s, const Eigen::VectorXd& u_previous, const Eigen::VectorXd& r_previous,
                      HhtDissipation& hht) const;

  const LayerModel& model_;
  Eigen::VectorXd M_fd_v_top_;  ///< M_fd v_top (constant)
  double kinetic_top_;          ///< v_top.M_top v_top (constant)
  HHTCoefficients hht_;
  double weight_previous_;  ///< a': weight of r(n) in the equation of motion of step n -> n+1
};

}  // namespace slidewave

#pragma once
// The energy ledger's figures (model/energy_ledger.hpp) of a layer state held in wavenumbers
// (model/stick_phase/wavenumber_stepper.hpp), without going back to the mesh: every term is a quadratic
// form x.y of two free-row vectors, which Parseval's relation gives as sum_m weight(m) Re(X_m^H Y_m)
// (model/stick_phase/wavenumber_blocks.hpp), plus the top rows, which see wavenumber 0 only (the top is
// x-uniform). Retired wavenumbers sit at their static state: no velocity, no acceleration, no change, so
// they add a constant to u.K u / 2 and nothing else.
#include <Eigen/Dense>
#include <vector>

#include "model/energy_ledger.hpp"
#include "model/stick_phase/wavenumber_blocks.hpp"
#include "model/stick_phase/wavenumber_stepper.hpp"

namespace slidewave {

class StickPhaseLedger {
 public:
  /// @param V0 the top's velocity (x)
  StickPhaseLedger(const WavenumberBlocks& blocks, const HHTCoefficients& hht, double V0);

  /// E_kin = 1/2 v.M v (all DOFs) of the active wavenumbers 0..n_active-1 of x.
  double kinetic(const ModeState& x, int n_active) const;
  /// E_el = 1/2 u.K u (all DOFs); retired_elastic: the retired wavenumbers' share; u_top one top node's (x, y).
  double elastic(const ModeState& x, int n_active, double retired_elastic, const Eigen::Vector2d& u_top) const;
  /// The same two from the per-lane sums of the forms v.M v and u.K u (sum over the rows, real then imaginary
  /// part, as the lanes accumulate them; lanes m < n), made by a caller that passes over the rows anyway.
  double kinetic(const double* v_M_v_per_lane, int n, const LaneVectors& V) const;
  double elastic(const double* u_K_u_per_lane, int n, const LaneVectors& U, double retired_elastic,
                 const Eigen::Vector2d& u_top) const;
  /// The sum over the top nodes of F_top = (K u + M a)_top (x, y).
  Eigen::Vector2d top_force(const ModeState& x, const Eigen::Vector2d& u_top) const;
  /// Books the step from `before` to `after` as EnergyLedger::book_step does: external work, contact work
  /// (du_contact, r_before, r_after at the contact DOFs, in x), the HHT terms if sums.hht is on.
  void book_step(const ModeState& before, const ModeState& after, int n_active, const Eigen::Vector2d& u_top_before,
                 const Eigen::Vector2d& u_top_after, const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r_before,
                 const Eigen::VectorXd& r_after, EnergySums& sums) const;
  /// The contact work and the external work of a step (book_step without the HHT terms), from the sums of the
  /// top force F_top = (K u + M a)_top over the top nodes before and after it (top_force()).
  void book_work(const Eigen::Vector2d& F_top_before, const Eigen::Vector2d& F_top_after,
                 const Eigen::Vector2d& u_top_before, const Eigen::Vector2d& u_top_after,
                 const Eigen::VectorXd& du_contact, const Eigen::VectorXd& r_before, const Eigen::VectorXd& r_after,
                 EnergySums& sums) const;

 private:
  /// One form sum over lanes m < n of weight(m) Re((X + cx X2)_m^H (Y + cy Y2)_m) (X2, Y2 both null or both set).
  struct LaneProduct {
    const LaneVectors *X, *X2;
    double cx;
    const LaneVectors *Y, *Y2;
    double cy;
  };
  /// sums[q] = the form of products[q], q < count, in one pass over the rows per form.
  void lane_products(const LaneProduct* products, int count, int n, double* sums) const;
  /// E_kin from the lanes' v.M v, E_el from their u.K u (the top rows' shares added).
  double kinetic_from(double v_M_v, const LaneVectors& V) const;
  double elastic_from(double u_K_u, const LaneVectors& U, double retired_elastic, const Eigen::Vector2d& u_top) const;
  /// sum over lanes m < n of weight(m) per_lane[m].
  double weighted(const double* per_lane, int n) const;
  /// sum over lanes m < n of weight(m) Re(X_m^H Y_m).
  double dot(const LaneVectors& X, const LaneVectors& Y, int n) const;
  const WavenumberBlocks& blocks_;
  HHTCoefficients hht_;
  Eigen::VectorXd M_fd_v_top_;            ///< M_fd v_top per free row of a column (x-uniform)
  double kinetic_top_;                    ///< v_top.M_top v_top (all top DOFs)
  mutable std::vector<double> per_lane_;  ///< scratch of lane_products
};

}  // namespace slidewave

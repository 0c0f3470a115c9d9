#pragma once
// The HHT step of the layer while every contact node sticks, wavenumber by wavenumber
// (docs/stick-phase.md). Sticking holds the contact DOFs (y = q + W r = 0: u_x(n+1) = u_x(n), u_y = 0), so
// the step is the HHT step of the layer with those DOFs prescribed: linear and block-circulant, it splits
// into independent systems per wavenumber m = 0..n_x/2 on the s = 2 n_y free DOFs of one mesh column,
//     A_eff,II U_I(n+1) = b (M U~)_I - a (K U(n))_I - (b M_Ic + (1-a) K_Ic) U_c - [m = 0] (1-a) n_x K_fd0 u_top(n+1),
// (I the interior rows, c the held contact rows, b = 1/(beta dt^2), U~ the predictor), the Newmark updates,
// and the contact reactions from the contact rows of the equation of motion,
//     w R(n+1) = (M A(n+1))_c + (1-a) (K U(n+1))_c + a (K U(n))_c - a' R(n).
// Only wavenumber 0 feels the top's motion. Every other one is homogeneous with the contact held: it
// tends to its static state U* (K_II U*_I = -K_Ic U_c, V = A = 0, R* = (K U*)_c), and HHT's numerical
// damping takes it there. Once the distance from it cannot change a double of the layer's state or
// reactions, the wavenumber is retired: set to U* and no longer stepped. Wavenumbers retire from the
// highest down (their lowest frequency grows with m), so the active ones are always m = 0..n_active-1, and
// the step's arrays keep only those (narrowed in place, a cache line of lanes at a time): a row's active lanes
// stay contiguous, which is what the step's loops stream through (the lanes beyond are at their static state).
// One state, updated in place: a step first makes u(n+1) and the reactions only (what the caller tests), and
// advance() then updates the state row by row where it lies, so that the step streams through one state instead
// of reading one and writing another (the same operations, the same bits).
#include <Eigen/Dense>
#include <vector>

#include "model/stick_phase/banded_lanes.hpp"
#include "model/stick_phase/row_transform.hpp"
#include "model/stick_phase/wavenumber_blocks.hpp"
#include "time/hht.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

/// The layer's state in wavenumbers (free rows; the top is x-uniform and known). The mass products are
/// carried as time/hht_stepper.hpp carries them (Newmark relations and the equation of motion): the
/// predictor's M u~ and the ledger's forms v.M v, v.M da, da.M a are then sums over the rows, and the
/// step's only band products are K u and the two contact rows of M a (the reactions).
struct ModeState {
  LaneVectors U, V, A, KU;  ///< u, v, a, K u of the free rows (K u with the top's share)
  LaneVectors MU, MV, MA;   ///< M u, M v, M a of the free rows (M of the free DOFs: the top has a = 0)
  LaneVectors S;            ///< the HHT shift term s (model/energy_ledger.hpp), if booked (else empty)
  LaneVectors R;            ///< contact reactions (2 rows)
  /// Per lane, the energies' forms v.M v and u.K u summed over the rows (real then imaginary part of each row,
  /// the order of StickPhaseLedger's sums), where the step that made the state accumulated them; else empty.
  std::vector<double> v_M_v, u_K_u;
  ModeState(int s, int lanes, bool with_shift = true)
      : U(s, lanes),
        V(s, lanes),
        A(s, lanes),
        KU(s, lanes),
        MU(s, lanes),
        MV(s, lanes),
        MA(s, lanes),
        S(with_shift ? s : 0, lanes),
        R(2, lanes) {}
};

/// The lanes' state from the layer's: the DFT of its free rows' u, v, a, K u and mass products, and of r (not S).
void transform_state(const HHTState& layer, const RowTransform& transform, ModeState& x);

/// The layer's u, v, a (its top at u_top = (u_x, u_y) and moving at V0) by the inverse DFT of the lanes' state,
/// and K u and the mass products by the real-space products (the contact reactions are left to the caller).
/// Lanes beyond x's arrays (narrowed) are at rest: u from U_beyond (every lane), v = a = 0.
void rebuild_dynamics(const LayerModel& layer, const RowTransform& transform, const ModeState& x,
                      const Eigen::Vector2d& u_top, HHTState& s, const LaneVectors* U_beyond = nullptr);

class WavenumberStepper {
 public:
  /// Factorizes the interior blocks of A_eff,m and K_m of every wavenumber.
  /// @param retire_tolerance  a wavenumber retires when kappa (its share of any entry) of its distance from
  ///                          its static state is below retire_tolerance times the layer's scale (0: never)
  WavenumberStepper(const WavenumberBlocks& blocks, const HHTCoefficients& hht, bool alpha_weighted,
                    double retire_tolerance);

  const WavenumberBlocks& blocks() const { return blocks_; }
  /// The state at t = 0 from the layer's (its free rows and their mass products), with shift_f the ledger's
  /// s (or null); the held contact values U_c = (u_x(0), 0) and the static states.
  void start(const HHTState& layer, const Eigen::VectorXd* shift_f, const RowTransform& transform);
  /// The first part of a step, the top displaced to u_top_next (one node's x, y): u(n+1) and the reactions
  /// R(n+1) into next_displacement() and next_reactions(); current() unchanged.
  void step(const Eigen::Vector2d& u_top_next);
  /// The rest of the step: current() becomes the state at n+1, in place (previous() keeps the one at n when the
  /// shift term is booked).
  void advance();
  /// Retires what may be (after the caller has read the state advance() made).
  void retire_settled();

  /// The state of the active lanes (rows width() long; the reactions R of every lane). The lanes beyond
  /// width() retired before the arrays narrowed: they are at rest at their static displacement (V, A, S = 0).
  const ModeState& current() const { return state_; }
  /// The state before the last advance(), kept only when the shift term is booked (the ledger's HHT terms).
  const ModeState& previous() const { return previous_; }
  /// u(n+1) (rows width() long) and R(n+1) (every lane) of the last step().
  const LaneVectors& next_displacement() const { return U_next_; }
  const LaneVectors& next_reactions() const { return R_next_; }
  /// The static displacement U* of every lane.
  const LaneVectors& static_displacement() const { return U_static_; }
  /// The row length of the step's arrays: n_active() rounded up to a cache line, at most all lanes.
  int width() const { return width_; }
  int n_active() const { return n_active_; }
  /// 1/2 sum of weight Re(U*^H K U*) over the retired wavenumbers (their constant share of u.K u / 2).
  double retired_elastic() const { return retired_elastic_; }
  /// The transient growth factor of lane m in the retirement test (docs/stick-phase.md).
  double transient_factor(int m) const { return transient_factor_[m]; }

 private:
  /// True if lane m is within the retirement bound of its static state.
  bool may_retire(int m) const;
  void retire(int m);
  /// Drops the retired lanes beyond the next cache line from the step's arrays.
  void narrow_to_active();
  /// Row r (interior) of the step's right-hand side b M u~ - a K u(n) + the held contact's load, from x's mass
  /// products and KU, into rhs_out (the active lanes).
  void interior_rhs_row(const ModeState& x, const LaneVectors& KU, int r, LaneVectors& rhs_out) const;
  const BandedLanes& K() const { return K_narrow_.lanes > 0 ? K_narrow_ : blocks_.K; }
  const BandedLanes& M() const { return M_narrow_.lanes > 0 ? M_narrow_ : blocks_.M; }

  const WavenumberBlocks& blocks_;
  HHTCoefficients hht_;
  double w_, w_previous_, retire_tolerance_;
  BandedLaneFactor A_eff_interior_, K_interior_;
  ModeState state_, previous_;
  /// The step's new values until advance(): u(n+1), K u(n+1) (rows 0, 1 by step(), the rest by advance()), R(n+1);
  /// a(n+1) of the rows that M's contact rows reach, and M a(n+1) of the contact rows. After advance(), U_next_
  /// holds the next step's interior right-hand side (rhs_ready_).
  LaneVectors U_next_, KU_next_, R_next_, A_contact_, MA_contact_;
  LaneVectors hold_, hold_load_;                  ///< hold_: U_c
  LaneVectors U_static_, KU_static_, MU_static_;  ///< the static states of all lanes (R* = rows 0, 1 of KU*)
  BandedLanes K_narrow_, M_narrow_;  ///< K_m of the active lanes, once the arrays narrow; M_m's contact rows
  Eigen::Vector2d u_top_next_ = Eigen::Vector2d::Zero();  ///< the top of the last step()
  int n_active_ = 0, width_ = 0;
  double retired_elastic_ = 0;
  double u_scale_ = 0, r_scale_ = 0;  ///< the layer's max |u| and max |r| at the start
  bool track_shift_ = false;
  bool rhs_ready_ = false;  ///< U_next_ holds the next step's interior right-hand side (made by advance())
  std::vector<double> transient_factor_;
};

}  // namespace slidewave

#pragma once
// The slip step of the layer on the rigid flat with its state in wavenumbers (docs/stick-phase.md, "The slip
// phase in wavenumbers"). The plain step (time/hht_stepper.hpp on linalg/block_circulant_solver.hpp)
// transforms the right-hand side of all rows forward and the corrected displacement of all rows back, every
// step. Here the state stays in the lanes m = 0..n_x/2 of model/stick_phase/wavenumber_stepper.hpp (u_y turned
// by -i: real symmetric K_m, M_m; the mass products carried), and only the two contact rows cross over:
//     free solve   A_eff,m U_free = b (M U~) - a K U(n) + a' [rows 0, 1] R(n) - [m = 0] (1-a) n_x K_fd0 u_top(n+1)
//                  (band L D L^T of all s rows), u_free,c = inverse DFT of rows 0, 1;
//     contact      r(n+1) by the loop's contact solve (model/contact_step.hpp; W from the lanes),
//                  R(n+1) = its DFT (one mesh row);
//     correction   U(n+1) = U_free + w (G_0 R_0 + G_1 R_1),  G_c = A_eff,m^-1 e_c (real per lane), the Newmark
//                  update, K U by the band product (+ the top's share on lane 0), and the mass products,
//                  M A(n+1) = -(1-a) K U(n+1) - a K U(n) + [rows 0, 1] (w R(n+1) + a' R(n)),
//                  u_c(n+1) = inverse DFT of rows 0, 1 (the next q, the friction law's increment).
// w = 1-a, a' = a (alpha weighting) or w = 1, a' = 0 (end), as in HHTStepper. The same discrete step as
// plain stepping, to round-off. The energy ledger's contact and external work are booked per step (the
// energies from lane sums, model/stick_phase/stick_phase_ledger.hpp); its HHT terms are not
// (output.energy_decomposition = hht steps plainly). The lanes' state goes into checkpoints (save/restore),
// so that a resumed run is the uninterrupted one bit for bit.
#include <Eigen/Dense>
#include <cstdint>
#include <memory>
#include <vector>

#include "contact/friction_law.hpp"
#include "model/contact_step.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state.hpp"
#include "model/run_observer.hpp"
#include "model/stick_phase/banded_lanes.hpp"
#include "model/stick_phase/row_transform.hpp"
#include "model/stick_phase/stick_phase_ledger.hpp"
#include "model/stick_phase/wavenumber_blocks.hpp"
#include "model/stick_phase/wavenumber_stepper.hpp"

namespace slidewave {

class WavenumberSlipStep {
 public:
  /// @param layer  the layer and its blocks per wavenumber (both must outlive this object); u_x_top: the
  ///               preload's top shear displacement
  /// @param law    the friction law (must outlive this object)
  WavenumberSlipStep(const LayerModel& layer, const WavenumberBlocks& blocks, double u_x_top,
                     const GaussSeidelSettings& settings, const FrictionLaw& law);

  /// The Delassus operator W = w C A_eff^-1 C^T of the contact solve, from the lanes' responses to a unit load
  /// on a contact node (what plain stepping gets from its K_eff factorization: the same to round-off).
  const Eigen::MatrixXd& delassus() const { return W_; }

  /// From the layer's real-space loop state (rigid flat): the DFT of u, v, a, K u, the mass products, r; the
  /// energy sums as they are.
  void start(const LoopState& loop);
  /// True if save() wrote into these arrays.
  static bool saved_in(const StateArrays& arrays);
  /// From a checkpoint that save() wrote into (`loop`: its real-space state, restored), exactly where the
  /// saving run was. Throws std::runtime_error if its lanes' state is missing or of another size.
  void restore(const LoopState& loop, const StateArrays& arrays);
  /// Adds the lanes' state to a checkpoint's arrays.
  void save(StateArrays& arrays) const;
  /// The three parts of a step (timed apart by the bench), in this order; step() does all three.
  void solve_free();
  GaussSeidelReport solve_contact();
  void correct();
  GaussSeidelReport step();

  std::int64_t step_count() const { return step_; }
  /// True once the lanes' state is no longer the transform of a real-space state (after a step, or restored):
  /// from then on the lanes, not the real-space state, are what a checkpoint must keep.
  bool owns_state() const { return owns_state_; }
  /// Reactions and contact displacements of the current step (2 per contact node, real space).
  const Eigen::VectorXd& reactions() const { return r_; }
  const Eigen::VectorXd& contact_displacement() const { return u_contact_; }
  const std::vector<ContactState>& contact_states() const { return contact_states_; }
  const ModeState& modes() const { return state_; }
  /// The energy ledger's running sums (F_top and the HHT vectors are filled by reconstruct()).
  const EnergySums& sums() const { return sums_; }
  /// E_kin, E_el of the current step (from the per-lane sums the correction accumulates).
  double kinetic() const { return kinetic_; }
  double elastic() const { return elastic_; }
  /// The layer's loop state at the current step: dynamics (K u and the mass products by the real-space
  /// products, as StickPhase::reconstruct makes them), energy sums, contact states, friction memory, step. The
  /// recorder's state is left as it was.
  void reconstruct(LoopState& loop) const;

 private:
  Eigen::Vector2d top_after(std::int64_t step) const;
  /// After start() or restore() has set the lanes: the step, contact states, friction memory, reactions and
  /// sums of `loop`, and what follows from the lanes (the ledger's top force and energies, the contact
  /// displacement).
  void adopt(const LoopState& loop, bool owns_state);

  const LayerModel& layer_;
  HHTCoefficients hht_;
  double u_x_top_, w_, w_previous_;
  const FrictionLaw& law_;
  const WavenumberBlocks& blocks_;
  RowTransform transform_;
  BandedLaneFactor A_eff_;                 ///< A_eff,m = b M_m + (1-a) K_m on all s rows
  std::vector<double> G0_, G1_;            ///< w A_eff,m^-1 e_0, w A_eff,m^-1 e_1 (row r, lane m at r lanes + m)
  ModeState state_;                        ///< time n (updated in place by correct(); no S: no HHT terms booked)
  LaneVectors U_next_, KU_next_, R_next_;  ///< the step's right-hand side -> U_free -> U(n+1); K U(n+1); R(n+1)
  Eigen::MatrixXd W_;
  std::unique_ptr<ContactStep> contact_;  ///< made once W_ is (it keeps W_ by reference)
  StickPhaseLedger ledger_;
  EnergySums sums_;
  Eigen::Vector2d F_top_;  ///< sum over the top nodes of (K u + M a)_top at the current step
  double kinetic_ = 0, elastic_ = 0;
  std::vector<ContactState> contact_states_;
  FrictionState friction_;
  std::int64_t step_ = 0;
  bool owns_state_ = false;
  bool predicted_ = false;  ///< the last correct() made the next free solve's right-hand side (in U_next_)
  Eigen::Vector2d u_top_next_;
  Eigen::VectorXd u_free_contact_, u_contact_, u_contact_next_, r_, du_;
  std::vector<double> v_M_v_, u_K_u_;  ///< per lane: the energies' forms, accumulated by correct()
};

}  // namespace slidewave

#pragma once
// The frictional contact problem of a Delassus operator W, condensed on the contact DOFs:
//     y = q + W r,   node k: y_k = (du_x, u_y)_k, r_k = (r_x, r_y)_k  (layout 2k: x, 2k+1: y),
// with the local Signorini–Coulomb law of coulomb_local.hpp at every node, each closed node's friction
// bound given by the friction law (contact/friction_bounds.hpp). A ContactSolver is made once per W (the
// time loop's, the preload's) and solves the problems of every step on it.
//
// Nonsmooth (projected) Gauss–Seidel: each sweep solves every node exactly with the others frozen; y is
// updated in place (two columns of W per node), so a sweep costs O(n^2) (O(n) memory traffic when W is
// block-circulant and read from its two generating columns, which fit in the cache where W does not;
// docs/contact-solver.md). Warm-started from the r passed in.
// Convergence: max_k |r_k(new) - r_k(old)| <= tolerance * force_scale over one sweep.
//
// Under-relaxed fallback. With a large f the friction force of one node can move a neighbour's gap
// more than its own pressure does; the exact local solves then overshoot the solution from both sides
// and the sweeps settle on a period-2 orbit around it (every other sweep repeats, the change per sweep
// stays put: seen at f = 2, H/128, just before slip onset, with stick <-> slip flips of a few nodes).
// If the plain sweeps miss the tolerance within max_iterations, or come back to the reactions of two
// sweeps before on kCycleSweeps sweeps in a row (the orbit, detected early), or stall (their smallest change
// has not halved in kStallSweeps sweeps), the solve restarts from the warm start with under-relaxed sweeps, r_k <- r_k
// + omega (r_k,local - r_k), omega = kFallbackRelaxation, for up to max_iterations more sweeps. The fixed points are
// the same (those of the exact local solves) and the residual is the unrelaxed change, so the tolerance means the same.
// A solve whose plain sweeps converge never reaches the fallback: its result is unchanged bit for bit. The fallback
// starts afresh (warm start, friction bounds' pass state), so when the plain pass gives up changes only the sweep
// count, unless it would have converged after a stall: converging plain passes halve their change every few to ~100
// sweeps. Neither pass is guaranteed to converge for large f (projected Gauss–Seidel has no such guarantee); the caller
// must check.
//
// A law-specific remedy (Prakash–Clifton at grazing) is the friction bounds' business: the sweeps tell
// them each node's open <-> closed changes (FrictionBounds::status_changed) and ask each node's bound anew.
#include <Eigen/Dense>
#include <optional>
#include <vector>

#include "contact/all_stick.hpp"
#include "contact/block_circulant_product.hpp"
#include "contact/coulomb_local.hpp"
#include "contact/friction_bounds.hpp"

namespace slidewave {

struct GaussSeidelReport {
  int iterations;   ///< sweeps of both passes (> max_iterations after a fallback)
  double residual;  ///< last sweep's max reaction change / force_scale
  bool converged;
  int n_bounds_released = 0;  ///< nodes whose given bound fell back to f r_y (FrictionBounds::n_released)
  double relaxation = 1;      ///< omega of the pass that produced r: 1, or kFallbackRelaxation
};

/// Relaxation of the fallback pass (see above). Of 300 000 random two- to four-node problems at f = 1, 2
/// (diagonal blocks), plain sweeps missed on 289, all solvable; omega = 0.5 solved 97 % of those,
/// symmetric (forward/backward) sweeps 26 %.
inline constexpr double kFallbackRelaxation = 0.5;

/// Sweeps in a row on a period-2 orbit after which the plain pass gives up (see above), watched from
/// sweep kCycleWatchFrom on (converging solves take 10-25 sweeps, up to ~740 in the campaign's runs).
inline constexpr int kCycleSweeps = 10;
inline constexpr int kCycleWatchFrom = 50;
/// Sweeps without halving the plain pass's smallest change after which it gives up (see above). Measured at
/// H/256 (nu 0.2, f 1.5, t_end 1000 s): 160 of 333 slip steps had plain passes whose change stayed at 1e-4 to
/// 1e-2 of the force scale, neither converging nor on a period-2 orbit (reactions two sweeps back 0.25-0.33 of
/// a sweep's change away), for all max_iterations = 2000 sweeps: 93 % of the run's sweeps. The slowest plain
/// pass that converged there halved its change every 60-200 sweeps (2.9e-6 at sweep 400, 4.6e-11 at 1800).
inline constexpr int kStallSweeps = 500;

struct GaussSeidelSettings {
  double tolerance = 1e-10;
  int max_iterations = 2000;
  double force_scale = 1.0;  ///< nominal nodal force (p0 h): residuals are relative to it
};

/// How W is read.
enum class DelassusLayout {
  dense,           ///< any SPD W: products with W itself
  block_circulant  ///< W as delassus_operator_periodic makes it: node updates through its two generating
                   ///< columns (delassus_periodic_columns), skipping the blocks that are round-off
                   ///< (beyond delassus_periodic_reach at kDelassusRoundOff; a W whose every block rises
                   ///< above it, e.g. lambda 2H at H/16, sweeps as the dense W does, bit for bit), the
                   ///< product W r by FFT (contact/block_circulant_product.hpp), and the exact all-stick
                   ///< solution (contact/all_stick.hpp)
};

class ContactSolver {
 public:
  /// @param W        Delassus operator (2n x 2n, symmetric positive definite); kept by reference: it must
  ///                 outlive the solver
  /// @param settings at most max_iterations plain sweeps, then at most max_iterations under-relaxed ones
  ContactSolver(const Eigen::MatrixXd& W, const GaussSeidelSettings& settings, DelassusLayout layout);

  /// Gauss–Seidel (see above).
  /// @param q      free local variables (r = 0)
  /// @param bounds the friction law's bounds of this solve (it learns the status changes of the sweeps)
  /// @param r      in: warm start; out: reactions
  /// @param state  out: per-node contact state
  GaussSeidelReport solve(const Eigen::VectorXd& q, FrictionBounds& bounds, Eigen::VectorXd& r,
                          std::vector<ContactState>& state) const;

  /// The exact all-stick solution r = -W^{-1} q, if it is closed and inside its bound at every node
  /// (AllStickSolution::solve; block-circulant W only, std::logic_error otherwise).
  bool solve_all_stick(const Eigen::VectorXd& q, const FrictionBounds& bounds, Eigen::VectorXd& r,
                       std::vector<ContactState>& state);

  /// y = q + W r (one product: the time loop does not ask for it).
  void local_variables(const Eigen::VectorXd& q, const Eigen::VectorXd& r, Eigen::VectorXd& y) const;

 private:
  /// One pass of at most max_iterations sweeps from the r passed in, each node's reaction moved by
  /// `relaxation` times the change of its exact local solve.
  GaussSeidelReport sweep_until_converged(const Eigen::VectorXd& q, FrictionBounds& bounds, double relaxation,
                                          Eigen::VectorXd& r, Eigen::VectorXd& y,
                                          std::vector<ContactState>& state) const;

  const Eigen::MatrixXd& W_;
  GaussSeidelSettings settings_;
  int n_nodes_;
  std::vector<LocalOperator> diagonal_blocks_;  ///< W's 2 x 2 diagonal blocks, factorized
  Eigen::MatrixXd periodic_columns_;            ///< delassus_periodic_columns(W) (block-circulant W), else empty
  int reach_ = 0;  ///< node distance beyond which W's blocks are round-off (delassus_periodic_reach)
  std::optional<BlockCirculantProduct> periodic_product_;  ///< W r by FFT (block-circulant W)
  std::optional<AllStickSolution> all_stick_;              ///< block-circulant W only
};

}  // namespace slidewave

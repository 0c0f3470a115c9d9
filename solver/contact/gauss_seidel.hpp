#pragma once
// Nonsmooth (projected) Gauss–Seidel for the frictional contact problem condensed on the contact DOFs:
//     y = q + W r,   node k: y_k = (du_x, u_y)_k, r_k = (r_x, r_y)_k  (layout 2k: x, 2k+1: y),
// with the local Signorini–Coulomb law of coulomb_local.hpp at every node. Each sweep solves every
// node exactly with the others frozen; y is updated in place (two columns of W per node), so a sweep
// costs O(n^2) (O(n) memory traffic when W is block-circulant and its two generating columns are
// passed: they fit in the cache where W does not; docs/contact-solver.md). Warm-started from the r passed in.
// Convergence: max_k |r_k(new) - r_k(old)| <= tolerance * force_scale over one sweep.
//
// Prakash–Clifton bounds (a given bound g_k per closed node) make the local law discontinuous at
// opening: |r_x| <= g_k while closed, however small r_y, and r = 0 once open. A node at grazing then
// can have no solution other than the grazing one (u_y = r_y = 0), which exact local solves never hit:
// through the coupling of W, its friction force opens it, opening removes the force, and it closes
// again, so the sweeps cycle for ever. A node whose open/closed status has changed more than
// kMaxStatusChanges times in one solve therefore gets the Coulomb bound f r_y (the Prakash–Clifton
// strength with the memory relaxed onto the current pressure, continuous at opening) for the rest of
// that solve. Coulomb problems (empty bounds) are not affected.
//
// Under-relaxed fallback. With a large f the friction force of one node can move a neighbour's gap
// more than its own pressure does; the exact local solves then overshoot the solution from both sides
// and the sweeps settle on a period-2 orbit around it (every other sweep repeats, the change per sweep
// stays put: seen at f = 2, H/128, just before slip onset, with stick <-> slip flips of a few nodes).
// If the plain sweeps miss the tolerance within max_iterations, or come back to the reactions of two
// sweeps before on kCycleSweeps sweeps in a row (the orbit, detected early), the solve restarts from the warm start
// with under-relaxed sweeps, r_k <- r_k + omega (r_k,local - r_k), omega = kFallbackRelaxation, for up
// to max_iterations more sweeps. The fixed points are the same (those of the exact local solves) and the
// residual is the unrelaxed change, so the tolerance means the same. A solve whose plain sweeps converge
// never reaches the fallback: its result is unchanged bit for bit. Neither pass is guaranteed to
// converge for large f (projected Gauss–Seidel has no such guarantee); the caller must check.
#include <Eigen/Dense>
#include <vector>

#include "contact/coulomb_local.hpp"

namespace slidewave {

struct GaussSeidelReport {
  int iterations;  ///< sweeps of both passes (> max_iterations after a fallback)
  double residual;  ///< last sweep's max reaction change / force_scale
  bool converged;
  int n_bounds_released = 0;  ///< nodes that fell back from their given bound to f r_y (cycling)
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

/// Status changes (open <-> closed) of one node in one solve after which its given bound is replaced
/// by f r_y. Genuine changes during convergence are one or two; cycles repeat without end.
inline constexpr int kMaxStatusChanges = 4;

struct GaussSeidelSettings {
  double tolerance = 1e-10;
  int max_iterations = 2000;
  double force_scale = 1.0;  ///< nominal nodal force (p0 h): residuals are relative to it
};

/// @param W      Delassus operator (2n x 2n, symmetric positive definite)
/// @param q      free local variables (r = 0)
/// @param f      friction coefficient
/// @param bounds if non-empty, a fixed friction bound per closed node (Prakash–Clifton), else f r_y;
///               a cycling node falls back to f r_y (see above)
/// @param settings at most max_iterations plain sweeps, then at most max_iterations under-relaxed ones
/// @param r      in: warm start; out: reactions
/// @param y_out  null, or out: local variables q + W r (one more product: the time loop does not ask)
/// @param state  out: per-node contact state
/// @param periodic_columns  null, or delassus_periodic_columns(W) when W is block-circulant: the in-place
///               updates of y and the products y = q + W r then read W's columns from it
///               (add_periodic_node_columns, periodic_residual: the same numbers and operations, so the
///               same result bit for bit, without streaming all of W through the cache)
GaussSeidelReport solve_contact_gauss_seidel(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                             const std::vector<double>& bounds, const GaussSeidelSettings& settings,
                                             Eigen::VectorXd& r, Eigen::VectorXd* y_out,
                                             std::vector<ContactState>& state,
                                             const Eigen::MatrixXd* periodic_columns = nullptr);

}  // namespace slidewave

#pragma once
// Nonsmooth (projected) Gauss–Seidel for the frictional contact problem condensed on the contact DOFs:
//     y = q + W r,   node k: y_k = (du_x, u_y)_k, r_k = (r_x, r_y)_k  (layout 2k: x, 2k+1: y),
// with the local Signorini–Coulomb law of coulomb_local.hpp at every node. Each sweep solves every
// node exactly with the others frozen; y is updated in place (two columns of W per node), so a sweep
// costs O(n^2). Warm-started from the r passed in.
// Convergence: max_k |r_k(new) - r_k(old)| <= tolerance * force_scale over one sweep.
#include <Eigen/Dense>
#include <vector>

#include "contact/coulomb_local.hpp"

namespace slidewave {

struct GaussSeidelReport {
  int iterations;
  double residual;  ///< last sweep's max reaction change / force_scale
  bool converged;
};

struct GaussSeidelSettings {
  double tolerance = 1e-10;
  int max_iterations = 2000;
  double force_scale = 1.0;  ///< nominal nodal force (p0 h): residuals are relative to it
};

/// @param W      Delassus operator (2n x 2n, symmetric positive definite)
/// @param q      free local variables (r = 0)
/// @param f      friction coefficient
/// @param bounds if non-empty, a fixed friction bound per node (Prakash–Clifton), else f r_y
/// @param r      in: warm start; out: reactions
/// @param y      out: local variables q + W r
/// @param state  out: per-node contact state
GaussSeidelReport solve_contact_gauss_seidel(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                             const std::vector<double>& bounds, const GaussSeidelSettings& settings,
                                             Eigen::VectorXd& r, Eigen::VectorXd& y,
                                             std::vector<ContactState>& state);

}  // namespace slidewave

#pragma once
// Condensation of a linear system K_eff u = F + C^T r onto the contact DOFs:
//     Z = K_eff^{-1} C^T  (n_free x n_c),   W = C K_eff^{-1} C^T = C Z  (the Delassus operator).
// C selects the contact DOFs, which are the first n_c free DOFs in the mesh numbering.
#include <Eigen/Dense>

#include "linalg/linear_solver.hpp"

namespace slidewave {

/// W by n_c solves (any mesh). Symmetrized to remove the round-off of the solves.
/// @param n_contact_dofs number of leading free DOFs that are contact DOFs
Eigen::MatrixXd delassus_operator(const LinearSolver& K_eff, int n_contact_dofs);

/// W by 2 solves, for an operator that is invariant under the periodic shift of the mesh by one column
/// (every uniform periodic layer): the response at contact node i to a unit load at contact node k is
/// the response at node i - k (mod n_x) to the load at node 0, so
///     W(2i + a, 2k + b) = [K_eff^{-1} e_{b}](2 ((i - k) mod n_x) + a).
/// Equal to delassus_operator() to round-off (tested).
Eigen::MatrixXd delassus_operator_periodic(const LinearSolver& K_eff, int n_contact_nodes);

/// The same W from the two responses it is made of: z_b (at least 2 n entries, the contact DOFs first) the
/// displacement under a unit load on DOF b of contact node 0; filled by the shift and symmetrized.
Eigen::MatrixXd delassus_from_node_responses(const Eigen::VectorXd& z0, const Eigen::VectorXd& z1, int n_contact_nodes);

/// The two columns of node 0 of a block-circulant W (as delassus_operator_periodic makes it, symmetrized
/// and still exactly block-circulant), stacked twice: a 4n x 2 matrix C with
///     W(:, 2k + b) = C.col(b).segment(2 ((n - k) mod n), 2n),
/// the same numbers bit for bit, in 2n x 2 storage instead of 2n x 2n (what the Gauss–Seidel sweeps
/// read for their in-place updates, contact/contact_solver.hpp).
Eigen::MatrixXd delassus_periodic_columns(const Eigen::MatrixXd& W);

// ---- The Gauss–Seidel node update with a block-circulant W read from its generating columns ----
// The in-place update of the Gauss–Seidel contact solve (contact/contact_solver.hpp) with a block-circulant
// Delassus operator W, computed from its two generating columns (delassus_periodic_columns, a 4n x 2
// matrix C with W(:, 2k + b) = C.col(b).segment(2 ((n - k) mod n), 2n)) instead of the dense 2n x 2n W:
// C fits in the cache where W does not.
//
// The loops are compiled for AVX2 and AVX-512 next to the baseline ISA (GCC function multiversioning,
// chosen at load time) with floating-point contraction off, so no fused multiply-add changes a rounding:
// the results do not depend on the ISA that runs them (tested against the dense product to round-off).

/// y += W(:, 2k..2k+1) (d0, d1), as Eigen's y += W.middleCols<2>(2k) * Vector2d(d0, d1):
/// y_i += C(s + i, 0) d0 + C(s + i, 1) d1 with s = 2 ((n - k) mod n), for the nodes i within `reach` nodes
/// of k (periodically); y_i of the nodes beyond are left as they are. reach >= n / 2: every node, the
/// product above bit for bit; a smaller reach skips the blocks that delassus_periodic_reach found to be
/// round-off (the same operations on every node it keeps).
/// @param columns delassus_periodic_columns(W), 4n x 2;  @param k node, 0 <= k < n_nodes
void add_periodic_node_columns(const Eigen::MatrixXd& columns, int n_nodes, int k, int reach, double d0, double d1,
                               Eigen::VectorXd& y);

/// Relative size below which an entry of a block-circulant W is round-off (delassus_periodic_reach).
/// The time loop's W decays with distance (an implicit step's response is local: over a fixed length, a
/// few times c dt, so by ~0.6 per node at H/128 and the default dt) until it reaches the noise of the FFT
/// solves that computed it, ~1e-17..6e-17 of the largest entry at H/128 (measured): entries below 1e-15
/// of it are that noise or within 16-100 times it; what a sweep leaves out by skipping them is 1e5 times
/// below the contact tolerance (1e-10 of p0 h). Reach at the default dt (lambda 2H and 6H alike): 25 nodes
/// at H/32, 33 at H/64, 67 at H/128, 135 at H/256.
inline constexpr double kDelassusRoundOff = 1e-15;

/// The largest node distance d (at most n / 2) at which a 2 x 2 block of the block-circulant W given by
/// its generating columns has an entry above relative_floor times W's largest entry: the reach of the
/// Gauss–Seidel updates (add_periodic_node_columns). n / 2 or more when no block falls below it.
int delassus_periodic_reach(const Eigen::MatrixXd& columns, int n_nodes, double relative_floor);

}  // namespace slidewave

#pragma once
// The deformable substrate (config group `substrate`, docs/substrate.md): a second periodic elastic
// layer below the interface, built like the layer in mirrored coordinates
//     y' = -y,   u_y' = -u_y,
// in which it occupies 0 <= y' <= H_s: its interface row is its row j = 0 (its "contact" DOFs, numbered
// first like the layer's) and its held bottom (u = 0) its prescribed row j = n_y. A reflection is
// orthogonal and the material isotropic, so the element matrices in the mirrored frame are the layer's
// (quad4_stiffness, quad4_mass of the substrate's E, nu, rho and the same h): the substrate is a LayerModel
// of its own configuration (substrate_body_config) and runs with its own HHT stepper and FFT split solver.
//
// The pair shares one contact force r per interface node pair, in the layer's frame (r acts on the layer,
// -r on the substrate). With S = diag(-1, +1) per node (the mirroring of x-components under "minus r"):
//     force on the substrate, mirrored frame   S r = (-r_x, r_y)
//     relative displacement (layer - substrate, physical)   u_rel = C u_L + S C u_S'
//                                                            = (u_Lx - u_Sx, u_Ly + u_Sy')
// so the pair's contact problem is y = q + W_pair r with
//     q = q_L + S q_S,   W_pair = W_L + S W_S S
// (W_S the substrate's Delassus operator in its own frame): symmetric positive definite and still
// block-circulant, so the all-stick solve and periodic Gauss–Seidel apply unchanged, with every friction
// law (they see only y and r). A rigid flat is W_S = 0, q_S = 0.
#include <Eigen/Dense>

#include "config/run_config.hpp"

namespace slidewave {

/// The substrate's own RunConfig (the mirrored body as a layer): its material, height H_s and n_y =
/// H_s / h elements of the layer's size h, the layer's period (n_x) and time step, no substrate.
/// Precondition: layer.substrate.present().
RunConfig substrate_body_config(const RunConfig& layer);

/// v := S v on every node pair (x-components negated): a layer-frame contact force to the substrate's
/// mirrored frame, or a substrate contact displacement (mirrored) to its share of the relative one.
void mirror_x_components(Eigen::VectorXd& v);

/// W_L + S W_S S (both 2n x 2n, the same node order).
Eigen::MatrixXd pair_delassus(const Eigen::MatrixXd& W_layer, const Eigen::MatrixXd& W_substrate);

/// The relative contact displacement C u_L + S C u_S' (n_contact_dofs entries) of the full DOF vectors.
Eigen::VectorXd relative_contact_displacement(const Eigen::VectorXd& u_layer, const Eigen::VectorXd& u_substrate,
                                              int n_contact_dofs);

}  // namespace slidewave

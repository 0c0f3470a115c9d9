#pragma once
// Bilinear square element (side h, unit depth), plane strain, small strain, isotropic.
// Local DOF order: (u_x, u_y) of nodes 1..4, counter-clockwise from the lower-left corner.
#include <Eigen/Dense>

#include "config/run_config.hpp"

namespace slidewave {

using Matrix8 = Eigen::Matrix<double, 8, 8>;

/// Plane-strain elasticity matrix in Voigt order (xx, yy, xy with engineering shear).
Eigen::Matrix3d plane_strain_elasticity(double E, double nu);

/// Element stiffness.
///  - full: 2x2 Gauss quadrature.
///  - reduced_pure: 1-point quadrature, K = A B0^T D B0; has two zero-energy hourglass modes.
///  - reduced: 1 point plus the assumed-strain (ASQBI, Belytschko & Bindeman 1991) stabilization.
///    For a square the hourglass mode u = q xi eta e_d gets the strain eps_dd = q eta_d / a,
///    eps_ee = -nu/(1-nu) eps_dd, no shear, whose energy is the exact pure-bending energy
///    (1/2) E' (4/3) q^2 with E' = E/(1-nu^2); no volumetric or shear locking.
Matrix8 quad4_stiffness(double E, double nu, double h, Integration integration);

/// Element mass: consistent (exact integration of N_i N_j) or row-sum lumped (`redistributed` is consistent here:
/// fem/mass_redistribution.hpp changes the bottom row of elements).
Matrix8 quad4_mass(double rho, double h, MassKind kind);

}  // namespace slidewave

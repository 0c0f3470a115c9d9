#pragma once
// Mass redistribution at the contact (`mesh.mass = "redistributed"`): the contact nodes' inertia is moved onto
// the nodes above them (Khenous, Laborde & Renard, Eur. J. Mech. A/Solids 27, 2008). With mass on the contact
// nodes, exact Signorini–Coulomb enforcement lets long unregularized runs create energy once c_s dt / h is
// small (docs/physics-notes.md, section 8); without it they stay dissipative at every step measured.
// The bottom row of elements carries its mass on its top edge (the consistent mass of that edge: total mass
// rho h^2 kept, split 2:1 between the edge's own node and its neighbour); a residual share of the consistent
// element mass stays so that M remains positive definite (the initial acceleration and the HHT step solve with
// it): the contact nodes keep 1e-6 of their inertia.
#include "fem/assembly.hpp"
#include "fem/quad4.hpp"
#include "mesh/layer_mesh.hpp"

namespace slidewave {

/// The share of the consistent element mass the bottom row of elements keeps.
constexpr double kContactResidualMass = 1e-6;

/// Mass of an element of the bottom row (side h): kContactResidualMass of the consistent mass plus the rest on
/// its top edge (local nodes 3, 4), consistent along the edge.
Matrix8 quad4_contact_row_mass(double rho, double h);

/// Adds, for every element of the bottom row, (its mass - the consistent element mass) to M, a matrix of the
/// layer's DOFs restricted to `rows` x `cols` (entries outside those ranges are left out). M must hold the
/// consistent mass's sparsity (every element coupling): only existing entries change.
void redistribute_contact_mass(const LayerMesh& mesh, double rho, RowSparseMatrix& M, DofRange rows, DofRange cols);
void redistribute_contact_mass(const LayerMesh& mesh, double rho, SparseMatrix& M, DofRange rows, DofRange cols);

}  // namespace slidewave

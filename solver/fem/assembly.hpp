#pragma once
// Global stiffness and mass of the periodic layer (all DOFs, mesh numbering of layer_mesh.hpp).
#include <Eigen/Sparse>

#include "fem/quad4.hpp"
#include "mesh/layer_mesh.hpp"

namespace slidewave {

using SparseMatrix = Eigen::SparseMatrix<double>;

/// Assembles the same element matrix over every element (the mesh is uniform).
SparseMatrix assemble_uniform(const LayerMesh& mesh, const Matrix8& element_matrix);

}  // namespace slidewave

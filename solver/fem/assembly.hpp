#pragma once
// Global stiffness and mass of the periodic layer (mesh numbering of layer_mesh.hpp), assembled straight
// into compressed storage: the mesh is uniform and structured, so every row's columns are the DOFs of the
// (up to) nine nodes around its node, known without a triplet list, a sort or a storage conversion.
// Each entry is the sum of its elements' contributions in ascending element order, zero contributions
// skipped and an entry with none left out: the numbers, bit for bit, of Eigen's setFromTriplets over the
// elements in order (tested against it), at a fraction of the time and memory of a layer's setup.
#include <Eigen/Sparse>

#include "fem/quad4.hpp"
#include "mesh/layer_mesh.hpp"

namespace slidewave {

using SparseMatrix = Eigen::SparseMatrix<double>;
/// Row-major storage: the matrices that are only multiplied with vectors (faster, no scatter).
using RowSparseMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// A half-open range of global DOFs [begin, end).
struct DofRange {
  int begin, end;
  int size() const { return end - begin; }
};

/// The block (rows x cols) of the matrix that assembles element_matrix over every element, indices
/// relative to the block.
RowSparseMatrix assemble_uniform_rows(const LayerMesh& mesh, const Matrix8& element_matrix, DofRange rows,
                                      DofRange cols);
/// The same block in column-major storage (what the factorizations take).
SparseMatrix assemble_uniform_columns(const LayerMesh& mesh, const Matrix8& element_matrix, DofRange rows,
                                      DofRange cols);

/// All DOFs, column-major.
SparseMatrix assemble_uniform(const LayerMesh& mesh, const Matrix8& element_matrix);

/// y = A(0:n, 0:n) x, x of size n: the product with the leading n x n block of a row-major A (the free-free
/// block of a matrix on all DOFs: the free DOFs come first), each row's entries in column order, those of the
/// columns beyond n skipped; the operations of Eigen's product of that block as a matrix of its own (a sum from
/// 0 per row, added to a zero), so the same bits as assembling the block and multiplying it.
Eigen::VectorXd leading_block_product(const RowSparseMatrix& A, Eigen::Index n,
                                      const Eigen::Ref<const Eigen::VectorXd>& x);

}  // namespace slidewave

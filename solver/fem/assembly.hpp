#pragma once
// Global stiffness and mass of the periodic layer (mesh numbering of layer_mesh.hpp), assembled straight
// into compressed storage: the mesh is uniform and structured, so every row's columns are the DOFs of the
// (up to) nine nodes around its node, known without a triplet list, a sort or a storage conversion.
// Each entry is the sum of its elements' contributions in ascending element order, zero contributions
// skipped and an entry with none left out: the numbers, bit for bit, of Eigen's setFromTriplets over the
// elements in order (tested against it), at a fraction of the time and memory of a layer's setup.
#include <Eigen/Sparse>
#include <array>
#include <vector>

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

/// The rows of the matrix that assembles one element matrix over every element of the uniform mesh, known
/// without storing them: nodes of one class (first, inner or last mesh column; bottom, inner or top mesh row)
/// have the same elements around them in the same order, so the same row blocks up to a shift of the
/// neighbours, computed once per class. The assembly below stores its rows from here; the product reads the
/// same entries in the same order, so it gives the bits of the assembled matrix's product without the matrix.
class UniformRows {
 public:
  UniformRows(const LayerMesh& mesh, const Matrix8& element_matrix);

  /// f(column, value) for the stored entries of row `dof` whose column is in `cols`, in ascending column order.
  template <typename F>
  void for_each_entry(int dof, DofRange cols, F&& f) const {
    const int base = dof - dof % 2;  // 2 p: the row's node's first DOF
    for (const Entry& e : row_entries(dof)) {
      const int column = base + e.offset;
      if (column >= cols.begin && column < cols.end) f(column, e.value);
    }
  }

  /// y = A(rows, cols) x (x of size cols.size()): Eigen's product of the block as a row-major matrix of its own
  /// (per row a sum from 0 over its entries in column order, added to a zero), so the same bits. The rows of
  /// inner-column nodes are summed eight nodes at a time, each row its own sum (vectorized across the nodes).
  Eigen::VectorXd product(DofRange rows, DofRange cols, const Eigen::Ref<const Eigen::VectorXd>& x) const;

  /// The block (rows x cols), indices relative to it; with `node_columns`, only the rows of the nodes in those
  /// mesh columns are stored (the others empty).
  RowSparseMatrix rows(DofRange rows, DofRange cols, const std::vector<int>& node_columns = {}) const;

 private:
  /// A stored entry of row 2 p + d: column 2 p + offset.
  struct Entry {
    int offset;
    double value;
  };
  int node_class(int p) const {
    const int i = p % n_x_, j = p / n_x_;
    return 3 * (i == 0 ? 0 : (i == n_x_ - 1 ? 2 : 1)) + (j == 0 ? 0 : (j == n_y_ ? 2 : 1));
  }
  /// The entries of row `dof` in ascending column order: its node's class's, component dof % 2.
  const std::vector<Entry>& row_entries(int dof) const { return class_rows_[2 * node_class(dof / 2) + dof % 2]; }

  int n_x_, n_y_;
  std::array<std::vector<Entry>, 18> class_rows_;  ///< [2 class + d]
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

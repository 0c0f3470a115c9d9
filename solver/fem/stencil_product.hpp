#pragma once
// K u without the sparse matrix, for a stiffness that repeats along a periodic mesh row: the product the
// HHT stepper does once per step (time/hht_stepper.hpp), bitwise equal to Eigen's row-major `K * u`.
//
// Structure used. DOF numbering 2 (j n_x + i) + d of mesh/layer_mesh.hpp (node i of mesh row j, component d).
// K assembled from one element matrix on the uniform periodic mesh (fem/assembly.hpp) couples node (i, j) to
// the nodes (i +- 1, j +- 1) with coefficients that depend on j (bottom, interior and top rows differ) but
// not on i. So every row of an interior node i in [1, n_x - 2] is the row of node (1, j) shifted by
// 2 (i - 1) columns: a few coefficients per mesh row replace the n_x copies stored in K.
//
// Bitwise equality. Eigen's row-major sparse * dense computes, for each row k, tmp = 0, then
// tmp += K(k, c) u(c) over the stored entries in increasing column c (each product rounded, then added),
// and Ku(k) = 0 + 1 * tmp (= tmp: tmp starts at +0, so it is never -0). apply() gives each output the same
// terms in the same order (the stored order of K, explicit zeros included), so the rounding is the same:
//   - interior nodes: the template row's entries in its stored order, one entry at a time over a block of
//     8 nodes whose sums stay in registers; the coefficients are fixed across the block, so it vectorizes
//     across x (the lanes are different outputs: the two rows of a node; each keeps its order);
//   - the seam nodes i = 0 and i = n_x - 1, whose periodic neighbour has the larger (smaller) index and
//     so comes last (first) in column order: their rows of K, copied as they are stored.
// Neither this product nor Eigen's may be contracted to fused multiply-adds (the build has no -mfma or
// -march, so neither is); tests/solver/stencil_product_test.cpp checks the equality with memcmp.
//
// When not to use: K with entries that differ along x (graded mesh, x-dependent material), or a numbering
// other than the one above; the constructor then refuses K (std::invalid_argument), and the sparse product is
// the one to use.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <vector>

namespace slidewave {

class StencilProduct {
 public:
  /// Reads the coefficients from K and checks that every stored entry of every interior node's rows repeats
  /// the row of node (1, j) (same columns shifted by 2 (i - 1), bitwise equal values, same count), and that
  /// the two rows of a node (d = 0, 1) store the same columns.
  /// @param K    square, all DOFs, numbered 2 (j n_x + i) + d; K.rows() a multiple of 2 n_x
  /// @param n_x  nodes per mesh row (the period), >= 1 (n_x < 3: every row is a seam row, kept as stored)
  /// @throws std::invalid_argument naming the first row and entry that break the structure
  StencilProduct(const Eigen::SparseMatrix<double, Eigen::RowMajor>& K, int n_x);

  /// Ku = K u, bitwise equal to Eigen's `Ku.noalias() = K * u`. u and Ku must be distinct vectors of size
  /// n_dofs() (Ku is resized if needed).
  void apply(const Eigen::VectorXd& u, Eigen::VectorXd& Ku) const;

  int n_x() const { return n_x_; }
  int n_rows_of_nodes() const { return n_rows_of_nodes_; }  ///< mesh rows, n_y + 1
  int n_dofs() const { return 2 * n_x_ * n_rows_of_nodes_; }

 private:
  /// A row of K as stored (seam nodes).
  struct StoredRow {
    int row;
    int begin, end;  ///< range in seam_columns_, seam_values_
  };

  void apply_interior(int j, const double* __restrict u, double* __restrict Ku) const;

  int n_x_, n_rows_of_nodes_;
  /// Slot s = one stored column of the rows of an interior node (i, j), in stored order: column
  /// 2 (j n_x + i) + 2 + slot_offsets_[s] - 2, coefficient slot_c_x_[s] in row d = 0, slot_c_y_[s] in d = 1.
  /// The slots of mesh row j are [slot_begin_[j], slot_begin_[j + 1]).
  std::vector<int> slot_begin_, slot_offsets_;
  std::vector<double> slot_c_x_, slot_c_y_;
  std::vector<StoredRow> seam_rows_;
  std::vector<int> seam_columns_;
  std::vector<double> seam_values_;
};

}  // namespace slidewave

#include "fem/assembly.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

namespace slidewave {

namespace {

/// One neighbour node q of a row node: the 2 x 2 block (d, d') of entries (2p + d, 2q + d'), and which
/// of them received a nonzero contribution.
struct NeighbourBlock {
  int node;
  std::array<std::array<double, 2>, 2> value{};
  std::array<std::array<bool, 2>, 2> present{};
};

/// The nonzero 2 x 2 blocks of node p's two rows, by ascending neighbour node: the elements around p in
/// ascending element order, each adding Ke(2a + d, 2b + d') (a: p's corner, b: q's corner).
void row_blocks(const LayerMesh& mesh, const Matrix8& Ke, int p, std::vector<NeighbourBlock>& blocks) {
  blocks.clear();
  const int pi = p % mesh.n_x, pj = p / mesh.n_x;
  std::array<int, 4> elements{};
  int n_elements = 0;
  for (int ej = pj - 1; ej <= pj; ++ej)
    for (int ei = pi - 1; ei <= pi; ++ei)
      if (ej >= 0 && ej < mesh.n_y) {
        // insertion in ascending order (the wrapped element of the first column comes last in its row)
        int k = n_elements++;
        const int e = ej * mesh.n_x + (ei + mesh.n_x) % mesh.n_x;
        for (; k > 0 && elements[k - 1] > e; --k) elements[k] = elements[k - 1];
        elements[k] = e;
      }
  for (int k = 0; k < n_elements; ++k) {
    const std::array<int, 4> nodes = mesh.element_nodes(elements[k]);
    const int a = static_cast<int>(std::find(nodes.begin(), nodes.end(), p) - nodes.begin());
    for (int b = 0; b < 4; ++b) {
      auto it = std::find_if(blocks.begin(), blocks.end(), [&](const NeighbourBlock& s) { return s.node == nodes[b]; });
      if (it == blocks.end()) it = blocks.insert(blocks.end(), NeighbourBlock{nodes[b]});
      for (int d = 0; d < 2; ++d)
        for (int e = 0; e < 2; ++e) {
          const double v = Ke(2 * a + d, 2 * b + e);
          if (v == 0) continue;
          it->value[d][e] = it->present[d][e] ? it->value[d][e] + v : v;
          it->present[d][e] = true;
        }
    }
  }
  std::sort(blocks.begin(), blocks.end(),
            [](const NeighbourBlock& x, const NeighbourBlock& y) { return x.node < y.node; });
}

/// The block in the storage of Matrix: each outer vector (a row of a row-major block, a column of a
/// column-major one) is a row of the matrix that assembles Ke_outer (Ke for rows, Ke^T for columns: the
/// same sums in the same element order), its outer DOFs in `outer`, its inner DOFs in `inner`.
template <typename Matrix>
Matrix assemble_outer_vectors(const LayerMesh& mesh, const Matrix8& Ke_outer, DofRange outer, DofRange inner) {
  // Nodes of one class (first, inner or last column; bottom, inner or top row) have the same elements
  // around them in the same order, so the same row blocks up to a shift of the neighbour ids: each class's
  // blocks are computed once, at its first node, as offsets from it.
  const auto class_of = [&](int p) {
    const int i = p % mesh.n_x, j = p / mesh.n_x;
    return 3 * (i == 0 ? 0 : (i == mesh.n_x - 1 ? 2 : 1)) + (j == 0 ? 0 : (j == mesh.n_y ? 2 : 1));
  };
  std::array<std::vector<NeighbourBlock>, 9> class_blocks;  // neighbour node stored as offset from p
  std::array<bool, 9> known{};
  Matrix A(Matrix::IsRowMajor ? outer.size() : inner.size(), Matrix::IsRowMajor ? inner.size() : outer.size());
  A.reserve(static_cast<Eigen::Index>(outer.size()) * 18);  // nine nodes, two DOFs each
  for (int dof = outer.begin; dof < outer.end; ++dof) {
    const int p = dof / 2, d = dof % 2, c = class_of(p);
    if (!known[c]) {
      row_blocks(mesh, Ke_outer, p, class_blocks[c]);
      for (NeighbourBlock& s : class_blocks[c]) s.node -= p;
      known[c] = true;
    }
    A.startVec(dof - outer.begin);
    for (const NeighbourBlock& s : class_blocks[c])
      for (int e = 0; e < 2; ++e) {
        const int other = 2 * (p + s.node) + e;
        if (s.present[d][e] && other >= inner.begin && other < inner.end)
          A.insertBackByOuterInner(dof - outer.begin, other - inner.begin) = s.value[d][e];
      }
  }
  A.finalize();
  return A;
}

}  // namespace

RowSparseMatrix assemble_uniform_rows(const LayerMesh& mesh, const Matrix8& Ke, DofRange rows, DofRange cols) {
  return assemble_outer_vectors<RowSparseMatrix>(mesh, Ke, rows, cols);
}

SparseMatrix assemble_uniform_columns(const LayerMesh& mesh, const Matrix8& Ke, DofRange rows, DofRange cols) {
  // Column j of the block is row j of the transposed block, which assembles Ke^T.
  return assemble_outer_vectors<SparseMatrix>(mesh, Ke.transpose(), cols, rows);
}

SparseMatrix assemble_uniform(const LayerMesh& mesh, const Matrix8& Ke) {
  return assemble_uniform_columns(mesh, Ke, {0, mesh.n_dofs()}, {0, mesh.n_dofs()});
}

Eigen::VectorXd leading_block_product(const RowSparseMatrix& A, Eigen::Index n,
                                      const Eigen::Ref<const Eigen::VectorXd>& x) {
  if (n > A.rows() || n > A.cols() || x.size() != n)
    throw std::invalid_argument("leading_block_product: the block or x does not fit the matrix");
  Eigen::VectorXd y(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    double sum = 0;  // Eigen's processRow: tmp = 0, tmp += a x over the row, then y(i) = 0 + 1 tmp
    for (RowSparseMatrix::InnerIterator it(A, i); it && it.index() < n; ++it) sum += it.value() * x(it.index());
    y(i) = 0.0 + sum;  // (1 tmp is tmp; 0 + keeps Eigen's +0 for a -0 sum)
  }
  return y;
}

}  // namespace slidewave

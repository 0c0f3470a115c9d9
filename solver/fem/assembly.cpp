#include "fem/assembly.hpp"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <vector>

#include "linalg/vector_clones.hpp"

namespace slidewave {

namespace {

/// One neighbour node q of a row node: the 2 x 2 block (d, d') of entries (2p + d, 2q + d'), and which
/// of them received a nonzero contribution.
struct NodeBlock {
  int node;
  std::array<std::array<double, 2>, 2> value{};
  std::array<std::array<bool, 2>, 2> present{};
};

/// The nonzero 2 x 2 blocks of node p's two rows, by ascending neighbour node: the elements around p in
/// ascending element order, each adding Ke(2a + d, 2b + d') (a: p's corner, b: q's corner).
std::vector<NodeBlock> row_blocks(const LayerMesh& mesh, const Matrix8& Ke, int p) {
  std::vector<NodeBlock> blocks;
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
      auto it = std::find_if(blocks.begin(), blocks.end(), [&](const NodeBlock& s) { return s.node == nodes[b]; });
      if (it == blocks.end()) it = blocks.insert(blocks.end(), NodeBlock{nodes[b]});
      for (int d = 0; d < 2; ++d)
        for (int e = 0; e < 2; ++e) {
          const double v = Ke(2 * a + d, 2 * b + e);
          if (v == 0) continue;
          it->value[d][e] = it->present[d][e] ? it->value[d][e] + v : v;
          it->present[d][e] = true;
        }
    }
  }
  std::sort(blocks.begin(), blocks.end(), [](const NodeBlock& x, const NodeBlock& y) { return x.node < y.node; });
  return blocks;
}

}  // namespace

UniformRows::UniformRows(const LayerMesh& mesh, const Matrix8& Ke) : n_x_(mesh.n_x), n_y_(mesh.n_y) {
  // Each class's rows at its first node: its neighbours in ascending order, each one's two columns in order.
  std::array<bool, 9> known{};
  for (int p = 0; p < mesh.n_x * (mesh.n_y + 1); ++p) {
    const int c = node_class(p);
    if (known[c]) continue;
    for (const NodeBlock& b : row_blocks(mesh, Ke, p))
      for (int d = 0; d < 2; ++d)
        for (int e = 0; e < 2; ++e)
          if (b.present[d][e]) class_rows_[2 * c + d].push_back({2 * (b.node - p) + e, b.value[d][e]});
    known[c] = true;
  }
}

namespace {

/// Nodes whose sums stay in registers at once (as fem/stencil_product.cpp's block).
constexpr int kBlockNodes = 8;

/// y[2 b] = sum over `entries` in order of value x[2 b + offset], b < n_nodes (kBlockNodes when kFull, else
/// fewer): one component's rows of consecutive nodes of one class, x and y at the first node's row; each sum
/// from 0, in the row's own order. kFull gives the compiler a fixed trip count to vectorize.
template <bool kFull, typename Entry>
inline void sum_node_block(const Entry* entries, int n_entries, const double* __restrict x, double* __restrict y,
                           int n_nodes) {
  double sum[kBlockNodes] = {};
  for (int e = 0; e < n_entries; ++e) {
    const double value = entries[e].value;
    const double* __restrict in = x + entries[e].offset;
    for (int b = 0; b < kBlockNodes; ++b) {
      if (!kFull && b >= n_nodes) break;
      sum[b] += value * in[2 * b];
    }
  }
  for (int b = 0; b < n_nodes; ++b) y[2 * b] = sum[b];
}

}  // namespace

SLIDEWAVE_VECTOR_CLONES
Eigen::VectorXd UniformRows::product(DofRange rows, DofRange cols, const Eigen::Ref<const Eigen::VectorXd>& x) const {
  if (x.size() != cols.size()) throw std::invalid_argument("UniformRows::product: x does not fit the columns");
  Eigen::VectorXd y(rows.size());
  const double* x_data = x.data();
  for (int row = rows.begin; row < rows.end;) {
    const int p = row / 2, i = p % n_x_;
    // Inner-column nodes from p on whose two rows are in the block and whose entries are all in cols: their
    // rows are one class's, shifted, so they are summed a block of nodes at a time (the same operations).
    int last = row % 2 == 0 && i >= 1 ? std::min(p + n_x_ - 2 - i, rows.end / 2 - 1) : p - 1;
    for (int d = 0; d < 2 && last >= p; ++d) {
      const std::vector<Entry>& entries = row_entries(2 * p + d);
      if (entries.empty() || 2 * p + entries.front().offset < cols.begin) {
        last = p - 1;
      } else {
        const int room = cols.end - 1 - entries.back().offset;  // a node q's last column is 2 q + that offset
        last = room < 2 * p ? p - 1 : std::min(last, room / 2);
      }
    }
    if (last >= p) {
      for (int d = 0; d < 2; ++d) {
        const std::vector<Entry>& entries = row_entries(2 * p + d);
        const int n = static_cast<int>(entries.size());
        for (int q = p; q <= last; q += kBlockNodes) {
          const double* in = x_data + (2 * q - cols.begin);
          double* out = y.data() + (2 * q + d - rows.begin);
          if (last - q + 1 >= kBlockNodes)
            sum_node_block<true>(entries.data(), n, in, out, kBlockNodes);
          else
            sum_node_block<false>(entries.data(), n, in, out, last - q + 1);
        }
      }
      row = 2 * (last + 1);
      continue;
    }
    // The first and last mesh columns, and rows reaching out of cols: row by row.
    double sum = 0;  // Eigen's processRow: tmp = 0, tmp += a x over the row, then y(i) = 0 + 1 tmp
    for_each_entry(row, cols, [&](int column, double value) { sum += value * x_data[column - cols.begin]; });
    y(row - rows.begin) = sum;  // 0 + 1 tmp is tmp: a sum from +0 is never -0
    ++row;
  }
  return y;
}

RowSparseMatrix UniformRows::rows(DofRange rows, DofRange cols, const std::vector<int>& node_columns) const {
  RowSparseMatrix A(rows.size(), cols.size());
  A.reserve(static_cast<Eigen::Index>(node_columns.empty() ? rows.size() : 2 * node_columns.size() * (n_y_ + 1)) *
            18);  // nine nodes, two DOFs each
  for (int dof = rows.begin; dof < rows.end; ++dof) {
    A.startVec(dof - rows.begin);
    const int i = (dof / 2) % n_x_;
    if (!node_columns.empty() && std::find(node_columns.begin(), node_columns.end(), i) == node_columns.end()) continue;
    for_each_entry(dof, cols, [&](int column, double value) {
      A.insertBackByOuterInner(dof - rows.begin, column - cols.begin) = value;
    });
  }
  A.finalize();
  return A;
}

RowSparseMatrix assemble_uniform_rows(const LayerMesh& mesh, const Matrix8& Ke, DofRange rows, DofRange cols) {
  return UniformRows(mesh, Ke).rows(rows, cols);
}

SparseMatrix assemble_uniform_columns(const LayerMesh& mesh, const Matrix8& Ke, DofRange rows, DofRange cols) {
  // Column j of the block is row j of the transposed block, which assembles Ke^T: the row-major storage of
  // that block is the column-major storage of this one.
  const RowSparseMatrix transposed = UniformRows(mesh, Ke.transpose()).rows(cols, rows);
  return Eigen::Map<const SparseMatrix>(transposed.cols(), transposed.rows(), transposed.nonZeros(),
                                        transposed.outerIndexPtr(), transposed.innerIndexPtr(), transposed.valuePtr());
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
    y(i) = sum;  // 0 + 1 tmp is tmp: a sum from +0 is never -0
  }
  return y;
}

}  // namespace slidewave

#include "fem/stencil_product.hpp"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

#include "linalg/vector_clones.hpp"

namespace slidewave {
namespace {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

struct Entry {
  int column;
  double value;
};

std::vector<Entry> stored_row(const RowMatrix& K, int row) {
  std::vector<Entry> entries;
  for (RowMatrix::InnerIterator it(K, row); it; ++it) entries.push_back({static_cast<int>(it.index()), it.value()});
  return entries;
}

/// Bitwise, so that -0 and +0 (which round the same but are not the same stored entry) count as different.
bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

std::string number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

std::string row_name(int row, int n_x) {
  const int node = row / 2;
  return "row " + std::to_string(row) + " (node i = " + std::to_string(node % n_x) +
         ", j = " + std::to_string(node / n_x) + ", d = " + std::to_string(row % 2) + ")";
}

[[noreturn]] void refuse(int n_x, const std::string& what) {
  throw std::invalid_argument("StencilProduct: K is not a stencil periodic in x with n_x = " + std::to_string(n_x) +
                              " nodes per mesh row: " + what);
}

}  // namespace

StencilProduct::StencilProduct(const RowMatrix& K, int n_x) : n_x_(n_x) {
  if (n_x < 1) throw std::invalid_argument("StencilProduct: n_x = " + std::to_string(n_x) + "; must be >= 1");
  if (K.rows() != K.cols() || K.rows() == 0 || K.rows() % (2 * n_x) != 0)
    refuse(n_x, "K is " + std::to_string(K.rows()) + " x " + std::to_string(K.cols()) +
                    "; it must be square with a positive multiple of 2 n_x rows");
  n_rows_of_nodes_ = static_cast<int>(K.rows()) / (2 * n_x);

  slot_begin_.push_back(0);
  for (int j = 0; j < n_rows_of_nodes_; ++j) {
    const int row_of_node_0 = 2 * j * n_x;
    // Interior nodes i in [1, n_x - 2]: the rows of node (1, j) are the template.
    if (n_x >= 3) {
      const int template_row = row_of_node_0 + 2;
      const std::vector<Entry> row_x = stored_row(K, template_row), row_y = stored_row(K, template_row + 1);
      if (row_x.size() != row_y.size())
        refuse(n_x, row_name(template_row, n_x) + " stores " + std::to_string(row_x.size()) + " entries, " +
                        row_name(template_row + 1, n_x) + " " + std::to_string(row_y.size()) +
                        "; the two rows of a node must store the same columns");
      for (size_t k = 0; k < row_x.size(); ++k) {
        if (row_x[k].column != row_y[k].column)
          refuse(n_x, "entry " + std::to_string(k) + " of " + row_name(template_row, n_x) + " is in column " +
                          std::to_string(row_x[k].column) + ", of " + row_name(template_row + 1, n_x) + " in column " +
                          std::to_string(row_y[k].column) + "; the two rows of a node must store the same columns");
        slot_offsets_.push_back(row_x[k].column - template_row);
        slot_c_x_.push_back(row_x[k].value);
        slot_c_y_.push_back(row_y[k].value);
      }
      for (int i = 2; i <= n_x - 2; ++i)
        for (int d = 0; d < 2; ++d) {
          const int row = row_of_node_0 + 2 * i + d;
          const std::vector<Entry> entries = stored_row(K, row);
          const size_t n_slots = row_x.size();
          for (size_t k = 0; k < std::max(entries.size(), n_slots); ++k) {
            if (k >= entries.size() || k >= n_slots)
              refuse(n_x, row_name(row, n_x) + " stores " + std::to_string(entries.size()) +
                              " entries, the row of node (1, " + std::to_string(j) + ") " + std::to_string(n_slots));
            const int s = slot_begin_.back() + static_cast<int>(k);
            const int column = row_of_node_0 + 2 * i + slot_offsets_[s];
            const double value = d == 0 ? slot_c_x_[s] : slot_c_y_[s];
            if (entries[k].column != column || !same_bits(entries[k].value, value))
              refuse(n_x, "entry " + std::to_string(k) + " of " + row_name(row, n_x) + " is K(" + std::to_string(row) +
                              ", " + std::to_string(entries[k].column) + ") = " + number(entries[k].value) +
                              "; the row of node (1, " + std::to_string(j) + ") shifted by " +
                              std::to_string(2 * (i - 1)) + " gives K(" + std::to_string(row) + ", " +
                              std::to_string(column) + ") = " + number(value));
          }
        }
    }
    slot_begin_.push_back(static_cast<int>(slot_offsets_.size()));

    // Seam nodes i = 0 and i = n_x - 1 (every node when n_x < 3): their rows as stored.
    std::vector<int> seam_nodes{0};
    for (int i = 1; i < n_x; ++i)
      if (n_x < 3 || i == n_x - 1) seam_nodes.push_back(i);
    for (int i : seam_nodes)
      for (int d = 0; d < 2; ++d) {
        const int row = row_of_node_0 + 2 * i + d;
        StoredRow stored{row, static_cast<int>(seam_columns_.size()), 0};
        for (const Entry& e : stored_row(K, row)) {
          seam_columns_.push_back(e.column);
          seam_values_.push_back(e.value);
        }
        stored.end = static_cast<int>(seam_columns_.size());
        seam_rows_.push_back(stored);
      }
  }
}

void StencilProduct::apply(const Eigen::VectorXd& u, Eigen::VectorXd& Ku) const {
  eigen_assert(u.size() == n_dofs() && &u != &Ku);
  Ku.resize(n_dofs());
  for (int j = 0; j < n_rows_of_nodes_; ++j) apply_interior(j, u.data(), Ku.data());
  const double* __restrict in = u.data();
  double* __restrict out = Ku.data();
  for (const StoredRow& r : seam_rows_) {
    double sum = 0;  // Eigen's tmp(0)
    for (int k = r.begin; k < r.end; ++k) sum += seam_values_[k] * in[seam_columns_[k]];
    out[r.row] = sum;
  }
}

namespace {

/// Nodes whose outputs are summed in registers at once: 2 per SSE2 register, 8 registers of sums, so that
/// the additions of different nodes overlap and no partial sum goes back to memory between slots.
constexpr int kBlock = 8;

/// Sums of n_nodes consecutive interior nodes of one mesh row, u and out at the first one's rows
/// (n_nodes <= n_nodes_max <= kBlock; the compiler unrolls and vectorizes the full block, n_nodes_max = kBlock).
template <int n_nodes_max>
inline void sum_block(const double* __restrict u, double* __restrict out, const int* offsets, const double* c_x,
                      const double* c_y, int n_slots, int n_nodes) {
  double sum[2 * n_nodes_max];
  for (int b = 0; b < 2 * n_nodes_max; ++b) sum[b] = 0;  // Eigen's tmp(0), one per row
  for (int s = 0; s < n_slots; ++s) {  // stored (increasing column) order: Eigen's order for every output
    const double* __restrict in = u + offsets[s];
    for (int b = 0; b < n_nodes_max; ++b) {
      if (n_nodes_max != kBlock && b >= n_nodes) break;
      const double v = in[2 * b];
      sum[2 * b] += c_x[s] * v;
      sum[2 * b + 1] += c_y[s] * v;
    }
  }
  for (int b = 0; b < 2 * n_nodes; ++b) out[b] = sum[b];
}

}  // namespace

SLIDEWAVE_VECTOR_CLONES
void StencilProduct::apply_interior(int j, const double* __restrict u, double* __restrict Ku) const {
  if (n_x_ < 3) return;
  const int first_row = 2 * j * n_x_ + 2;  // row of node (1, j), d = 0
  const int n_interior = n_x_ - 2;
  const int begin = slot_begin_[j], n_slots = slot_begin_[j + 1] - begin;
  const int* offsets = slot_offsets_.data() + begin;
  const double *c_x = slot_c_x_.data() + begin, *c_y = slot_c_y_.data() + begin;
  int m = 0;
  for (; m + kBlock <= n_interior; m += kBlock)
    sum_block<kBlock>(u + first_row + 2 * m, Ku + first_row + 2 * m, offsets, c_x, c_y, n_slots, kBlock);
  if (m < n_interior)
    sum_block<kBlock - 1>(u + first_row + 2 * m, Ku + first_row + 2 * m, offsets, c_x, c_y, n_slots, n_interior - m);
}

}  // namespace slidewave

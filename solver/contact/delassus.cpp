#include "contact/delassus.hpp"

#include <algorithm>

#include "linalg/vector_clones.hpp"

namespace slidewave {

Eigen::MatrixXd delassus_operator(const LinearSolver& K_eff, int n_contact_dofs) {
  Eigen::MatrixXd W(n_contact_dofs, n_contact_dofs);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(K_eff.size()), z(K_eff.size());
  for (int c = 0; c < n_contact_dofs; ++c) {
    e(c) = 1;
    K_eff.solve_into(e, z);
    W.col(c) = z.head(n_contact_dofs);
    e(c) = 0;
  }
  return 0.5 * (W + W.transpose());
}

Eigen::MatrixXd delassus_operator_periodic(const LinearSolver& K_eff, int n_contact_nodes) {
  Eigen::VectorXd e = Eigen::VectorXd::Zero(K_eff.size()), z[2];
  for (int b = 0; b < 2; ++b) {
    e(b) = 1;
    z[b].resize(K_eff.size());
    K_eff.solve_into(e, z[b]);
    e(b) = 0;
  }
  return delassus_from_node_responses(z[0], z[1], n_contact_nodes);
}

Eigen::MatrixXd delassus_from_node_responses(const Eigen::VectorXd& z0, const Eigen::VectorXd& z1,
                                             int n_contact_nodes) {
  const int n = n_contact_nodes;
  Eigen::MatrixXd W(2 * n, 2 * n);
  for (int b = 0; b < 2; ++b) {
    const Eigen::VectorXd& z = b == 0 ? z0 : z1;
    for (int i = 0; i < n; ++i)
      for (int k = 0; k < n; ++k)
        for (int a = 0; a < 2; ++a) W(2 * i + a, 2 * k + b) = z(2 * (((i - k) % n + n) % n) + a);
  }
  return 0.5 * (W + W.transpose());
}

Eigen::MatrixXd delassus_periodic_columns(const Eigen::MatrixXd& W) {
  const Eigen::Index n_c = W.rows();
  Eigen::MatrixXd C(2 * n_c, 2);
  C.topRows(n_c) = W.leftCols<2>();
  C.bottomRows(n_c) = W.leftCols<2>();
  return C;
}

namespace {

/// out_i = out_i + (c0_i d0 + c1_i d1), i < n.
SLIDEWAVE_VECTOR_CLONES
void add_two_columns(const double* __restrict c0, const double* __restrict c1, double d0, double d1,
                     double* __restrict out, Eigen::Index n) {
  for (Eigen::Index i = 0; i < n; ++i) out[i] += c0[i] * d0 + c1[i] * d1;
}

/// Start of W(:, 2k) (and of W(:, 2k + 1) in the second column) within the stacked generating columns.
Eigen::Index column_start(int n_nodes, int k) { return 2 * ((n_nodes - k) % n_nodes); }

}  // namespace

void add_periodic_node_columns(const Eigen::MatrixXd& columns, int n_nodes, int k, int reach, double d0, double d1,
                               Eigen::VectorXd& y) {
  const double* c0 = columns.data();
  const double* c1 = columns.data() + columns.rows();
  if (2 * reach + 1 >= n_nodes) {
    const Eigen::Index start = column_start(n_nodes, k);
    add_two_columns(c0 + start, c1 + start, d0, d1, y.data(), 2 * n_nodes);
    return;
  }
  // Nodes i = k - reach .. k + reach, cut where they wrap past 0 or n - 1 into runs of consecutive nodes;
  // node i's block is row 2 (n + i - k) of the stacked columns (0 < n + i - k < 2n), consecutive too.
  const auto add_run = [&](int first, int last, int offset) {  // nodes first..last, i - k = node - k + offset
    const Eigen::Index row = 2 * (static_cast<Eigen::Index>(n_nodes) + first - k + offset);
    add_two_columns(c0 + row, c1 + row, d0, d1, y.data() + 2 * first, 2 * (last - first + 1));
  };
  const int first = k - reach, last = k + reach;
  add_run(std::max(first, 0), std::min(last, n_nodes - 1), 0);
  if (first < 0) add_run(n_nodes + first, n_nodes - 1, -n_nodes);
  if (last >= n_nodes) add_run(0, last - n_nodes, n_nodes);
}

int delassus_periodic_reach(const Eigen::MatrixXd& columns, int n_nodes, double relative_floor) {
  const auto w = columns.topRows(2 * n_nodes);  // W(:, 0..1): node i's block at rows 2i, 2i + 1
  const double floor = relative_floor * w.cwiseAbs().maxCoeff();
  int reach = 0;
  for (int i = 1; i < n_nodes; ++i) {
    const int distance = std::min(i, n_nodes - i);
    if (w.middleRows<2>(2 * i).cwiseAbs().maxCoeff() > floor) reach = std::max(reach, distance);
  }
  return reach;
}

}  // namespace slidewave

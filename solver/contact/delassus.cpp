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
  const int n = n_contact_nodes;
  Eigen::MatrixXd W(2 * n, 2 * n);
  Eigen::VectorXd e = Eigen::VectorXd::Zero(K_eff.size()), z(K_eff.size());
  for (int b = 0; b < 2; ++b) {
    e(b) = 1;
    K_eff.solve_into(e, z);
    e(b) = 0;
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

void add_periodic_node_columns(const Eigen::MatrixXd& columns, int n_nodes, int k, double d0, double d1,
                               Eigen::VectorXd& y) {
  const Eigen::Index start = column_start(n_nodes, k);
  add_two_columns(columns.data() + start, columns.data() + columns.rows() + start, d0, d1, y.data(), 2 * n_nodes);
}

}  // namespace slidewave

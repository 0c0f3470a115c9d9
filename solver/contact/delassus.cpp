#include "contact/delassus.hpp"

namespace slidewave {

Condensation condense_on_contact(const SparseCholesky& K_eff, int n_contact_dofs) {
  Eigen::MatrixXd Ct = Eigen::MatrixXd::Zero(K_eff.size(), n_contact_dofs);
  for (int c = 0; c < n_contact_dofs; ++c) Ct(c, c) = 1;
  Condensation out;
  out.Z = K_eff.solve(Ct);
  out.W = out.Z.topRows(n_contact_dofs);
  out.W = 0.5 * (out.W + out.W.transpose()).eval();  // exact symmetry (round-off of the solves)
  return out;
}

}  // namespace slidewave

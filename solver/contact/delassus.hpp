#pragma once
// Condensation of a linear system K_eff u = F + C^T r onto the contact DOFs:
//     Z = K_eff^{-1} C^T  (n_free x n_c),   W = C K_eff^{-1} C^T = C Z  (the Delassus operator).
// C selects the contact DOFs, which are the first n_c free DOFs in the mesh numbering.
#include <Eigen/Dense>

#include "linalg/sparse_cholesky.hpp"

namespace slidewave {

struct Condensation {
  Eigen::MatrixXd Z;  ///< response of all free DOFs to unit contact forces
  Eigen::MatrixXd W;  ///< Delassus operator, symmetric positive definite
};

/// @param n_contact_dofs number of leading free DOFs that are contact DOFs
Condensation condense_on_contact(const SparseCholesky& K_eff, int n_contact_dofs);

}  // namespace slidewave

#pragma once
// The contact solve of a slip step on the rigid flat, as simulate()'s loop makes it (ContactStep in
// model/simulation.cpp, without the substrate): y = (du_x, u_y) = q + W r(n+1) at the contact nodes,
// q = u_free,c - (u_x(n), 0), under the local law with the friction law's bounds, warm-started from r(n);
// after an all-stick step the exact all-stick solution first (0 sweeps), Gauss–Seidel only if a node would
// not stick. Shared by the two slip steps of the wavenumber prototype (model/stick_phase/plain_slip_step.hpp,
// model/stick_phase/wavenumber_slip_step.hpp) so that both run the same contact solve.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/friction_law.hpp"

namespace slidewave {

struct SlipContact {
  /// @param W the loop's Delassus operator (block-circulant; kept by reference: it must outlive this object)
  SlipContact(int n_contact_dofs, const Eigen::MatrixXd& W, const GaussSeidelSettings& settings)
      : q(n_contact_dofs), r_next(n_contact_dofs), solver(W, settings, DelassusLayout::block_circulant) {}

  /// r_next from the free contact displacement u_free (n_c entries) and the contact displacement u and
  /// reactions r of time n; `contact` in: the states of time n, out: those of n+1.
  GaussSeidelReport solve(const Eigen::VectorXd& u_free, const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                          const FrictionLaw& law, const FrictionState& friction, std::vector<ContactState>& contact) {
    q = u_free.head(q.size());
    for (Eigen::Index k = 0; k < q.size() / 2; ++k) q(2 * k) -= u(2 * k);
    const std::unique_ptr<FrictionBounds> bounds = law.bounds(friction);
    r_next = r;
    if (all_stuck(contact) && solver.solve_all_stick(q, *bounds, r_next, contact))
      return GaussSeidelReport{0, 0.0, true};
    return solver.solve(q, *bounds, r_next, contact);
  }

  Eigen::VectorXd q, r_next;
  ContactSolver solver;
};

}  // namespace slidewave

#pragma once
// The contact problem of one time step and its buffers, for every stepping path (simulate()'s plain loop,
// model/stick_phase/plain_slip_step.hpp, model/stick_phase/wavenumber_slip_step.hpp): y = (du_x, u_y) =
// q + W r(n+1) at the contact nodes, q = u_free,c - (u_x(n), 0), under the local law with the friction law's
// bounds, warm-started from r(n). With a substrate, q = q_L + S q_S (model/substrate.hpp): the layer's minus
// the substrate's free slip, plus its free normal displacement. A step that follows an all-stick step first
// tries the exact all-stick solution (contact/all_stick.hpp; reported as 0 sweeps), and Gauss–Seidel only if
// a node would not stick.
#include <Eigen/Dense>
#include <memory>
#include <vector>

#include "contact/contact_solver.hpp"
#include "contact/friction_law.hpp"

namespace slidewave {

/// The substrate's part of q: its free contact displacement and its contact displacement of time n (both in
/// its mirrored frame, 2 per contact node).
struct SubstrateContact {
  const Eigen::VectorXd& u_free;
  const Eigen::VectorXd& u;
};

struct ContactStep {
  /// @param W the Delassus operator (block-circulant; kept by reference: it must outlive this object)
  ContactStep(int n_contact_dofs, const Eigen::MatrixXd& W, const GaussSeidelSettings& settings)
      : q(n_contact_dofs), r_next(n_contact_dofs), solver(W, settings, DelassusLayout::block_circulant) {}

  /// r_next from the free contact displacement u_free (at least n_c entries) and the contact displacement u and
  /// reactions r of time n; `contact` in: the states of time n, out: those of n+1.
  GaussSeidelReport solve(const Eigen::VectorXd& u_free, const Eigen::VectorXd& u, const Eigen::VectorXd& r,
                          const FrictionLaw& law, const FrictionState& friction, std::vector<ContactState>& contact,
                          const SubstrateContact* substrate = nullptr) {
    q = u_free.head(q.size());
    for (Eigen::Index k = 0; k < q.size() / 2; ++k) q(2 * k) -= u(2 * k);
    if (substrate)
      for (Eigen::Index k = 0; k < q.size() / 2; ++k) {
        q(2 * k) -= substrate->u_free(2 * k) - substrate->u(2 * k);
        q(2 * k + 1) += substrate->u_free(2 * k + 1);
      }
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

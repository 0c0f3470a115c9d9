#include "model/layer_model.hpp"

#include <cmath>
#include <mutex>
#include <sstream>
#include <stdexcept>

#include "contact/contact_solver.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/delassus.hpp"
#include "fem/assembly.hpp"
#include "fem/mass_redistribution.hpp"
#include "linalg/block_circulant_solver.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "linalg/two_solve_split.hpp"
#include "model/substrate.hpp"

namespace slidewave {

struct LayerModel::AssembledBlocks {
  std::once_flag all_dofs, free_free;
  RowSparseMatrix K, M;
  Eigen::SparseMatrix<double> K_ff, M_ff;
  RowSparseMatrix M_ff_rows;
};

LayerModel::LayerModel(const RunConfig& c) : config(c), d(c.derived()), mesh(d.n_x, d.n_y, d.h) {
  n_free = mesh.n_free();
  n_top = mesh.n_top();
  n_contact_dofs = 2 * mesh.n_contact();
  stiffness_rows_ =
      std::make_shared<const UniformRows>(mesh, quad4_stiffness(c.material.E, c.material.nu, d.h, c.mesh.integration));
  mass_rows_ = std::make_shared<const UniformRows>(mesh, quad4_mass(c.material.rho, d.h, c.mesh.mass));
  const DofRange all{0, mesh.n_dofs()}, free{0, n_free}, top{n_free, mesh.n_dofs()};
  // Swapped in: Eigen's SparseMatrix has no move assignment, and `K_fd = ...rows(...)` would copy each
  // matrix into fresh memory.
  stiffness_rows_->rows(free, top).swap(K_fd);
  mass_rows_->rows(free, top).swap(M_fd);
  mass_rows_->rows(top, all).swap(M_top_rows);
  // Mesh columns 0, 1 and n_x - 1 hold every distinct row (first, inner and last column).
  const std::vector<int> distinct_columns = {0, 1, mesh.n_x - 1};
  stiffness_rows_->rows(all, all, distinct_columns).swap(K_spectral_rows_);
  if (c.mesh.mass == MassKind::redistributed) {
    const double rho = c.material.rho;
    redistribute_contact_mass(mesh, rho, M_fd, free, top);
    redistribute_contact_mass(mesh, rho, M_top_rows, top, all);
  } else {
    mass_rows_->rows(all, all, distinct_columns).swap(M_spectral_rows_);
  }
  if (c.substrate.present()) substrate = std::make_shared<const LayerModel>(substrate_body_config(c));
  assembled_ = std::make_shared<AssembledBlocks>();
}

namespace {

/// K_ff, M_ff and M_ff_rows: the element matrices and the redistribution of the constructor.
void assemble_free_free(const LayerModel& m, Eigen::SparseMatrix<double>& K_ff, Eigen::SparseMatrix<double>& M_ff,
                        RowSparseMatrix& M_ff_rows) {
  const RunConfig& c = m.config;
  const DofRange free{0, m.n_free};
  const Matrix8 Me = quad4_mass(c.material.rho, m.d.h, c.mesh.mass);
  assemble_uniform_columns(m.mesh, quad4_stiffness(c.material.E, c.material.nu, m.d.h, c.mesh.integration), free, free)
      .swap(K_ff);
  assemble_uniform_columns(m.mesh, Me, free, free).swap(M_ff);
  assemble_uniform_rows(m.mesh, Me, free, free).swap(M_ff_rows);
  if (c.mesh.mass == MassKind::redistributed) {
    redistribute_contact_mass(m.mesh, c.material.rho, M_ff, free, free);
    redistribute_contact_mass(m.mesh, c.material.rho, M_ff_rows, free, free);
  }
}

}  // namespace

const RowSparseMatrix& LayerModel::K() const {
  AssembledBlocks& a = *assembled_;
  std::call_once(a.all_dofs, [this, &a] {
    const DofRange all{0, mesh.n_dofs()};
    stiffness_rows_->rows(all, all).swap(a.K);
    mass_rows_->rows(all, all).swap(a.M);
    if (config.mesh.mass == MassKind::redistributed)
      redistribute_contact_mass(mesh, config.material.rho, a.M, all, all);
  });
  return a.K;
}

const RowSparseMatrix& LayerModel::M() const {
  K();
  return assembled_->M;
}

Eigen::VectorXd LayerModel::stiffness_product(const Eigen::Ref<const Eigen::VectorXd>& u) const {
  const DofRange all{0, mesh.n_dofs()};
  return stiffness_rows_->product(all, all, u);
}

Eigen::VectorXd LayerModel::top_mass_product(const Eigen::Ref<const Eigen::VectorXd>& v_t) const {
  if (config.mesh.mass == MassKind::redistributed) return M().bottomRightCorner(n_top, n_top) * v_t;
  const DofRange top{n_free, n_free + n_top};
  return mass_rows_->product(top, top, v_t);
}

const RowSparseMatrix& LayerModel::spectral_rows(FreeBlock which) const {
  if (which == FreeBlock::stiffness) return K_spectral_rows_;
  return config.mesh.mass == MassKind::redistributed ? M() : M_spectral_rows_;
}

const Eigen::SparseMatrix<double>& LayerModel::K_ff() const {
  AssembledBlocks& a = *assembled_;
  std::call_once(a.free_free, [this, &a] { assemble_free_free(*this, a.K_ff, a.M_ff, a.M_ff_rows); });
  return a.K_ff;
}

const Eigen::SparseMatrix<double>& LayerModel::M_ff() const {
  K_ff();
  return assembled_->M_ff;
}

const RowSparseMatrix& LayerModel::M_ff_rows() const {
  K_ff();
  return assembled_->M_ff_rows;
}

PartitionedSystem LayerModel::partitioned() const {
  return {K(), K_ff(), M_ff(), M_ff_rows(), K_fd, n_free, n_top, n_contact_dofs};
}

Eigen::VectorXd LayerModel::free_mass_product(const Eigen::Ref<const Eigen::VectorXd>& x_f) const {
  if (config.mesh.mass == MassKind::redistributed) return leading_block_product(M(), n_free, x_f);
  const DofRange free{0, n_free};
  return mass_rows_->product(free, free, x_f);
}

std::unique_ptr<LinearSolver> LayerModel::factorize(FreeBlock which) const {
  if (config.numerics.linear_solver != LinearSolverKind::spectral)
    return factorize(which == FreeBlock::stiffness ? K_ff() : M_ff());
  return std::make_unique<BlockCirculantSolver>(circulant_blocks_of_rows(spectral_rows(which), mesh.n_x, mesh.n_y),
                                                mesh.n_x, mesh.n_y, config.numerics.threads);
}

std::unique_ptr<LinearSolver> LayerModel::factorize(const Eigen::SparseMatrix<double>& A) const {
  return factorize_split(A);
}

std::unique_ptr<SplitSolver> LayerModel::factorize_split(const Eigen::SparseMatrix<double>& A) const {
  if (config.numerics.linear_solver == LinearSolverKind::spectral)
    return std::make_unique<BlockCirculantSolver>(A, mesh.n_x, mesh.n_y, config.numerics.threads);
  return std::make_unique<TwoSolveSplit>(std::make_unique<SparseCholesky>(A, config.numerics.threads), n_contact_dofs);
}

Eigen::VectorXd LayerModel::top_displacement(double u_x, double u_y) const {
  Eigen::VectorXd u_d(n_top);
  for (int i = 0; i < mesh.n_x; ++i) {
    u_d(2 * i) = u_x;
    u_d(2 * i + 1) = u_y;
  }
  return u_d;
}

namespace {

double sum_every_other(const Eigen::VectorXd& r, int offset) {
  double s = 0;
  for (int k = offset; k < r.size(); k += 2) s += r(k);
  return s;
}

}  // namespace

PreloadState solve_preload(const LayerModel& model) {
  const auto& c = model.config;
  const int n_c = model.n_contact_dofs;
  const auto K_static = model.factorize(LayerModel::FreeBlock::stiffness);
  // With a substrate: the pair's static Delassus operator W_L + S W_S S (model/substrate.hpp).
  const LayerModel* sub = model.substrate.get();
  const auto K_static_sub = sub ? sub->factorize(LayerModel::FreeBlock::stiffness) : nullptr;
  const Eigen::MatrixXd W = sub ? pair_delassus(delassus_operator_periodic(*K_static, model.mesh.n_contact()),
                                                delassus_operator_periodic(*K_static_sub, sub->mesh.n_contact()))
                                : delassus_operator_periodic(*K_static, model.mesh.n_contact());
  // The substrate's static displacement (all DOFs, its held bottom at 0) under -r, i.e. S r in its frame.
  const auto substrate_displacement = [&](const Eigen::VectorXd& r) -> Eigen::VectorXd {
    Eigen::VectorXd load = Eigen::VectorXd::Zero(sub->n_free), u = Eigen::VectorXd::Zero(sub->n_free + sub->n_top);
    load.head(n_c) = r;
    mirror_x_components(load);
    u.head(sub->n_free) = K_static_sub->solve(load);
    return u;
  };
  // The quasi-static stages slide under Coulomb's bound f r_y, whatever the law of the dynamics.
  const ContactSolver contact_solver(W, {c.contact.tolerance, c.contact.max_iterations, model.d.p0 * model.d.h},
                                     DelassusLayout::dense);

  // Contact displacements of the free (reaction-less) static response to the top displacement u_d.
  const auto free_contact_displacement = [&](const Eigen::VectorXd& u_d) -> Eigen::VectorXd {
    return K_static->solve(Eigen::VectorXd(-(model.K_fd * u_d))).head(n_c);
  };

  // Quasi-static contact solve: K_ff u_f = -K_fd u_d + C^T r; local slip measured from u_x_before.
  const auto solve_static = [&](const Eigen::VectorXd& u_d, const Eigen::VectorXd& u_contact_before, Eigen::VectorXd& r,
                                std::vector<ContactState>& state, int& iterations) {
    Eigen::VectorXd rhs = -(model.K_fd * u_d);
    Eigen::VectorXd q = free_contact_displacement(u_d);
    for (int k = 0; k < n_c; k += 2) q(k) -= u_contact_before(k);
    CoulombBounds bounds(c.friction.f);
    const auto report = contact_solver.solve(q, bounds, r, state);
    if (!report.converged) throw std::runtime_error("preload: the quasi-static contact solve did not converge");
    iterations += report.iterations;
    Eigen::VectorXd u(model.n_free + model.n_top);
    rhs.head(n_c) += r;
    u.head(model.n_free) = K_static->solve(rhs);
    u.tail(model.n_top) = u_d;
    return u;
  };

  PreloadState s;
  s.contact_iterations = 0;
  const double u_y_top = c.loading.Uy_over_H * model.d.H;

  // Stage 1: compression, warm-started from the all-stick answer W r = -q (glued interface, exact
  // when the whole interface sticks): Gauss-Seidel then only verifies it, instead of needing hundreds
  // of sweeps from zero that stop at the tolerance, not at round-off. The dense LDLT, not the time
  // loop's AllStickSolution (contact/all_stick.hpp): that gives the same r rounded otherwise, which moves
  // u_x_preshear in its 15th digit and every run by what that grows to after slip onset (measured).
  const Eigen::LDLT<Eigen::MatrixXd> W_ldlt = W.ldlt();
  const Eigen::VectorXd zero_contact = Eigen::VectorXd::Zero(n_c);
  const Eigen::VectorXd u_d1 = model.top_displacement(0, u_y_top);
  s.r = -W_ldlt.solve(free_contact_displacement(u_d1));
  Eigen::VectorXd u1 = solve_static(u_d1, zero_contact, s.r, s.state, s.contact_iterations);
  const Eigen::VectorXd r1 = s.r;
  // Stage 2's slip is measured from stage 1's relative position (the layer's own on a rigid flat).
  const Eigen::VectorXd u1_contact =
      sub ? relative_contact_displacement(u1, substrate_displacement(r1), n_c) : Eigen::VectorXd(u1.head(n_c));

  // Stage 2: while all nodes stick, the reactions are linear in the top shear U:
  // r(U) = r1 + U r_unit with W r_unit = -(free contact displacement of a unit shear). Solve for the U
  // that gives T/N = preshear_ratio * f, then verify with the full contact law.
  const Eigen::VectorXd r_unit = -W_ldlt.solve(free_contact_displacement(model.top_displacement(1, 0)));
  const double target = c.loading.preshear_ratio * c.friction.f;
  const double T1 = -sum_every_other(r1, 0), N1 = sum_every_other(r1, 1);
  const double Tu = -sum_every_other(r_unit, 0), Nu = sum_every_other(r_unit, 1);
  s.u_x_top = (target * N1 - T1) / (Tu - target * Nu);
  s.r = r1 + s.u_x_top * r_unit;  // warm start: the exact all-stick answer
  s.u = solve_static(model.top_displacement(s.u_x_top, u_y_top), u1_contact, s.r, s.state, s.contact_iterations);
  if (sub) s.u_substrate = substrate_displacement(s.r);
  s.T = -sum_every_other(s.r, 0);
  s.N = sum_every_other(s.r, 1);

  // Frictionless (f = 0): "stick" is not defined (any round-off of r_x is a slip), so only closure is required.
  const bool frictionless = c.friction.f == 0;
  for (size_t k = 0; k < s.state.size(); ++k)
    if (s.state[k] == ContactState::open || (!frictionless && s.state[k] != ContactState::stick)) {
      std::ostringstream msg;
      msg << "preload: contact node " << k << " is not in stick after stage 2 (state " << static_cast<int>(s.state[k])
          << "); the preload must leave the interface all-closed, all-stick";
      throw std::runtime_error(msg.str());
    }
  return s;
}

}  // namespace slidewave

#pragma once
// One HHT step (time/hht.hpp) of a linear second-order system with contact forces,
//     M a + K u = C^T r,
// split into a predictor, a free solve and a correction, so that the contact forces r(n+1) can be solved
// between the free solve and the correction (the loop of model/simulation.cpp):
//     predictor  u~ = u + dt v + dt^2 (1/2 - beta) a                  (free DOFs)
//     free solve K_eff u_free = M u~ / (beta dt^2) - (1-a) K_fd u_d(n+1) - a K u(n) + a' C^T r(n)
//     correction K_eff u(n+1) = (same right-hand side) + w C^T r(n+1),   i.e. u_free + w Z r(n+1)
// with K_eff = M_ff / (beta dt^2) + (1-a) K_ff, and w = 1-a, a' = a for "alpha" weighting (contact forces
// weighted like external forces) or w = 1, a' = 0 for "end" weighting.
//
// DOF layout: the n_free free DOFs first, of which the first n_contact carry the contact forces C^T r
// (C picks them), then the n_prescribed DOFs whose displacement u_d is imposed. The prescribed DOFs must
// move at constant velocity (a = 0): the inertia coupling M_fd a_d is not in the equations.
//
// The two K_eff solves of a step go through a SplitSolver (linalg/split_solver.hpp): the free solve keeps
// what the correction needs and yields only C u_free, and the correction adds the response to w C^T r(n+1).
// On the periodic layer that is BlockCirculantSolver's one pass per step; any other factorization goes
// through TwoSolveSplit (two solves, the oracle).
//
// The mass products M_ff u, M_ff v, M_ff a of the free rows are carried through the step by the Newmark
// relations and the equation of motion (M_ff a(n+1) follows from K u(n+1), K u(n) and the contact forces),
// so that K u is the only full product of a step. When K is a stencil periodic in x with rows of n_contact / 2
// nodes (the layer: its contact DOFs are the bottom mesh row), K u is matrix-free (fem/stencil_product.hpp),
// bitwise equal to the sparse product; any other K (StencilProduct refuses it) keeps the sparse product.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <functional>
#include <limits>
#include <memory>

#include "fem/stencil_product.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/split_solver.hpp"
#include "time/hht.hpp"

namespace slidewave {

/// The matrices of the system, partitioned as above (the stepper keeps references: they must outlive it).
struct PartitionedSystem {
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& K;          ///< all DOFs
  const Eigen::SparseMatrix<double>& K_ff;                        ///< free-free block
  const Eigen::SparseMatrix<double>& M_ff;                        ///< free-free block
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& M_ff_rows;  ///< M_ff, row-major (products)
  const Eigen::SparseMatrix<double, Eigen::RowMajor>& K_fd;       ///< free-prescribed block
  int n_free, n_prescribed, n_contact;
};

/// Everything the step carries from one time to the next (a checkpoint of the dynamics).
struct HHTState {
  Eigen::VectorXd u, v, acc;         ///< displacement, velocity, acceleration (all DOFs; acc = 0 on prescribed)
  Eigen::VectorXd Ku;                ///< K u (all DOFs)
  Eigen::VectorXd Mu_f, Mv_f, Ma_f;  ///< M_ff u_f, M_ff v_f, M_ff a_f (free rows)
  Eigen::VectorXd r;                 ///< contact forces of the current time, weighted into the next step by a'
};

/// Effective matrix K_eff = M_ff / (beta dt^2) + (1 - alpha) K_ff.
Eigen::SparseMatrix<double> effective_matrix(const HHTCoefficients& hht, const Eigen::SparseMatrix<double>& M_ff,
                                             const Eigen::SparseMatrix<double>& K_ff);
/// The same, of the system's blocks.
Eigen::SparseMatrix<double> effective_matrix(const HHTCoefficients& hht, const PartitionedSystem& system);

/// M_ff x_f, for x_f of size n_free.
using FreeMassProduct = std::function<Eigen::VectorXd(const Eigen::Ref<const Eigen::VectorXd>&)>;

/// HHTStepper::initial_state with K u given (a run that never steps plainly has no stepper): the state in the
/// equation of motion, the acceleration from M_ff a_f = C^T r - (K u)_f, the mass products (by
/// free_mass_product: the stepper's M_ff, or the layer's, model/layer_model.hpp); the contact DOFs first.
HHTState hht_initial_state(const FreeMassProduct& free_mass_product, int n_free, int n_contact,
                           const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& r,
                           Eigen::VectorXd Ku, const LinearSolver& M_ff);

class HHTStepper {
 public:
  /// @param K_eff  split factorization of effective_matrix(hht, system) whose n_contact() is system.n_contact
  ///                (std::invalid_argument otherwise)
  /// @param alpha_weighted  true: contact forces weighted like external forces (w = 1-a, a' = a)
  HHTStepper(const PartitionedSystem& system, const HHTCoefficients& hht, bool alpha_weighted,
             std::unique_ptr<SplitSolver> K_eff);

  /// State at rest in the equation of motion: K u, the mass products, and the consistent acceleration
  /// M_ff a_f = C^T r - (K u)_f (a = 0 on the prescribed DOFs).
  /// @param M_ff  factorization of system.M_ff
  HHTState initial_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& r,
                         const LinearSolver& M_ff) const;

  /// Predictor and right-hand side of the free solve for the prescribed displacement u_d(n+1). Nothing to do
  /// when the last correct() was given this u_d as u_d_following (and the state was not changed since).
  void predict(const HHTState& state, const Eigen::VectorXd& u_d_next);
  /// Free solve (r(n+1) = 0): its displacement at the contact DOFs (n_contact entries), valid until the next
  /// predict().
  const Eigen::VectorXd& solve_free();
  /// Correction with the contact forces r(n+1), Newmark update: the state moves to time n+1.
  /// @param u_d_following  null, or u_d(n+2): then the same loops also do predict(state, *u_d_following)
  ///                       (same bits), and that call returns at once; the state must not change in between
  void correct(const Eigen::VectorXd& r_next, HHTState& state, const Eigen::VectorXd* u_d_following = nullptr);

  /// Displacement and contact forces before the last correct() (time n).
  const Eigen::VectorXd& u_previous() const { return u_work_; }
  const Eigen::VectorXd& r_previous() const { return r_previous_; }

  const LinearSolver& K_eff() const { return *K_eff_; }
  const HHTCoefficients& coefficients() const { return hht_; }
  /// w, the weight of r(n+1) in the equation of motion (the correction is u_free + w Z r(n+1)).
  double contact_weight() const { return w_; }
  /// K u by the matrix-free stencil product (else by the sparse product); same bits either way.
  bool uses_stencil_product() const { return K_stencil_ != nullptr; }

 private:
  PartitionedSystem system_;
  HHTCoefficients hht_;
  double w_, w_previous_;
  std::unique_ptr<SplitSolver> K_eff_;
  std::unique_ptr<StencilProduct> K_stencil_;  ///< null when K is not a periodic stencil
  /// Ku = K u (u and Ku distinct).
  void multiply_K(const Eigen::VectorXd& u, Eigen::VectorXd& Ku) const;
  /// u_d(n+1) and (1-a) K_fd u_d(n+1), the prescribed part of the free solve's right-hand side.
  void prescribe(const Eigen::VectorXd& u_d_next);
  /// rhs += a' C^T r(n), the last of the right-hand side.
  void add_previous_contact_forces(const Eigen::VectorXd& r);
  bool predicted_ = false;  ///< the last correct() did the predict() of the step that follows
  /// The rows of K_fd that have entries (K_fd u_d is zero elsewhere).
  int coupled_rows_begin_ = std::numeric_limits<int>::max(), coupled_rows_end_ = 0;
  Eigen::VectorXd u_free_contact_, contact_load_;
  Eigen::VectorXd u_d_next_, K_fd_u_d_, rhs_, u_work_, Ku_next_, r_previous_;
};

}  // namespace slidewave

#pragma once
// Small linear systems with known solutions for the tests of the production HHT stepper
// (time/hht_stepper.hpp): dense solvers behind its solver interfaces, the stepper's three paths, a
// single-DOF oscillator, a periodic array of them laid out as the layer, and a driver loop.
// Shared by hht_test.cpp (coefficients, convergence, weightings) and hht_stability_test.cpp (spectral
// radius, stability, energy).
#include <Eigen/Dense>
#include <functional>
#include <memory>

#include "linalg/block_circulant_solver.hpp"
#include "linalg/two_solve_split.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave::hht_testing {

using RowMatrix = Eigen::SparseMatrix<double, Eigen::RowMajor>;

/// Dense LDL^T behind the LinearSolver interface (the systems here have a few DOFs).
class DenseSolver : public LinearSolver {
 public:
  explicit DenseSolver(const Eigen::SparseMatrix<double>& A) : ldlt_(Eigen::MatrixXd(A)) {}
  void solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const override {
    x = ldlt_.solve(b);
  }
  int size() const override { return static_cast<int>(ldlt_.rows()); }

 private:
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
};

/// The same as a split solver (linalg/split_solver.hpp): u = u_free + Z g with Z = A^{-1} C^T precomputed.
class DenseSplitSolver : public SplitSolver {
 public:
  // No solve without contact columns: Eigen's triangular solve binds coeffRef(0, 0) of an empty
  // right-hand side (undefined behaviour, found by UBSan).
  DenseSplitSolver(const Eigen::SparseMatrix<double>& A, int n_contact)
      : ldlt_(Eigen::MatrixXd(A)),
        Z_(n_contact > 0 ? Eigen::MatrixXd(ldlt_.solve(Eigen::MatrixXd::Identity(A.rows(), n_contact)))
                         : Eigen::MatrixXd(A.rows(), 0)) {}
  void solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const override {
    x = ldlt_.solve(b);
  }
  int size() const override { return static_cast<int>(ldlt_.rows()); }
  int n_contact() const override { return static_cast<int>(Z_.cols()); }
  void solve_free(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> u_contact) override {
    u_free_ = ldlt_.solve(b);
    u_contact = u_free_.head(n_contact());
  }
  void solve_loaded(const Eigen::Ref<const Eigen::VectorXd>& g, Eigen::Ref<Eigen::VectorXd> u) override {
    u = u_free_ + Z_ * g;
  }

 private:
  Eigen::LDLT<Eigen::MatrixXd> ldlt_;
  Eigen::MatrixXd Z_;
  Eigen::VectorXd u_free_;
};

/// two_solves: any solver through TwoSolveSplit; one_pass: the dense split solver; one_pass_fft:
/// BlockCirculantSolver's split solve (only for oscillator_array, whose K_eff is block-circulant).
enum class Path { two_solves, one_pass, one_pass_fft };

/// A system M a + K u = C^T r with its matrices owned, partitioned as PartitionedSystem wants.
struct OwnedSystem {
  RowMatrix K, M_ff_rows, K_fd;
  Eigen::SparseMatrix<double> K_ff, M_ff;
  int n_free, n_prescribed, n_contact;
  int array_columns = 0;  ///< n_x of a periodic array laid out as the layer (oscillator_array), else 0

  OwnedSystem(const Eigen::MatrixXd& K_full, const Eigen::MatrixXd& M_full, int n_f, int n_c)
      : n_free(n_f), n_prescribed(static_cast<int>(K_full.rows()) - n_f), n_contact(n_c) {
    K = K_full.sparseView();
    K_ff = K_full.topLeftCorner(n_f, n_f).sparseView();
    M_ff = M_full.topLeftCorner(n_f, n_f).sparseView();
    M_ff_rows = M_ff;
    K_fd = K_full.topRightCorner(n_f, n_prescribed).sparseView();
  }
  PartitionedSystem view() const { return {K, K_ff, M_ff, M_ff_rows, K_fd, n_free, n_prescribed, n_contact}; }
  HHTStepper stepper(const HHTCoefficients& hht, bool alpha_weighted = true, Path path = Path::two_solves) const {
    if (path == Path::one_pass_fft)
      return HHTStepper(view(), hht, alpha_weighted,
                        std::make_unique<BlockCirculantSolver>(effective_matrix(hht, view()), array_columns,
                                                               n_free / (2 * array_columns)));
    if (path == Path::one_pass)
      return HHTStepper(view(), hht, alpha_weighted,
                        std::make_unique<DenseSplitSolver>(effective_matrix(hht, view()), n_contact));
    return HHTStepper(
        view(), hht, alpha_weighted,
        std::make_unique<TwoSolveSplit>(std::make_unique<DenseSolver>(effective_matrix(hht, view())), n_contact));
  }
};

/// Free mass (DOF 0, also the contact DOF) on a spring k to a support (DOF 1, prescribed).
inline OwnedSystem oscillator(double m, double k) {
  Eigen::MatrixXd K(2, 2), M = Eigen::MatrixXd::Zero(2, 2);
  K << k, -k, -k, k;
  M(0, 0) = m;
  M(1, 1) = m;
  return OwnedSystem(K, M, 1, 1);
}

/// n_x columns of the oscillator in both directions, numbered as the layer's bottom row (free DOF 2 i + d,
/// all of them contact DOFs) and top row (support 2 n_x + 2 i + d): K_eff is block-circulant with n_y = 1.
inline OwnedSystem oscillator_array(double m, double k, int n_x) {
  const int n_f = 2 * n_x;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(2 * n_f, 2 * n_f), M = Eigen::MatrixXd::Zero(2 * n_f, 2 * n_f);
  for (int f = 0; f < n_f; ++f) {
    K(f, f) = K(n_f + f, n_f + f) = k;
    K(f, n_f + f) = K(n_f + f, f) = -k;
    M(f, f) = M(n_f + f, n_f + f) = m;
  }
  OwnedSystem system(K, M, n_f, n_f);
  system.array_columns = n_x;
  return system;
}

inline OwnedSystem oscillator_on(Path path, double m, double k) {
  return path == Path::one_pass_fft ? oscillator_array(m, k, 4) : oscillator(m, k);
}

/// (u_free, u_d) in every copy of the oscillator.
inline Eigen::VectorXd both(const OwnedSystem& system, double free, double prescribed) {
  Eigen::VectorXd x(system.n_free + system.n_prescribed);
  x.head(system.n_free).setConstant(free);
  x.tail(system.n_prescribed).setConstant(prescribed);
  return x;
}

/// Runs n_steps with the contact force r(t) and the support u_d(t); returns the final state.
inline HHTState integrate(const OwnedSystem& system, const HHTCoefficients& hht, HHTState s, int n_steps,
                          const std::function<double(double)>& r, const std::function<double(double)>& u_d,
                          bool alpha_weighted = true, Path path = Path::two_solves) {
  HHTStepper stepper = system.stepper(hht, alpha_weighted, path);
  for (int n = 1; n <= n_steps; ++n) {
    const double t = n * hht.dt;
    stepper.predict(s, Eigen::VectorXd::Constant(system.n_prescribed, u_d(t)));
    stepper.solve_free();
    stepper.correct(Eigen::VectorXd::Constant(system.n_contact, r(t)), s);
  }
  return s;
}

inline HHTState start(const OwnedSystem& system, const HHTCoefficients& hht, const Eigen::VectorXd& u,
                      const Eigen::VectorXd& v, const Eigen::VectorXd& r) {
  return system.stepper(hht).initial_state(u, v, r, DenseSolver(system.M_ff));
}

inline const double kAlphas[] = {0.0, 0.05, 0.1, 1.0 / 3.0};
}  // namespace slidewave::hht_testing

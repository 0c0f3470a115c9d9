#pragma once
// The split solve (linalg/split_solver.hpp) of any factorized matrix, by two full solves:
//     solve_free(b)    u_free = K^{-1} b, kept; returns its first n_contact entries;
//     solve_loaded(g)  u = K^{-1} (b + C^T g) by a second solve.
// The general sparse path (CHOLMOD, a mesh that is not the uniform periodic layer) and the tests' oracle
// of BlockCirculantSolver's one-pass split. Costs two solves per step where the FFT split costs about one.
#include <Eigen/Dense>
#include <memory>

#include "linalg/split_solver.hpp"

namespace slidewave {

class TwoSolveSplit : public SplitSolver {
 public:
  /// @param solver     the factorization (owned)
  /// @param n_contact  leading DOFs that carry the load g (0 <= n_contact <= solver->size())
  TwoSolveSplit(std::unique_ptr<LinearSolver> solver, int n_contact);

  void solve_into(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> x) const override {
    solver_->solve_into(b, x);
  }
  int size() const override { return solver_->size(); }
  int n_contact() const override { return n_contact_; }
  void solve_free(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> u_contact) override;
  void solve_loaded(const Eigen::Ref<const Eigen::VectorXd>& g, Eigen::Ref<Eigen::VectorXd> u) override;

 private:
  std::unique_ptr<LinearSolver> solver_;
  int n_contact_;
  Eigen::VectorXd b_, u_free_;
  bool kept_valid_ = false;
};

}  // namespace slidewave

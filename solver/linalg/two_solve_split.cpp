#include "linalg/two_solve_split.hpp"

#include <stdexcept>
#include <string>

namespace slidewave {

TwoSolveSplit::TwoSolveSplit(std::unique_ptr<LinearSolver> solver, int n_contact)
    : solver_(std::move(solver)), n_contact_(n_contact) {
  if (!solver_ || n_contact < 0 || n_contact > solver_->size())
    throw std::invalid_argument("TwoSolveSplit: n_contact = " + std::to_string(n_contact) +
                                " must be in [0, size of the solver]");
  b_.resize(solver_->size());
  u_free_.resize(solver_->size());
}

void TwoSolveSplit::solve_free(const Eigen::Ref<const Eigen::VectorXd>& b, Eigen::Ref<Eigen::VectorXd> u_contact) {
  b_ = b;
  solver_->solve_into(b_, u_free_);
  u_contact = u_free_.head(n_contact_);
  kept_valid_ = true;
}

void TwoSolveSplit::solve_loaded(const Eigen::Ref<const Eigen::VectorXd>& g, Eigen::Ref<Eigen::VectorXd> u) {
  if (!kept_valid_) throw std::logic_error("TwoSolveSplit::solve_loaded: no solve_free() before it");
  kept_valid_ = false;
  b_.head(n_contact_) += g;
  solver_->solve_into(b_, u);
}

}  // namespace slidewave

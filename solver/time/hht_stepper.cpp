#include "time/hht_stepper.hpp"

#include <stdexcept>
#include <string>

namespace slidewave {

Eigen::SparseMatrix<double> effective_matrix(const HHTCoefficients& hht, const PartitionedSystem& system) {
  return hht.mass_factor() * system.M_ff + (1 - hht.alpha) * system.K_ff;
}

HHTStepper::HHTStepper(const PartitionedSystem& system, const HHTCoefficients& hht, bool alpha_weighted,
                       std::unique_ptr<LinearSolver> K_eff, bool one_pass)
    : system_(system),
      hht_(hht),
      w_(alpha_weighted ? 1 - hht.alpha : 1.0),
      w_previous_(alpha_weighted ? hht.alpha : 0.0),
      K_eff_(std::move(K_eff)) {
  if (one_pass) {
    split_ = dynamic_cast<SplitSolver*>(K_eff_.get());
    if (!split_ || split_->n_contact() != system.n_contact)
      throw std::invalid_argument("HHTStepper: one pass per step needs a split solver (BlockCirculantSolver) whose " +
                                  std::string("loaded DOFs are the ") + std::to_string(system.n_contact) +
                                  " contact DOFs");
  }
  try {
    if (system.n_contact % 2 == 0) K_stencil_ = std::make_unique<StencilProduct>(system.K, system.n_contact / 2);
  } catch (const std::invalid_argument&) {
    // Not the layer's periodic stencil (e.g. a small test system): the sparse product, same result.
  }
  const int n_f = system.n_free, n = system.n_free + system.n_prescribed;
  u_free_contact_.resize(system.n_contact);
  contact_load_.resize(system.n_contact);
  u_tilde_.resize(n_f);
  Mu_tilde_.resize(n_f);
  rhs_.resize(n_f);
  u_free_.resize(n_f);
  u_work_.resize(n);
  Ku_next_.resize(n);
  Ma_next_.resize(n_f);
  acc_f_next_.resize(n_f);
}

HHTState HHTStepper::initial_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& r,
                                   const LinearSolver& M_ff) const {
  const int n_f = system_.n_free, n_c = system_.n_contact;
  HHTState s;
  s.u = u;
  s.v = v;
  s.r = r;
  multiply_K(u, s.Ku);
  Eigen::VectorXd rhs = -s.Ku.head(n_f);
  rhs.head(n_c) += r;
  s.acc = Eigen::VectorXd::Zero(u.size());
  s.acc.head(n_f) = M_ff.solve(rhs);
  s.Mu_f = system_.M_ff_rows * u.head(n_f);
  s.Mv_f = system_.M_ff_rows * v.head(n_f);
  s.Ma_f = -s.Ku.head(n_f);
  s.Ma_f.head(n_c) += r;
  return s;
}

void HHTStepper::multiply_K(const Eigen::VectorXd& u, Eigen::VectorXd& Ku) const {
  if (K_stencil_)
    K_stencil_->apply(u, Ku);
  else
    Ku.noalias() = system_.K * u;
}

void HHTStepper::predict(const HHTState& s, const Eigen::VectorXd& u_d_next) {
  const int n_f = system_.n_free, n_c = system_.n_contact;
  const double a = hht_.alpha, dt = hht_.dt;
  u_d_next_ = u_d_next;
  u_tilde_ = s.u.head(n_f) + dt * s.v.head(n_f) + dt * dt * (0.5 - hht_.beta) * s.acc.head(n_f);
  Mu_tilde_ = s.Mu_f + dt * s.Mv_f + dt * dt * (0.5 - hht_.beta) * s.Ma_f;
  rhs_.noalias() = hht_.mass_factor() * Mu_tilde_;
  rhs_.noalias() -= (1 - a) * (system_.K_fd * u_d_next);
  rhs_.noalias() -= a * s.Ku.head(n_f);
  if (w_previous_ != 0) rhs_.head(n_c) += w_previous_ * s.r;
}

const Eigen::VectorXd& HHTStepper::solve_free() {
  if (split_) {
    split_->solve_free(rhs_, u_free_contact_);
  } else {
    K_eff_->solve_into(rhs_, u_free_);
    u_free_contact_ = u_free_.head(system_.n_contact);
  }
  return u_free_contact_;
}

void HHTStepper::correct(const Eigen::VectorXd& r_next, HHTState& s) {
  const int n_f = system_.n_free, n_c = system_.n_contact, n_d = system_.n_prescribed;
  const double a = hht_.alpha, dt = hht_.dt;
  if (split_) {
    contact_load_.noalias() = w_ * r_next;
    split_->solve_loaded(contact_load_, u_work_.head(n_f));
  } else {
    rhs_.head(n_c) += w_ * r_next;
    K_eff_->solve_into(rhs_, u_work_.head(n_f));
  }
  u_work_.tail(n_d) = u_d_next_;
  acc_f_next_.noalias() = hht_.mass_factor() * (u_work_.head(n_f) - u_tilde_);
  s.v.head(n_f) += dt * ((1 - hht_.gamma) * s.acc.head(n_f) + hht_.gamma * acc_f_next_);
  s.acc.head(n_f) = acc_f_next_;

  multiply_K(u_work_, Ku_next_);
  Ma_next_ = -(1 - a) * Ku_next_.head(n_f) - a * s.Ku.head(n_f);
  Ma_next_.head(n_c) += w_ * r_next + w_previous_ * s.r;
  s.Mv_f += dt * ((1 - hht_.gamma) * s.Ma_f + hht_.gamma * Ma_next_);
  s.Mu_f = Mu_tilde_ + hht_.beta * dt * dt * Ma_next_;
  s.Ma_f.swap(Ma_next_);  // Ma_next_ is rewritten whole by the next step
  s.u.swap(u_work_);  // u_work_ keeps u(n): u_previous()
  r_previous_.swap(s.r);
  s.r = r_next;
  s.Ku.swap(Ku_next_);
}

}  // namespace slidewave

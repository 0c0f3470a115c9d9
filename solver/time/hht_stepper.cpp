#include "time/hht_stepper.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

#include "fem/assembly.hpp"
#include "linalg/vector_clones.hpp"

namespace slidewave {

Eigen::SparseMatrix<double> effective_matrix(const HHTCoefficients& hht, const Eigen::SparseMatrix<double>& M_ff,
                                             const Eigen::SparseMatrix<double>& K_ff) {
  return hht.mass_factor() * M_ff + (1 - hht.alpha) * K_ff;
}

Eigen::SparseMatrix<double> effective_matrix(const HHTCoefficients& hht, const PartitionedSystem& system) {
  return effective_matrix(hht, system.M_ff, system.K_ff);
}

HHTStepper::HHTStepper(const PartitionedSystem& system, const HHTCoefficients& hht, bool alpha_weighted,
                       std::unique_ptr<SplitSolver> K_eff)
    : system_(system),
      hht_(hht),
      w_(alpha_weighted ? 1 - hht.alpha : 1.0),
      w_previous_(alpha_weighted ? hht.alpha : 0.0),
      K_eff_(std::move(K_eff)) {
  if (!K_eff_ || K_eff_->n_contact() != system.n_contact)
    throw std::invalid_argument("HHTStepper: the split solver's loaded DOFs must be the " +
                                std::to_string(system.n_contact) + " contact DOFs");
  try {
    if (system.n_contact % 2 == 0) K_stencil_ = std::make_unique<StencilProduct>(system.K, system.n_contact / 2);
  } catch (const std::invalid_argument&) {
    // Not the layer's periodic stencil (e.g. a small test system): the sparse product, same result.
  }
  const int n_f = system.n_free, n = system.n_free + system.n_prescribed;
  u_free_contact_.resize(system.n_contact);
  contact_load_.resize(system.n_contact);
  rhs_.resize(n_f);
  u_work_.resize(n);
  Ku_next_.resize(n);
  K_fd_u_d_ = Eigen::VectorXd::Zero(n_f);
  // Rows of K_fd with an entry: [coupled_rows_begin_, coupled_rows_end_).
  const int* row_start = system.K_fd.outerIndexPtr();
  const int* row_count = system.K_fd.innerNonZeroPtr();  // null when compressed
  for (int i = 0; i < n_f; ++i)
    if (row_count ? row_count[i] > 0 : row_start[i + 1] > row_start[i]) {
      coupled_rows_end_ = i + 1;
      if (coupled_rows_begin_ > i) coupled_rows_begin_ = i;
    }
  coupled_rows_begin_ = std::min(coupled_rows_begin_, coupled_rows_end_);
}

HHTState HHTStepper::initial_state(const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& r,
                                   const LinearSolver& M_ff) const {
  Eigen::VectorXd Ku(u.size());
  multiply_K(u, Ku);
  const auto free_mass_product = [this](const Eigen::Ref<const Eigen::VectorXd>& x_f) {
    return leading_block_product(system_.M_ff_rows, system_.n_free, x_f);
  };
  return hht_initial_state(free_mass_product, system_.n_free, system_.n_contact, u, v, r, std::move(Ku), M_ff);
}

HHTState hht_initial_state(const FreeMassProduct& free_mass_product, int n_free, int n_contact,
                           const Eigen::VectorXd& u, const Eigen::VectorXd& v, const Eigen::VectorXd& r,
                           Eigen::VectorXd Ku, const LinearSolver& M_ff) {
  const int n_f = n_free, n_c = n_contact;
  HHTState s;
  s.u = u;
  s.v = v;
  s.r = r;
  s.Ku = std::move(Ku);
  Eigen::VectorXd rhs = -s.Ku.head(n_f);
  rhs.head(n_c) += r;
  s.acc = Eigen::VectorXd::Zero(u.size());
  s.acc.head(n_f) = M_ff.solve(rhs);
  s.Mu_f = free_mass_product(u.head(n_f));
  s.Mv_f = free_mass_product(v.head(n_f));
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

// The Newmark vector updates below are single loops over the free DOFs (one pass over memory instead of one
// per vector expression). Each entry is computed with the same operations, rounded in the same order, as the
// Eigen vector expressions of the formulas in the comments did, so the results are the same bits. The
// predictor u~ = u + dt v + c a and its mass product M u~ are not stored: the correction recomputes them
// from the state, which has not changed since the predictor (the same operations, the same bits).

namespace {

/// The coefficients of the predictor and of the free solve's right-hand side.
struct PredictorCoefficients {
  double dt, c, mass, a;  ///< c = dt^2 (1/2 - beta), mass = 1 / (beta dt^2), a = alpha
};

/// The predictor u~ = u + dt v + c a, of a displacement or (the same relation) of its mass product.
inline double predicted(double u, double v, double acc, const PredictorCoefficients& k) {
  return u + k.dt * v + k.c * acc;
}

/// One row of the free solve's right-hand side M u~ / (beta dt^2) - (1-a) K_fd u_d(n+1) - a K u(n), from the
/// mass products M u, M v, M a of time n, Kd = (1-a) K_fd u_d(n+1) and Ku = K u(n) (without a' C^T r(n)).
inline double free_solve_rhs(double Mu, double Mv, double Ma, double Kd, double Ku, const PredictorCoefficients& k) {
  return k.mass * predicted(Mu, Mv, Ma, k) - Kd - k.a * Ku;
}

PredictorCoefficients predictor_coefficients(const HHTCoefficients& hht) {
  return {hht.dt, hht.dt * hht.dt * (0.5 - hht.beta), hht.mass_factor(), hht.alpha};
}

/// The coefficients of the mass-product update of correct().
struct MassCoefficients {
  double k_next, w, w_previous, g, g_old, b;  ///< k_next = -(1-a), b = beta dt^2
  PredictorCoefficients predictor;
};

/// n rows of the mass-product update (formulas in correct()); kForces: the contact rows, which carry
/// w r(n+1) + a' r(n); kPredict: also the next step's right-hand side. Restrict parameters and a plain loop,
/// so that the compiler vectorizes it (the same operations per entry, so the same bits).
template <bool kForces, bool kPredict>
__attribute__((always_inline)) inline void update_mass_rows(const double* __restrict Ku_next,
                                                            const double* __restrict Ku, const double* __restrict r_new,
                                                            const double* __restrict r_old, const double* __restrict Kd,
                                                            double* __restrict Ma, double* __restrict Mv,
                                                            double* __restrict Mu, double* __restrict rhs, long n,
                                                            const MassCoefficients& coefficients) {
  const MassCoefficients k = coefficients;
  const PredictorCoefficients& p = k.predictor;
  for (long i = 0; i < n; ++i) {
    double Ma_i = k.k_next * Ku_next[i] - p.a * Ku[i];
    if constexpr (kForces) Ma_i = Ma_i + (k.w * r_new[i] + k.w_previous * r_old[i]);
    const double Mu_tilde = predicted(Mu[i], Mv[i], Ma[i], p);
    Mv[i] += p.dt * (k.g_old * Ma[i] + k.g * Ma_i);
    Ma[i] = Ma_i;
    Mu[i] = Mu_tilde + k.b * Ma_i;
    if constexpr (kPredict) rhs[i] = free_solve_rhs(Mu[i], Mv[i], Ma_i, Kd[i], Ku_next[i], p);
  }
}

/// Rows [begin, end) of the vectors of correct() through update_mass_rows.
template <bool kForces, bool kPredict>
__attribute__((always_inline)) inline void update_mass_rows_between(int begin, int end, const double* Ku_next,
                                                                    const double* Ku, const double* r_new,
                                                                    const double* r_old, const double* Kd, double* Ma,
                                                                    double* Mv, double* Mu, double* rhs,
                                                                    const MassCoefficients& k) {
  update_mass_rows<kForces, kPredict>(Ku_next + begin, Ku + begin, kForces ? r_new + begin : nullptr,
                                      kForces ? r_old + begin : nullptr, Kd + begin, Ma + begin, Mv + begin, Mu + begin,
                                      rhs + begin, end - begin, k);
}

}  // namespace

SLIDEWAVE_VECTOR_CLONES
void HHTStepper::predict(const HHTState& s, const Eigen::VectorXd& u_d_next) {
  if (predicted_ && u_d_next == u_d_next_) {  // done by the last correct(), from this state and this u_d
    predicted_ = false;
    return;
  }
  predicted_ = false;
  const int n_f = system_.n_free;
  prescribe(u_d_next);
  // M u~ = M u + dt M v + c M a;  rhs = M u~ / (beta dt^2) - (1-a) K_fd u_d - a K u
  const PredictorCoefficients k = predictor_coefficients(hht_);
  const double *Mu = s.Mu_f.data(), *Mv = s.Mv_f.data(), *Ma = s.Ma_f.data(), *Ku = s.Ku.data(), *Kd = K_fd_u_d_.data();
  double* __restrict rhs = rhs_.data();
  for (int i = 0; i < n_f; ++i) rhs[i] = free_solve_rhs(Mu[i], Mv[i], Ma[i], Kd[i], Ku[i], k);
  add_previous_contact_forces(s.r);
}

void HHTStepper::prescribe(const Eigen::VectorXd& u_d_next) {
  u_d_next_ = u_d_next;
  // Eigen folds the scalar into the sparse factor: ((1-a) K_fd) u_d, which rounds differently from (1-a) (K_fd u_d).
  // Only the rows that couple to prescribed DOFs (the layer's top row of free nodes) are computed: the
  // product is row by row, and the others stay the exact zeros it would give them.
  K_fd_u_d_.segment(coupled_rows_begin_, coupled_rows_end_ - coupled_rows_begin_).noalias() =
      (1 - hht_.alpha) *
      (system_.K_fd.middleRows(coupled_rows_begin_, coupled_rows_end_ - coupled_rows_begin_) * u_d_next);
}

void HHTStepper::add_previous_contact_forces(const Eigen::VectorXd& r) {
  if (w_previous_ != 0) rhs_.head(system_.n_contact) += w_previous_ * r;
}

const Eigen::VectorXd& HHTStepper::solve_free() {
  K_eff_->solve_free(rhs_, u_free_contact_);
  return u_free_contact_;
}

SLIDEWAVE_VECTOR_CLONES
void HHTStepper::correct(const Eigen::VectorXd& r_next, HHTState& s, const Eigen::VectorXd* u_d_following) {
  const int n_f = system_.n_free, n_c = system_.n_contact, n_d = system_.n_prescribed;
  const double a = hht_.alpha, dt = hht_.dt;
  contact_load_.noalias() = w_ * r_next;
  K_eff_->solve_loaded(contact_load_, u_work_.head(n_f));
  u_work_.tail(n_d) = u_d_next_;
  const double g = hht_.gamma, g_old = 1 - hht_.gamma;
  const PredictorCoefficients p = predictor_coefficients(hht_);
  {
    // u~ = u + dt v + c a;  a(n+1) = (u(n+1) - u~) / (beta dt^2);  v += dt ((1-gamma) a(n) + gamma a(n+1))
    const double *u_next = u_work_.data(), *u = s.u.data();
    double* __restrict v = s.v.data(), * __restrict acc = s.acc.data();
    for (int i = 0; i < n_f; ++i) {
      const double u_tilde = predicted(u[i], v[i], acc[i], p);
      const double acc_next = p.mass * (u_next[i] - u_tilde);
      v[i] += dt * (g_old * acc[i] + g * acc_next);
      acc[i] = acc_next;
    }
  }

  multiply_K(u_work_, Ku_next_);
  // With u_d_following, the loop below also does the following step's predict() (the same operations on the
  // values it has just computed, so the same bits), which then has nothing left to do: one pass over the
  // mass products instead of two.
  const bool predict_following = u_d_following != nullptr;
  if (predict_following) prescribe(*u_d_following);
  // M a(n+1) = -(1-a) K u(n+1) - a K u(n) + w C^T r(n+1) + a' C^T r(n);
  // M v += dt ((1-gamma) M a(n) + gamma M a(n+1));  M u = M u~ + beta dt^2 M a(n+1)
  // [and the next step's rhs from M u~ = M u + dt M v + c M a at n+1]
  const MassCoefficients k{-(1 - a), w_, w_previous_, g, g_old, hht_.beta * dt * dt, p};
  const double *Ku_next = Ku_next_.data(), *Ku = s.Ku.data(), *r_new = r_next.data(), *r_old = s.r.data(),
               *Kd = K_fd_u_d_.data();
  double *Ma = s.Ma_f.data(), *Mv = s.Mv_f.data(), *Mu = s.Mu_f.data(), *rhs = rhs_.data();
  if (predict_following) {  // the contact rows [0, n_c) carry the forces
    update_mass_rows_between<true, true>(0, n_c, Ku_next, Ku, r_new, r_old, Kd, Ma, Mv, Mu, rhs, k);
    update_mass_rows_between<false, true>(n_c, n_f, Ku_next, Ku, r_new, r_old, Kd, Ma, Mv, Mu, rhs, k);
  } else {
    update_mass_rows_between<true, false>(0, n_c, Ku_next, Ku, r_new, r_old, Kd, Ma, Mv, Mu, rhs, k);
    update_mass_rows_between<false, false>(n_c, n_f, Ku_next, Ku, r_new, r_old, Kd, Ma, Mv, Mu, rhs, k);
  }
  s.u.swap(u_work_);  // u_work_ keeps u(n): u_previous()
  r_previous_.swap(s.r);
  s.r = r_next;
  s.Ku.swap(Ku_next_);
  if (predict_following) {
    add_previous_contact_forces(s.r);
    predicted_ = true;
  }
}

}  // namespace slidewave

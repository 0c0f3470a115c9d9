// The production HHT stepper (time/hht_stepper.hpp, the one simulate() uses) on small linear systems with
// known solutions:
//   - a single-DOF oscillator m a + k (u - u_d) = r, driven through the contact-force path (r(t) given to
//     correct()) or through the prescribed DOF (a support u_d(t); lumped mass, so M_fd = 0 and any u_d(t)
//     is exact);
//   - a chain of masses with consistent mass, fixed at one end and pulled at constant velocity at the
//     other (the production loading: prescribed DOFs with a = 0), against its modal solution.
// Oracles: convergence order 2 when halving dt (MFEM test_ode2 style), spectral radius at omega dt -> inf
// equal to (1-a)/(1+a) (classic HHT with alpha_H = -a), exact energy conservation for a = 0, rho <= 1
// everywhere (unconditional stability), decay for a > 0.
// Every test runs on both paths of the stepper: two K_eff solves per step, and one pass (a split solver:
// here a dense superposition u = u_free + Z g; the FFT split solver of the layer on a periodic array of the
// oscillators, OscillatorArrayOnTheFftSplitSolve).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "linalg/block_circulant_solver.hpp"
#include "linalg/two_solve_split.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

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
    return HHTStepper(view(), hht, alpha_weighted,
                      std::make_unique<TwoSolveSplit>(std::make_unique<DenseSolver>(effective_matrix(hht, view())),
                                                      n_contact));
  }
};

/// Free mass (DOF 0, also the contact DOF) on a spring k to a support (DOF 1, prescribed).
OwnedSystem oscillator(double m, double k) {
  Eigen::MatrixXd K(2, 2), M = Eigen::MatrixXd::Zero(2, 2);
  K << k, -k, -k, k;
  M(0, 0) = m;
  M(1, 1) = m;
  return OwnedSystem(K, M, 1, 1);
}

/// n_x columns of the oscillator in both directions, numbered as the layer's bottom row (free DOF 2 i + d,
/// all of them contact DOFs) and top row (support 2 n_x + 2 i + d): K_eff is block-circulant with n_y = 1.
OwnedSystem oscillator_array(double m, double k, int n_x) {
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

OwnedSystem oscillator_on(Path path, double m, double k) {
  return path == Path::one_pass_fft ? oscillator_array(m, k, 4) : oscillator(m, k);
}

/// (u_free, u_d) in every copy of the oscillator.
Eigen::VectorXd both(const OwnedSystem& system, double free, double prescribed) {
  Eigen::VectorXd x(system.n_free + system.n_prescribed);
  x.head(system.n_free).setConstant(free);
  x.tail(system.n_prescribed).setConstant(prescribed);
  return x;
}

/// Runs n_steps with the contact force r(t) and the support u_d(t); returns the final state.
HHTState integrate(const OwnedSystem& system, const HHTCoefficients& hht, HHTState s, int n_steps,
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

HHTState start(const OwnedSystem& system, const HHTCoefficients& hht, const Eigen::VectorXd& u,
               const Eigen::VectorXd& v, const Eigen::VectorXd& r) {
  return system.stepper(hht).initial_state(u, v, r, DenseSolver(system.M_ff));
}

const double kAlphas[] = {0.0, 0.05, 0.1, 1.0 / 3.0};

TEST(HHT, CoefficientsOfThePaperConvention) {
  for (double a : kAlphas) {
    const HHTCoefficients c(a, 0.25);
    EXPECT_DOUBLE_EQ(c.alpha, a);
    EXPECT_DOUBLE_EQ(c.beta, (1 + a) * (1 + a) / 4);  // classic beta = (1 - alpha_H)^2 / 4, alpha_H = -a
    EXPECT_DOUBLE_EQ(c.gamma, 0.5 + a);               // classic gamma = 1/2 - alpha_H
    EXPECT_DOUBLE_EQ(c.mass_factor(), 1 / (c.beta * 0.25 * 0.25));
  }
}

enum class Drive { none, contact_force, support };

/// Max over the final state of |u - u_exact|, |v - v_exact| / omega, at t_end, for m a + k u = F cos(Omega t)
/// with F applied as the contact force or as k u_d.
double oscillator_error(double a, int n_steps, Drive drive, Path path) {
  const double m = 2.0, k = 8.0, omega = std::sqrt(k / m), t_end = 10.0;
  const double F_amp = drive == Drive::none ? 0.0 : 3.0, Omega = 0.7;
  const auto F = [&](double t) { return F_amp * std::cos(Omega * t); };
  const auto r = [&](double t) { return drive == Drive::contact_force ? F(t) : 0.0; };
  const auto u_d = [&](double t) { return drive == Drive::support ? F(t) / k : 0.0; };
  const double u0 = 1.0, v0 = 0.3;
  const double particular = F_amp / (k - m * Omega * Omega);
  const double A = u0 - particular, B = v0 / omega;
  const double u_exact = A * std::cos(omega * t_end) + B * std::sin(omega * t_end) + particular * std::cos(Omega * t_end);
  const double v_exact = omega * (-A * std::sin(omega * t_end) + B * std::cos(omega * t_end)) -
                         particular * Omega * std::sin(Omega * t_end);
  const OwnedSystem system = oscillator_on(path, m, k);
  const HHTCoefficients hht(a, t_end / n_steps);
  HHTState s = start(system, hht, both(system, u0, u_d(0)), both(system, v0, 0),
                     Eigen::VectorXd::Constant(system.n_contact, r(0)));
  s = integrate(system, hht, s, n_steps, r, u_d, true, path);
  const int n_f = system.n_free;
  return std::max((s.u.head(n_f).array() - u_exact).abs().maxCoeff(),
                  (s.v.head(n_f).array() - v_exact).abs().maxCoeff() / omega);
}

/// Observed order log2(e(dt) / e(dt/2)) over three halvings must be 2 (second order, not more).
void expect_second_order(const std::function<double(int)>& error, const std::string& what) {
  double previous = 0;
  for (int n_steps : {200, 400, 800, 1600}) {
    const double e = error(n_steps);
    if (previous > 0) {
      const double order = std::log2(previous / e);
      EXPECT_GT(order + 0.1, 2.0) << what << " n = " << n_steps;
      EXPECT_LT(order - 0.1, 2.0) << what << " n = " << n_steps;
    }
    previous = e;
  }
}

class HHTPaths : public ::testing::TestWithParam<Path> {};
INSTANTIATE_TEST_SUITE_P(Stepper, HHTPaths, ::testing::Values(Path::two_solves, Path::one_pass),
                         [](const auto& info) { return info.param == Path::one_pass ? "OnePass" : "TwoSolves"; });

TEST_P(HHTPaths, OscillatorConvergesWithOrderTwo) {
  for (Drive drive : {Drive::none, Drive::contact_force, Drive::support})
    for (double a : kAlphas)
      expect_second_order([&](int n) { return oscillator_error(a, n, drive, GetParam()); },
                          "a = " + std::to_string(a) + " drive " + std::to_string(static_cast<int>(drive)));
}

/// Chain of n_f free nodes and one prescribed node (two-node bar elements: springs k, consistent mass):
/// node 0 is tied to a wall by a spring, the last node (prescribed) moves at V t.
/// Error at t_end against the modal solution u = u_qs(t) + sum_i (A_i cos w_i t + B_i sin w_i t) phi_i,
/// u_qs = -K_ff^-1 K_fd V t (linear in t, so the prescribed DOF has a = 0 as the stepper requires).
double chain_error(double a, int n_steps, Path path) {
  const int n_f = 3, n = n_f + 1;
  const double k = 5.0, rho_h = 1.5, V = 0.4, t_end = 6.0;
  Eigen::MatrixXd K = Eigen::MatrixXd::Zero(n, n), M = Eigen::MatrixXd::Zero(n, n);
  K(0, 0) += k;  // spring to the wall
  for (int e = 0; e + 1 < n; ++e) {
    K.block<2, 2>(e, e) += k * (Eigen::Matrix2d() << 1, -1, -1, 1).finished();
    M.block<2, 2>(e, e) += rho_h / 6 * (Eigen::Matrix2d() << 2, 1, 1, 2).finished();
  }
  const OwnedSystem system(K, M, n_f, 1);
  const Eigen::MatrixXd K_ff = K.topLeftCorner(n_f, n_f), M_ff = M.topLeftCorner(n_f, n_f);
  const Eigen::VectorXd qs_rate = -K_ff.ldlt().solve(K.topRightCorner(n_f, 1) * V);  // d u_qs / dt
  Eigen::VectorXd u0(n), v0(n);
  u0 << 0.2, -0.1, 0.05, 0.0;
  v0 << 0.0, 0.3, 0.0, V;
  // Modal solution of the deviation from the quasi-static motion.
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> modes(K_ff, M_ff);
  const Eigen::MatrixXd& Phi = modes.eigenvectors();  // Phi^T M Phi = I
  const Eigen::VectorXd q0 = Phi.transpose() * M_ff * u0.head(n_f);
  const Eigen::VectorXd qd0 = Phi.transpose() * M_ff * (v0.head(n_f) - qs_rate);
  Eigen::VectorXd q(n_f), qd(n_f);
  for (int i = 0; i < n_f; ++i) {
    const double w = std::sqrt(modes.eigenvalues()(i));
    q(i) = q0(i) * std::cos(w * t_end) + qd0(i) / w * std::sin(w * t_end);
    qd(i) = -q0(i) * w * std::sin(w * t_end) + qd0(i) * std::cos(w * t_end);
  }
  const Eigen::VectorXd u_exact = qs_rate * t_end + Phi * q, v_exact = qs_rate + Phi * qd;

  const HHTCoefficients hht(a, t_end / n_steps);
  HHTState s = start(system, hht, u0, v0, Eigen::VectorXd::Zero(1));
  s = integrate(system, hht, s, n_steps, [](double) { return 0.0; }, [&](double t) { return V * t; }, true, path);
  EXPECT_DOUBLE_EQ(s.u(n_f), V * t_end);
  EXPECT_EQ(s.acc(n_f), 0.0);
  return std::max((s.u.head(n_f) - u_exact).cwiseAbs().maxCoeff(), (s.v.head(n_f) - v_exact).cwiseAbs().maxCoeff());
}

TEST_P(HHTPaths, ChainPulledAtConstantVelocityConvergesWithOrderTwo) {
  for (double a : kAlphas)
    expect_second_order([&](int n) { return chain_error(a, n, GetParam()); }, "a = " + std::to_string(a));
}

TEST_P(HHTPaths, MassProductsStayConsistentWithTheState) {
  // The stepper carries M_ff u, M_ff v, M_ff a instead of recomputing them: they must stay the products.
  const int n_f = 3;
  Eigen::MatrixXd K(4, 4), M(4, 4);
  K << 4, -1, 0, -1, -1, 4, -1, 0, 0, -1, 4, -1, -1, 0, -1, 4;
  M << 4, 1, 0, 1, 1, 4, 1, 0, 0, 1, 4, 1, 1, 0, 1, 4;
  const OwnedSystem system(K, M, n_f, 2);
  const HHTCoefficients hht(0.1, 0.3);
  HHTState s = start(system, hht, Eigen::Vector4d(0.1, -0.2, 0.3, 0.05), Eigen::Vector4d(0, 0.1, 0, 0.2),
                     Eigen::Vector2d(0.5, -0.1));
  s = integrate(system, hht, s, 50, [](double t) { return std::sin(t); }, [](double t) { return 0.05 + 0.2 * t; },
                true, GetParam());
  const Eigen::MatrixXd M_ff = M.topLeftCorner(n_f, n_f);
  EXPECT_LT((s.Mu_f - M_ff * s.u.head(n_f)).norm(), 1e-12);
  EXPECT_LT((s.Mv_f - M_ff * s.v.head(n_f)).norm(), 1e-12);
  EXPECT_LT((s.Ma_f - M_ff * s.acc.head(n_f)).norm(), 1e-12);
  EXPECT_LT((s.Ku - K * s.u).norm(), 1e-12);
}

/// Amplification matrix of one production step on (u, v, a) for omega dt = Omega (m = 1, dt = 1).
Eigen::Matrix3d amplification(double a, double Omega, Path path) {
  Eigen::MatrixXd K(1, 1), M(1, 1);
  K << Omega * Omega;
  M << 1.0;
  const OwnedSystem system(K, M, 1, 0);
  const HHTCoefficients hht(a, 1.0);
  HHTStepper stepper = system.stepper(hht, true, path);
  Eigen::Matrix3d A;
  for (int col = 0; col < 3; ++col) {
    HHTState s;
    s.u = Eigen::VectorXd::Constant(1, col == 0 ? 1.0 : 0.0);
    s.v = Eigen::VectorXd::Constant(1, col == 1 ? 1.0 : 0.0);
    s.acc = Eigen::VectorXd::Constant(1, col == 2 ? 1.0 : 0.0);
    s.Ku = K * s.u;
    s.Mu_f = s.u;
    s.Mv_f = s.v;
    s.Ma_f = s.acc;
    s.r = Eigen::VectorXd(0);
    stepper.predict(s, Eigen::VectorXd(0));
    stepper.solve_free();
    stepper.correct(Eigen::VectorXd(0), s);
    A.col(col) << s.u(0), s.v(0), s.acc(0);
  }
  return A;
}

double spectral_radius(const Eigen::Matrix3d& A) {
  return Eigen::EigenSolver<Eigen::Matrix3d>(A, false).eigenvalues().cwiseAbs().maxCoeff();
}

TEST_P(HHTPaths, SpectralRadiusAtInfinityIsOneMinusAOverOnePlusA) {
  const auto amplification = [this](double a, double Omega) { return slidewave::amplification(a, Omega, GetParam()); };
  for (double a : {0.0, 0.05, 0.1}) {
    const double rho_inf = (1 - a) / (1 + a);
    EXPECT_NEAR(spectral_radius(amplification(a, 1e5)), rho_inf, 1e-8) << "a = " << a;
  }
  EXPECT_NEAR(spectral_radius(amplification(0.1, 1e5)), 0.9 / 1.1, 1e-8);  // the paper's alpha
  // At a = 1/3 all three roots meet at 1/2 in the limit (triple root), so rho approaches 1/2 only like
  // (omega dt)^(-2/3): check the limit through that rate.
  double previous = 0;
  for (double Omega : {1e2, 1e4, 1e6}) {
    const double error = spectral_radius(amplification(1.0 / 3.0, Omega)) - 0.5;
    EXPECT_GT(error, 0);
    if (previous > 0) {
      EXPECT_NEAR(std::log10(previous / error), 4.0 / 3.0, 0.05) << "10^2 in omega dt: 10^(4/3) in error";
    }
    previous = error;
  }
  EXPECT_LT(previous, 1e-4);
}

TEST_P(HHTPaths, UnconditionallyStableAndDissipativeOnlyForPositiveA) {
  const auto amplification = [this](double a, double Omega) { return slidewave::amplification(a, Omega, GetParam()); };
  for (double a : kAlphas)
    for (double log_Omega = -2; log_Omega <= 5; log_Omega += 0.25) {
      const double rho = spectral_radius(amplification(a, std::pow(10.0, log_Omega)));
      EXPECT_LE(rho, 1 + 1e-12) << "a = " << a << " omega dt = " << std::pow(10.0, log_Omega);
      if (a == 0) {
        EXPECT_NEAR(rho, 1.0, 1e-9) << "trapezoidal rule: no numerical dissipation";
      } else if (log_Omega >= 0) {
        EXPECT_LT(rho, 1 - 1e-4) << "a = " << a << ": high frequencies must decay";
      }
    }
}

double oscillator_energy(double m, double k, const HHTState& s) {
  return 0.5 * m * s.v(0) * s.v(0) + 0.5 * k * s.u(0) * s.u(0);
}

void expect_energy_conserved(Path path) {
  const double m = 3.0, k = 12.0;
  const OwnedSystem system = oscillator_on(path, m, k);
  const HHTCoefficients hht(0.0, 0.4);
  HHTStepper stepper = system.stepper(hht, true, path);
  HHTState s = start(system, hht, both(system, 0.2, 0), both(system, -1.1, 0), Eigen::VectorXd::Zero(system.n_contact));
  const double E0 = oscillator_energy(m, k, s);
  double max_drift = 0;
  for (int n = 0; n < 20000; ++n) {
    stepper.predict(s, Eigen::VectorXd::Zero(system.n_prescribed));
    stepper.solve_free();
    stepper.correct(Eigen::VectorXd::Zero(system.n_contact), s);
    max_drift = std::max(max_drift, std::fabs(oscillator_energy(m, k, s) - E0));
  }
  EXPECT_LE(max_drift, 1e-12 * E0);
}

void expect_dissipation(Path path) {
  const double m = 1.0, k = 1.0;
  const OwnedSystem system = oscillator_on(path, m, k);
  for (double a : {0.05, 0.1, 1.0 / 3.0}) {
    const HHTCoefficients hht(a, 0.5);
    HHTState s = start(system, hht, both(system, 1.0, 0), both(system, 0, 0), Eigen::VectorXd::Zero(system.n_contact));
    const double E0 = oscillator_energy(m, k, s);
    s = integrate(system, hht, s, 2000, [](double) { return 0.0; }, [](double) { return 0.0; }, true, path);
    EXPECT_LT(oscillator_energy(m, k, s), 0.99 * E0) << "a = " << a;
  }
}

TEST_P(HHTPaths, TrapezoidalRuleConservesEnergyExactly) { expect_energy_conserved(GetParam()); }
TEST_P(HHTPaths, PositiveADissipatesEnergy) { expect_dissipation(GetParam()); }

// The same oscillator tests through the FFT split solve of the layer's solver (the "spectral" path).
TEST(HHT, OscillatorArrayOnTheFftSplitSolve) {
  for (Drive drive : {Drive::none, Drive::contact_force, Drive::support})
    for (double a : kAlphas)
      expect_second_order([&](int n) { return oscillator_error(a, n, drive, Path::one_pass_fft); },
                          "a = " + std::to_string(a) + " drive " + std::to_string(static_cast<int>(drive)));
  expect_energy_conserved(Path::one_pass_fft);
  expect_dissipation(Path::one_pass_fft);
}

TEST_P(HHTPaths, ContactWeightingsCoincideForTheTrapezoidalRule) {
  // At a = 0, "alpha" weighting (w = 1 - a, a' = a) and "end" weighting (w = 1, a' = 0) are the same scheme.
  const OwnedSystem system = oscillator(2.0, 8.0);
  const HHTCoefficients hht(0.0, 0.05);
  const auto r = [](double t) { return std::cos(0.7 * t); };
  const HHTState s0 = start(system, hht, Eigen::Vector2d(1, 0), Eigen::Vector2d(0.3, 0), Eigen::VectorXd::Constant(1, 1.0));
  const auto zero = [](double) { return 0.0; };
  const HHTState alpha = integrate(system, hht, s0, 300, r, zero, true, GetParam()),
                 end = integrate(system, hht, s0, 300, r, zero, false, GetParam());
  EXPECT_EQ(alpha.u, end.u);
  EXPECT_EQ(alpha.v, end.v);
  EXPECT_EQ(system.stepper(HHTCoefficients(0.1, 0.05), true).contact_weight(), 0.9);
  EXPECT_EQ(system.stepper(HHTCoefficients(0.1, 0.05), false).contact_weight(), 1.0);
}

}  // namespace
}  // namespace slidewave

// The production HHT stepper (time/hht_stepper.hpp, the one simulate() uses) on small linear systems with
// known solutions:
//   - a single-DOF oscillator m a + k (u - u_d) = r, driven through the contact-force path (r(t) given to
//     correct()) or through the prescribed DOF (a support u_d(t); lumped mass, so M_fd = 0 and any u_d(t)
//     is exact);
//   - a chain of masses with consistent mass, fixed at one end and pulled at constant velocity at the
//     other (the production loading: prescribed DOFs with a = 0), against its modal solution.
// Oracles: convergence order 2 when halving dt (MFEM test_ode2 style); the two contact weightings coincide
// at a = 0. The stepper as a linear map (spectral radius, stability, energy) is hht_stability_test.cpp;
// the systems and solvers of both are hht_support.hpp.
// Every test runs on both paths of the stepper: two K_eff solves per step, and one pass (a split solver:
// here a dense superposition u = u_free + Z g; the FFT split solver of the layer on a periodic array of the
// oscillators, OscillatorArrayOnTheFftSplitSolve).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>
#include <string>

#include "hht_support.hpp"

namespace slidewave {
namespace {

using namespace hht_testing;

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
  const double u_exact =
      A * std::cos(omega * t_end) + B * std::sin(omega * t_end) + particular * std::cos(Omega * t_end);
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
  s = integrate(
      system, hht, s, n_steps, [](double) { return 0.0; }, [&](double t) { return V * t; }, true, path);
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
  s = integrate(
      system, hht, s, 50, [](double t) { return std::sin(t); }, [](double t) { return 0.05 + 0.2 * t; }, true,
      GetParam());
  const Eigen::MatrixXd M_ff = M.topLeftCorner(n_f, n_f);
  EXPECT_LT((s.Mu_f - M_ff * s.u.head(n_f)).norm(), 1e-12);
  EXPECT_LT((s.Mv_f - M_ff * s.v.head(n_f)).norm(), 1e-12);
  EXPECT_LT((s.Ma_f - M_ff * s.acc.head(n_f)).norm(), 1e-12);
  EXPECT_LT((s.Ku - K * s.u).norm(), 1e-12);
}

// The same oscillator tests through the FFT split solve of the layer's solver (the "spectral" path).
TEST(HHT, OscillatorArrayOnTheFftSplitSolve) {
  for (Drive drive : {Drive::none, Drive::contact_force, Drive::support})
    for (double a : kAlphas)
      expect_second_order([&](int n) { return oscillator_error(a, n, drive, Path::one_pass_fft); },
                          "a = " + std::to_string(a) + " drive " + std::to_string(static_cast<int>(drive)));
}

TEST_P(HHTPaths, ContactWeightingsCoincideForTheTrapezoidalRule) {
  // At a = 0, "alpha" weighting (w = 1 - a, a' = a) and "end" weighting (w = 1, a' = 0) are the same scheme.
  const OwnedSystem system = oscillator(2.0, 8.0);
  const HHTCoefficients hht(0.0, 0.05);
  const auto r = [](double t) { return std::cos(0.7 * t); };
  const HHTState s0 =
      start(system, hht, Eigen::Vector2d(1, 0), Eigen::Vector2d(0.3, 0), Eigen::VectorXd::Constant(1, 1.0));
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

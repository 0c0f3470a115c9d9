// The production HHT stepper (time/hht_stepper.hpp) as a linear map: its amplification matrix on a
// single-DOF oscillator has spectral radius (1-a)/(1+a) at omega dt -> inf (classic HHT with
// alpha_H = -a) and rho <= 1 everywhere (unconditional stability), with decay only for a > 0; the
// trapezoidal rule (a = 0) conserves the oscillator's energy exactly, a > 0 dissipates it. On both
// paths of the stepper and, for the energy, on the FFT split solve (hht_support.hpp).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "hht_support.hpp"

namespace slidewave {
namespace {

using namespace hht_testing;

class HHTStability : public ::testing::TestWithParam<Path> {};
INSTANTIATE_TEST_SUITE_P(Stepper, HHTStability, ::testing::Values(Path::two_solves, Path::one_pass),
                         [](const auto& info) { return info.param == Path::one_pass ? "OnePass" : "TwoSolves"; });

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

TEST_P(HHTStability, SpectralRadiusAtInfinityIsOneMinusAOverOnePlusA) {
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

TEST_P(HHTStability, UnconditionallyStableAndDissipativeOnlyForPositiveA) {
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
    s = integrate(
        system, hht, s, 2000, [](double) { return 0.0; }, [](double) { return 0.0; }, true, path);
    EXPECT_LT(oscillator_energy(m, k, s), 0.99 * E0) << "a = " << a;
  }
}

TEST_P(HHTStability, TrapezoidalRuleConservesEnergyExactly) { expect_energy_conserved(GetParam()); }
TEST_P(HHTStability, PositiveADissipatesEnergy) { expect_dissipation(GetParam()); }

// The energy tests through the FFT split solve of the layer's solver (the "spectral" path).
TEST(HHT, OscillatorArrayOnTheFftSplitSolveKeepsEnergy) {
  expect_energy_conserved(Path::one_pass_fft);
  expect_dissipation(Path::one_pass_fft);
}

}  // namespace
}  // namespace slidewave

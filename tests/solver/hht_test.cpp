// HHT integration in the paper's convention (time/hht.hpp) on a single-DOF oscillator m a + k u = F:
//     m a1 + (1-a) k u1 + a k u0 = (1-a) F1 + a F0,
//     u1 = u0 + dt v0 + dt^2 [(1/2 - beta) a0 + beta a1],  v1 = v0 + dt [(1 - gamma) a0 + gamma a1],
// solved as the simulation does (effective stiffness m * mass_factor + (1-a) k on the predictor).
// Oracles: convergence order 2 when halving dt, spectral radius at omega dt -> infinity equal to
// (1-a)/(1+a) (classic HHT with alpha_H = -a: rho_inf = (1+alpha_H)/(1-alpha_H)), exact energy
// conservation for a = 0, rho <= 1 everywhere (unconditional stability).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>
#include <functional>

#include "time/hht.hpp"

namespace slidewave {
namespace {

struct State {
  double u, v, a;
};

/// One HHT step of m a + k u = F(t), written from the formulas of time/hht.hpp.
State hht_step(const HHTCoefficients& c, double m, double k, const State& s, double F0, double F1) {
  const double dt = c.dt, a = c.alpha;
  const double u_tilde = s.u + dt * s.v + dt * dt * (0.5 - c.beta) * s.a;
  const double k_eff = c.mass_factor() * m + (1 - a) * k;
  const double u1 = (c.mass_factor() * m * u_tilde - a * k * s.u + (1 - a) * F1 + a * F0) / k_eff;
  const double a1 = c.mass_factor() * (u1 - u_tilde);
  const double v1 = s.v + dt * ((1 - c.gamma) * s.a + c.gamma * a1);
  return {u1, v1, a1};
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

/// Max over the final state of |u - u_exact|, |v - v_exact| / omega, at t_end.
double final_error(double a, int n_steps, bool forced) {
  const double m = 2.0, k = 8.0, omega = std::sqrt(k / m), t_end = 10.0;
  const double F_amp = forced ? 3.0 : 0.0, Omega = 0.7;
  const auto F = [&](double t) { return F_amp * std::cos(Omega * t); };
  const double u0 = 1.0, v0 = 0.3;
  const double particular = F_amp / (k - m * Omega * Omega);
  const double A = u0 - particular, B = v0 / omega;
  const auto u_exact = [&](double t) { return A * std::cos(omega * t) + B * std::sin(omega * t) + particular * std::cos(Omega * t); };
  const auto v_exact = [&](double t) {
    return omega * (-A * std::sin(omega * t) + B * std::cos(omega * t)) - particular * Omega * std::sin(Omega * t);
  };
  const HHTCoefficients c(a, t_end / n_steps);
  State s{u0, v0, (F(0) - k * u0) / m};  // consistent initial acceleration
  for (int n = 0; n < n_steps; ++n) s = hht_step(c, m, k, s, F(n * c.dt), F((n + 1) * c.dt));
  return std::max(std::fabs(s.u - u_exact(t_end)), std::fabs(s.v - v_exact(t_end)) / omega);
}

TEST(HHT, SecondOrderConvergenceWhenHalvingDt) {
  for (bool forced : {false, true})
    for (double a : kAlphas) {
      double previous = 0;
      for (int n_steps : {200, 400, 800, 1600}) {
        const double error = final_error(a, n_steps, forced);
        if (previous > 0) {
          const double order = std::log2(previous / error);
          EXPECT_GT(order, 1.9) << "a = " << a << " forced = " << forced << " n = " << n_steps;
          EXPECT_LT(order, 2.1) << "a = " << a << " forced = " << forced << " n = " << n_steps;
        }
        previous = error;
      }
    }
}

/// Amplification matrix of one step on the scaled state (u, dt v, dt^2 a) for omega dt = Omega.
Eigen::Matrix3d amplification(double a, double Omega) {
  const HHTCoefficients c(a, 1.0);
  const double m = 1.0, k = Omega * Omega;
  Eigen::Matrix3d A;
  for (int col = 0; col < 3; ++col) {
    State s{col == 0 ? 1.0 : 0.0, col == 1 ? 1.0 : 0.0, col == 2 ? 1.0 : 0.0};
    const State s1 = hht_step(c, m, k, s, 0, 0);
    A.col(col) << s1.u, s1.v, s1.a;
  }
  return A;
}

double spectral_radius(const Eigen::Matrix3d& A) {
  return Eigen::EigenSolver<Eigen::Matrix3d>(A, false).eigenvalues().cwiseAbs().maxCoeff();
}

TEST(HHT, SpectralRadiusAtInfinityIsOneMinusAOverOnePlusA) {
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

TEST(HHT, UnconditionallyStableAndDissipativeOnlyForPositiveA) {
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

TEST(HHT, TrapezoidalRuleConservesEnergyExactly) {
  const double m = 3.0, k = 12.0;
  const HHTCoefficients c(0.0, 0.4);
  State s{0.2, -1.1, -k * 0.2 / m};
  const auto energy = [&](const State& x) { return 0.5 * m * x.v * x.v + 0.5 * k * x.u * x.u; };
  const double E0 = energy(s);
  double max_drift = 0;
  for (int n = 0; n < 20000; ++n) {
    s = hht_step(c, m, k, s, 0, 0);
    max_drift = std::max(max_drift, std::fabs(energy(s) - E0));
  }
  EXPECT_LE(max_drift, 1e-12 * E0);
}

TEST(HHT, PositiveADissipatesEnergy) {
  const double m = 1.0, k = 1.0;
  for (double a : {0.05, 0.1, 1.0 / 3.0}) {
    const HHTCoefficients c(a, 0.5);
    State s{1.0, 0.0, -1.0};
    const double E0 = 0.5 * k;
    for (int n = 0; n < 2000; ++n) s = hht_step(c, m, k, s, 0, 0);
    EXPECT_LT(0.5 * m * s.v * s.v + 0.5 * k * s.u * s.u, 0.99 * E0) << "a = " << a;
  }
}

}  // namespace
}  // namespace slidewave

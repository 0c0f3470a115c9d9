#pragma once
// Hilber–Hughes–Taylor time integration in the paper's convention (Yastrebov 2016, eq. in Methods):
//     M a(n+1) + (1-a) K u(n+1) + a K u(n) = (1-a) F(n+1) + a F(n),
// with the Newmark updates
//     u(n+1) = u(n) + dt v(n) + dt^2 [(1/2 - beta) a(n) + beta a(n+1)],
//     v(n+1) = v(n) + dt [(1 - gamma) a(n) + gamma a(n+1)],
//     beta = (1+a)^2/4, gamma = 1/2 + a.
// The paper's a = 0.1 is the classic HHT alpha_H = -0.1 (Hilber, Hughes & Taylor 1977); a = 0 is the
// trapezoidal rule (energy conserving, no numerical dissipation). Allowed: 0 <= a <= 1/3.
namespace slidewave {

struct HHTCoefficients {
  double alpha, beta, gamma, dt;
  explicit HHTCoefficients(double a, double step) : alpha(a), beta((1 + a) * (1 + a) / 4), gamma(0.5 + a), dt(step) {}
  /// Coefficient of M in the effective matrix K_eff = M / (beta dt^2) + (1 - alpha) K.
  double mass_factor() const { return 1.0 / (beta * dt * dt); }
};

}  // namespace slidewave

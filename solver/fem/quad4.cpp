#include "fem/quad4.hpp"

#include <cmath>

namespace slidewave {
namespace {

constexpr double kXi[4] = {-1, 1, 1, -1};
constexpr double kEta[4] = {-1, -1, 1, 1};

/// Strain-displacement matrix of a square of side h at (xi, eta).
Eigen::Matrix<double, 3, 8> strain_matrix(double h, double xi, double eta) {
  Eigen::Matrix<double, 3, 8> B = Eigen::Matrix<double, 3, 8>::Zero();
  const double a = h / 2;  // dx/dxi
  for (int n = 0; n < 4; ++n) {
    const double dN_dx = kXi[n] * (1 + kEta[n] * eta) / 4 / a;
    const double dN_dy = kEta[n] * (1 + kXi[n] * xi) / 4 / a;
    B(0, 2 * n) = dN_dx;
    B(1, 2 * n + 1) = dN_dy;
    B(2, 2 * n) = dN_dy;
    B(2, 2 * n + 1) = dN_dx;
  }
  return B;
}

}  // namespace

Eigen::Matrix3d plane_strain_elasticity(double E, double nu) {
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Eigen::Matrix3d D;
  D << lam + 2 * mu, lam, 0, lam, lam + 2 * mu, 0, 0, 0, mu;
  return D;
}

Matrix8 quad4_stiffness(double E, double nu, double h, Integration integration) {
  const Eigen::Matrix3d D = plane_strain_elasticity(E, nu);
  const double area = h * h;
  if (integration == Integration::full) {
    Matrix8 K = Matrix8::Zero();
    const double g = 1 / std::sqrt(3.0);
    for (double xi : {-g, g})
      for (double eta : {-g, g}) {
        const auto B = strain_matrix(h, xi, eta);
        K += B.transpose() * D * B * (area / 4);
      }
    return K;
  }
  const auto B0 = strain_matrix(h, 0, 0);
  Matrix8 K = B0.transpose() * D * B0 * area;
  if (integration == Integration::reduced) {
    // Hourglass vector of a parallelogram is gamma = h/4 with h = (1,-1,1,-1); energy (1/2) k q^2
    // with q the hourglass amplitude (q = h . u / 4) and k = (4/3) E/(1-nu^2).
    const double k = 4.0 / 3.0 * E / (1 - nu * nu);
    const Eigen::Vector4d hg(1, -1, 1, -1);
    const Eigen::Matrix4d K_hg = k / 16 * hg * hg.transpose();
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int d = 0; d < 2; ++d) K(2 * a + d, 2 * b + d) += K_hg(a, b);
  }
  return K;
}

Matrix8 quad4_mass(double rho, double h, MassKind kind) {
  Eigen::Matrix4d m;
  m << 4, 2, 1, 2, 2, 4, 2, 1, 1, 2, 4, 2, 2, 1, 2, 4;
  m *= rho * h * h / 36;
  if (kind == MassKind::lumped) {
    const Eigen::Vector4d row_sum = m.rowwise().sum();
    m = row_sum.asDiagonal();
  }
  Matrix8 M = Matrix8::Zero();
  for (int a = 0; a < 4; ++a)
    for (int b = 0; b < 4; ++b)
      for (int d = 0; d < 2; ++d) M(2 * a + d, 2 * b + d) = m(a, b);
  return M;
}

}  // namespace slidewave

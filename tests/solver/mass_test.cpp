// Element and global mass (fem/quad4, fem/assembly, model/layer_model): exact integration of
// N_i N_j, total mass, row-sum lumping.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "fem/assembly.hpp"
#include "fem/quad4.hpp"
#include "model/layer_model.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

constexpr double kXi[4] = {-1, 1, 1, -1};
constexpr double kEta[4] = {-1, -1, 1, 1};

/// rho * integral of N_a N_b over the square, by 3x3 Gauss quadrature (exact for biquadratics).
Eigen::Matrix4d consistent_mass_by_quadrature(double rho, double h) {
  const double points[3] = {-std::sqrt(0.6), 0.0, std::sqrt(0.6)};
  const double weights[3] = {5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0};
  Eigen::Matrix4d m = Eigen::Matrix4d::Zero();
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q) {
      Eigen::Vector4d N;
      for (int n = 0; n < 4; ++n) N(n) = (1 + kXi[n] * points[p]) * (1 + kEta[n] * points[q]) / 4;
      m += rho * weights[p] * weights[q] * (h * h / 4) * N * N.transpose();
    }
  return m;
}

TEST(Mass, ConsistentElementMassIsExactIntegral) {
  for (double h : {0.25, 1.5625, 3.0}) {
    const double rho = 1000.0;
    const Matrix8 M = quad4_mass(rho, h, MassKind::consistent);
    const Eigen::Matrix4d m = consistent_mass_by_quadrature(rho, h);
    for (int a = 0; a < 4; ++a)
      for (int b = 0; b < 4; ++b)
        for (int d = 0; d < 2; ++d) {
          EXPECT_NEAR(M(2 * a + d, 2 * b + d), m(a, b), 1e-14 * rho * h * h) << a << " " << b;
          EXPECT_EQ(M(2 * a + d, 2 * b + 1 - d), 0.0) << "no coupling between directions";
        }
  }
}

TEST(Mass, ElementTotalMassPerDirection) {
  const double rho = 1234.0, h = 0.7;
  for (MassKind kind : {MassKind::consistent, MassKind::lumped}) {
    const Matrix8 M = quad4_mass(rho, h, kind);
    for (int d = 0; d < 2; ++d) {
      Eigen::Matrix<double, 8, 1> translation = Eigen::Matrix<double, 8, 1>::Zero();
      for (int n = 0; n < 4; ++n) translation(2 * n + d) = 1;
      EXPECT_NEAR(translation.dot(M * translation), rho * h * h, 1e-13 * rho * h * h);
    }
  }
}

TEST(Mass, LumpedIsDiagonalOfConsistentRowSums) {
  const double rho = 1000.0, h = 0.9;
  const Matrix8 M_c = quad4_mass(rho, h, MassKind::consistent);
  const Matrix8 M_l = quad4_mass(rho, h, MassKind::lumped);
  for (int a = 0; a < 8; ++a) {
    EXPECT_NEAR(M_l.row(a).sum(), M_c.row(a).sum(), 1e-14 * rho * h * h);
    EXPECT_NEAR(M_l(a, a), rho * h * h / 4, 1e-14 * rho * h * h);
    for (int b = 0; b < 8; ++b)
      if (a != b) {
        EXPECT_EQ(M_l(a, b), 0.0);
      }
  }
}

TEST(Mass, ConsistentElementMassIsPositiveDefinite) {
  const Eigen::SelfAdjointEigenSolver<Matrix8> eig(quad4_mass(1000.0, 1.0, MassKind::consistent));
  EXPECT_GT(eig.eigenvalues().minCoeff(), 0.0);
}

// Assembled periodic layer: total mass rho lambda H per direction, lumped row sums equal the
// consistent row sums, M symmetric.
TEST(Mass, GlobalMassOfTheLayer) {
  const RunConfig consistent = testing::make_config({{"mesh", {{"elements_per_H", 4}, {"mass", "consistent"}}}});
  const RunConfig lumped = testing::make_config({{"mesh", {{"elements_per_H", 4}, {"mass", "lumped"}}}});
  const LayerModel m_c(consistent), m_l(lumped);
  const double rho = consistent.material.rho, total = rho * m_c.d.lambda * m_c.d.H;
  for (int d = 0; d < 2; ++d) {
    Eigen::VectorXd translation = Eigen::VectorXd::Zero(m_c.mesh.n_dofs());
    for (int node = 0; node < m_c.mesh.n_nodes(); ++node) translation(2 * node + d) = 1;
    EXPECT_NEAR(translation.dot(m_c.M() * translation), total, 1e-12 * total);
    EXPECT_NEAR(translation.dot(m_l.M() * translation), total, 1e-12 * total);
  }
  const Eigen::VectorXd ones = Eigen::VectorXd::Ones(m_c.mesh.n_dofs());
  EXPECT_LE((m_c.M() * ones - m_l.M() * ones).norm(), 1e-12 * (m_c.M() * ones).norm());
  const Eigen::MatrixXd M_dense(m_c.M());
  EXPECT_EQ((M_dense - M_dense.transpose()).norm(), 0.0);
}

}  // namespace
}  // namespace slidewave

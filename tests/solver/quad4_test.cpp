// Q4 element stiffness (fem/quad4): rigid-body modes, patch test on an assembled mesh, zero-energy
// modes, and the ASQBI hourglass energy against the exact pure-bending energy of the square.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "fem/assembly.hpp"
#include "fem/quad4.hpp"
#include "mesh/layer_mesh.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

using testing::integration_name;
using testing::kAllIntegrations;

constexpr double kXi[4] = {-1, 1, 1, -1};
constexpr double kEta[4] = {-1, -1, 1, 1};

/// Plane-strain Hooke matrix written from the Lamé constants (independent of the solver's).
Eigen::Matrix3d lame_elasticity(double E, double nu) {
  const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
  Eigen::Matrix3d D;
  D << lam + 2 * mu, lam, 0, lam, lam + 2 * mu, 0, 0, 0, mu;
  return D;
}

/// Element vector of the field u_x = q xi eta (d = 0) or u_y = q xi eta (d = 1).
Eigen::Matrix<double, 8, 1> hourglass_field(int d, double q) {
  Eigen::Matrix<double, 8, 1> u = Eigen::Matrix<double, 8, 1>::Zero();
  for (int n = 0; n < 4; ++n) u(2 * n + d) = q * kXi[n] * kEta[n];
  return u;
}

TEST(Quad4, ElasticityMatrixIsPlaneStrainHooke) {
  for (double nu : {0.0, 0.2, 0.45, 0.49}) {
    const Eigen::Matrix3d D = plane_strain_elasticity(1000.0, nu), D_ref = lame_elasticity(1000.0, nu);
    EXPECT_LE((D - D_ref).norm(), 1e-14 * D_ref.norm()) << "nu = " << nu;
  }
}

TEST(Quad4, StiffnessIsSymmetric) {
  for (Integration integration : kAllIntegrations) {
    const Matrix8 K = quad4_stiffness(1000.0, 0.3, 0.7, integration);
    EXPECT_LE((K - K.transpose()).norm(), 1e-15 * K.norm()) << integration_name(integration);
  }
}

TEST(Quad4, ThreeRigidBodyModesHaveZeroForce) {
  const double h = 0.7;
  for (Integration integration : kAllIntegrations)
    for (double nu : {0.0, 0.2, 0.49}) {
      const Matrix8 K = quad4_stiffness(1000.0, nu, h, integration);
      Eigen::Matrix<double, 8, 3> modes = Eigen::Matrix<double, 8, 3>::Zero();
      for (int n = 0; n < 4; ++n) {
        const double x = (1 + kXi[n]) * h / 2, y = (1 + kEta[n]) * h / 2;
        modes(2 * n, 0) = 1;      // translation x
        modes(2 * n + 1, 1) = 1;  // translation y
        modes(2 * n, 2) = -y;     // rotation about the origin (not the centre, on purpose)
        modes(2 * n + 1, 2) = x;
      }
      for (int m = 0; m < 3; ++m)
        EXPECT_LE((K * modes.col(m)).norm(), 1e-14 * K.norm() * modes.col(m).norm())
            << integration_name(integration) << " nu = " << nu << " mode " << m;
    }
}

// Eigenvalues of K_e: 3 zeros (rigid body) for full and stabilized reduced, 5 for pure 1-point
// (the two hourglass modes u_x = xi eta, u_y = xi eta), and those two are the extra null vectors.
TEST(Quad4, ZeroEnergyModeCount) {
  const struct {
    Integration integration;
    int n_zero;
  } cases[] = {{Integration::full, 3}, {Integration::reduced, 3}, {Integration::reduced_pure, 5}};
  for (const auto& c : cases)
    for (double nu : {0.0, 0.3, 0.49}) {
      const Matrix8 K = quad4_stiffness(1000.0, nu, 1.3, c.integration);
      const Eigen::SelfAdjointEigenSolver<Matrix8> eig(K);
      ASSERT_EQ(eig.info(), Eigen::Success);
      const double largest = eig.eigenvalues().cwiseAbs().maxCoeff();
      int n_zero = 0;
      for (int k = 0; k < 8; ++k) {
        EXPECT_GT(eig.eigenvalues()(k), -1e-12 * largest) << "K_e must be positive semi-definite";
        n_zero += std::fabs(eig.eigenvalues()(k)) < 1e-12 * largest;
      }
      EXPECT_EQ(n_zero, c.n_zero) << integration_name(c.integration) << " nu = " << nu;
      // The smallest non-zero eigenvalue is well separated from round-off (a real, stiff mode).
      EXPECT_GT(eig.eigenvalues()(c.n_zero), 1e-3 * largest) << integration_name(c.integration);
      for (int d = 0; d < 2; ++d) {
        const double hourglass_force = (K * hourglass_field(d, 1.0)).norm() / largest;
        if (c.integration == Integration::reduced_pure)
          EXPECT_LE(hourglass_force, 1e-14) << "pure 1-point integration: hourglass is a zero-energy mode";
        else
          EXPECT_GT(hourglass_force, 1e-3) << integration_name(c.integration) << ": hourglass must be stiff";
      }
    }
}

// Exact bending energy of the square for u_d = q xi eta: eps_dd = q eta_d / a (a = h/2), the other
// normal strain -nu/(1-nu) eps_dd (plane strain, sigma_ee = 0), no shear; integrated by Gauss
// quadrature (exact for the quadratic integrand) with the Lamé form of D.
double exact_bending_energy(double E, double nu, double h, double q) {
  const Eigen::Matrix3d D = lame_elasticity(E, nu);
  const double a = h / 2, g = 1 / std::sqrt(3.0);
  double energy = 0;
  for (double xi : {-g, g})
    for (double eta : {-g, g}) {
      (void)xi;
      Eigen::Vector3d eps(q * eta / a, -nu / (1 - nu) * q * eta / a, 0);
      energy += 0.5 * eps.dot(D * eps) * a * a;  // weight 1, Jacobian a^2
    }
  return energy;
}

TEST(Quad4, AsqbiHourglassEnergyEqualsExactBending) {
  const double E = 1000.0, q = 0.37;
  for (double nu : {0.0, 0.2, 0.45, 0.49})
    for (double h : {0.5, 1.5625, 3.0})
      for (int d = 0; d < 2; ++d) {
        const Matrix8 K = quad4_stiffness(E, nu, h, Integration::reduced);
        const auto u = hourglass_field(d, q);
        const double energy = 0.5 * u.dot(K * u);
        const double closed_form = 0.5 * (4.0 / 3.0) * E / (1 - nu * nu) * q * q;
        EXPECT_NEAR(exact_bending_energy(E, nu, h, q), closed_form, 1e-13 * closed_form);
        EXPECT_NEAR(energy, closed_form, 1e-13 * closed_form) << "nu = " << nu << " h = " << h << " d = " << d;
        // Full 2x2 integration adds the parasitic shear of the bilinear field (shear locking).
        const Matrix8 K_full = quad4_stiffness(E, nu, h, Integration::full);
        EXPECT_GT(0.5 * u.dot(K_full * u), 1.1 * closed_form);
      }
}

// 2x2 Gauss integrates the stiffness of a square exactly. For u_x = q xi eta: eps_xx = q eta / a and
// gamma_xy = q xi / a, so the exact energy is (1/2)(4/3)(lambda + 2 mu + mu) q^2 (shear locking
// included, which is what makes `full` stiff in bending).
TEST(Quad4, FullIntegrationEnergyOfTheBilinearFieldIsExact) {
  const double E = 1000.0, q = 0.37;
  for (double nu : {0.0, 0.3, 0.49})
    for (int d = 0; d < 2; ++d) {
      const double lam = E * nu / ((1 + nu) * (1 - 2 * nu)), mu = E / (2 * (1 + nu));
      const auto u = hourglass_field(d, q);
      const double energy = 0.5 * u.dot(quad4_stiffness(E, nu, 0.9, Integration::full) * u);
      const double exact = 0.5 * (4.0 / 3.0) * (lam + 3 * mu) * q * q;
      EXPECT_NEAR(energy, exact, 1e-13 * exact) << "nu = " << nu << " d = " << d;
    }
}

// The x and y hourglass modes are decoupled (their cross energy integrates to zero on a square).
TEST(Quad4, AsqbiHourglassModesDecoupled) {
  const Matrix8 K = quad4_stiffness(1000.0, 0.3, 1.0, Integration::reduced);
  const double cross = hourglass_field(0, 1.0).dot(K * hourglass_field(1, 1.0));
  EXPECT_LE(std::fabs(cross), 1e-14 * K.norm());
}

struct LinearField {
  double a0, a1, a2, b0, b1, b2;  // u_x = a0 + a1 x + a2 y, u_y = b0 + b1 x + b2 y
  Eigen::Vector3d strain() const { return {a1, b2, a2 + b1}; }
};
constexpr LinearField kLinearField{0.01, 2e-3, -1.5e-3, -0.02, 0.7e-3, -1.1e-3};

// Element level: the nodal forces of a linear field are those of the constant stress sigma = D eps,
// f_a = integral of B_a^T sigma = (h/2) (sigma_xx xi_a + sigma_xy eta_a, sigma_xy xi_a + sigma_yy eta_a).
TEST(Quad4, PatchTestElementForcesOfConstantStress) {
  const double E = 1000.0, h = 0.9;
  for (Integration integration : kAllIntegrations)
    for (double nu : {0.0, 0.25, 0.49}) {
      const Matrix8 K = quad4_stiffness(E, nu, h, integration);
      Eigen::Matrix<double, 8, 1> u, f_expected;
      const Eigen::Vector3d sigma = lame_elasticity(E, nu) * kLinearField.strain();
      for (int n = 0; n < 4; ++n) {
        const double x = 3.0 + (1 + kXi[n]) * h / 2, y = 2.0 + (1 + kEta[n]) * h / 2;
        u(2 * n) = kLinearField.a0 + kLinearField.a1 * x + kLinearField.a2 * y;
        u(2 * n + 1) = kLinearField.b0 + kLinearField.b1 * x + kLinearField.b2 * y;
        f_expected(2 * n) = h / 2 * (sigma(0) * kXi[n] + sigma(2) * kEta[n]);
        f_expected(2 * n + 1) = h / 2 * (sigma(2) * kXi[n] + sigma(1) * kEta[n]);
      }
      EXPECT_LE((K * u - f_expected).norm(), 1e-12 * f_expected.norm())
          << integration_name(integration) << " nu = " << nu;
    }
}

// Assembled mesh: a linear field gives zero residual at every interior node, and on the bottom/top
// rows exactly the consistent nodal load of the constant traction (-/+ sigma . e_y h).
// The mesh is periodic in x, so nodes next to the seam (i = 0, n_x - 1) see the jump of the
// non-periodic field and are excluded.
TEST(Quad4, PatchTestAssembledMeshInteriorResidualVanishes) {
  const double E = 1000.0, h = 0.8;
  const LayerMesh mesh(7, 5, h);
  for (Integration integration : kAllIntegrations)
    for (double nu : {0.0, 0.3, 0.49}) {
      const SparseMatrix K = assemble_uniform(mesh, quad4_stiffness(E, nu, h, integration));
      Eigen::VectorXd u(mesh.n_dofs());
      for (int node = 0; node < mesh.n_nodes(); ++node) {
        const double x = mesh.x(node), y = mesh.y(node);
        u(2 * node) = kLinearField.a0 + kLinearField.a1 * x + kLinearField.a2 * y;
        u(2 * node + 1) = kLinearField.b0 + kLinearField.b1 * x + kLinearField.b2 * y;
      }
      const Eigen::VectorXd R = K * u;
      const Eigen::Vector3d sigma = lame_elasticity(E, nu) * kLinearField.strain();
      const double force_scale = sigma.cwiseAbs().maxCoeff() * h;
      for (int j = 0; j <= mesh.n_y; ++j)
        for (int i = 1; i <= mesh.n_x - 2; ++i) {
          const int node = mesh.node(i, j);
          const double sign = j == 0 ? -1.0 : (j == mesh.n_y ? 1.0 : 0.0);
          EXPECT_NEAR(R(2 * node), sign * sigma(2) * h, 1e-12 * force_scale)
              << integration_name(integration) << " nu = " << nu << " node (" << i << ", " << j << ") x";
          EXPECT_NEAR(R(2 * node + 1), sign * sigma(1) * h, 1e-12 * force_scale)
              << integration_name(integration) << " nu = " << nu << " node (" << i << ", " << j << ") y";
        }
    }
}

// A field linear in y only is periodic, so on the periodic mesh the residual vanishes at every
// interior node, including the seam (checks the periodic tie of the assembly).
TEST(Quad4, PatchTestPeriodicSeam) {
  const double E = 1000.0, nu = 0.3, h = 0.8;
  const LayerMesh mesh(5, 4, h);
  for (Integration integration : kAllIntegrations) {
    const SparseMatrix K = assemble_uniform(mesh, quad4_stiffness(E, nu, h, integration));
    Eigen::VectorXd u(mesh.n_dofs());
    for (int node = 0; node < mesh.n_nodes(); ++node) {
      u(2 * node) = 1e-3 * mesh.y(node);
      u(2 * node + 1) = -2e-3 * mesh.y(node);
    }
    const Eigen::VectorXd R = K * u;
    for (int node = mesh.n_x; node < mesh.n_x * mesh.n_y; ++node)
      EXPECT_LE(R.segment<2>(2 * node).norm(), 1e-13 * E * 1e-3 * h) << integration_name(integration);
    // Global equilibrium: the bottom and top rows carry opposite forces.
    Eigen::Vector2d bottom = Eigen::Vector2d::Zero(), top = Eigen::Vector2d::Zero();
    for (int i = 0; i < mesh.n_x; ++i) {
      bottom += R.segment<2>(2 * mesh.node(i, 0));
      top += R.segment<2>(2 * mesh.node(i, mesh.n_y));
    }
    EXPECT_LE((bottom + top).norm(), 1e-13 * top.norm());
  }
}

}  // namespace
}  // namespace slidewave

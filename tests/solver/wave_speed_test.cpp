// Measured S and P wave speeds of the discrete layer (model/layer_model: K_ff, M_ff).
// A motion uniform in x is a 1-D column (the layer is periodic in x): fixed at the top (Dirichlet
// row), traction free at the bottom (no contact here). Its fundamental angular frequency is
// omega_1 = pi c / (2 H), with c = c_s for u_x (shear) and c = c_l for u_y (compression), so the
// measured celerity is c_h = 2 H omega_1 / pi. We project K_ff and M_ff on the x-uniform subspace
// (exactly invariant), solve the small generalized eigenproblem, and check 1 % agreement and the
// second-order convergence of c_h with the mesh.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "model/layer_model.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

struct ColumnSpeeds {
  double c_s, c_l;             // measured
  double coupling;             // |x-y block| / |x-x block| of the projected stiffness
  double invariance_residual;  // |K_ff P phi - omega^2 M_ff P phi| / |K_ff P phi|, shear mode
};

ColumnSpeeds measure_column_speeds(const RunConfig& config) {
  const LayerModel model(config);
  const int n_x = model.mesh.n_x, n_rows = model.mesh.n_y;  // free rows j = 0 .. n_y - 1
  // P maps (u_x, u_y) of free row j to every node of that row.
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(model.n_free, 2 * n_rows);
  for (int j = 0; j < n_rows; ++j)
    for (int i = 0; i < n_x; ++i)
      for (int d = 0; d < 2; ++d) P(2 * model.mesh.node(i, j) + d, 2 * j + d) = 1;
  const Eigen::MatrixXd K_P = model.K_ff() * P, M_P = model.M_ff() * P;
  const Eigen::MatrixXd K_r = P.transpose() * K_P, M_r = P.transpose() * M_P;

  ColumnSpeeds out{};
  Eigen::VectorXi x_dofs(n_rows), y_dofs(n_rows);
  for (int j = 0; j < n_rows; ++j) {
    x_dofs(j) = 2 * j;
    y_dofs(j) = 2 * j + 1;
  }
  out.coupling = K_r(x_dofs, y_dofs).norm() / K_r(x_dofs, x_dofs).norm();
  const double H = model.d.H;
  for (int d = 0; d < 2; ++d) {
    const Eigen::VectorXi& dofs = d == 0 ? x_dofs : y_dofs;
    const Eigen::MatrixXd K_d = K_r(dofs, dofs), M_d = M_r(dofs, dofs);
    const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> eig(K_d, M_d);
    const double omega = std::sqrt(eig.eigenvalues()(0));
    (d == 0 ? out.c_s : out.c_l) = 2 * H * omega / M_PI;
    if (d == 0) {
      Eigen::VectorXd phi = Eigen::VectorXd::Zero(2 * n_rows);
      phi(dofs) = eig.eigenvectors().col(0);
      const Eigen::VectorXd Kphi = K_P * phi, Mphi = M_P * phi;
      out.invariance_residual = (Kphi - omega * omega * Mphi).norm() / Kphi.norm();
    }
  }
  return out;
}

RunConfig column_config(double nu, int n, Integration integration, const char* mass) {
  // lambda_over_H * n = 4 columns of elements: the x extent does not matter for x-uniform motion.
  return testing::make_config(
      {{"material", {{"nu", nu}}},
       {"geometry", {{"lambda_over_H", 4.0 / n}}},
       {"mesh", {{"elements_per_H", n}, {"integration", testing::integration_name(integration)}, {"mass", mass}}}});
}

TEST(WaveSpeed, ShearAndCompressionWithinOnePercentAtH16) {
  for (double nu : {0.0, 0.2, 0.45})
    for (Integration integration : testing::kAllIntegrations)
      for (const char* mass : {"consistent", "lumped"}) {
        const RunConfig config = column_config(nu, 16, integration, mass);
        const DerivedConstants d = config.derived();
        // Independent closed forms of the celerities.
        const double E = config.material.E, rho = config.material.rho;
        const double c_s = std::sqrt(E / (2 * (1 + nu)) / rho);
        const double c_l = std::sqrt(E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / rho);
        EXPECT_NEAR(d.c_s, c_s, 1e-14 * c_s);
        EXPECT_NEAR(d.c_l, c_l, 1e-14 * c_l);

        const ColumnSpeeds measured = measure_column_speeds(config);
        const std::string where =
            "nu = " + std::to_string(nu) + " " + testing::integration_name(integration) + " " + mass;
        EXPECT_LT(std::fabs(measured.c_s / c_s - 1), 0.01) << where << ": c_s measured " << measured.c_s;
        EXPECT_LT(std::fabs(measured.c_l / c_l - 1), 0.01) << where << ": c_l measured " << measured.c_l;
        EXPECT_LE(measured.coupling, 1e-14) << where;
        EXPECT_LE(measured.invariance_residual, 1e-10) << where << ": x-uniform subspace not invariant";
        // Consistent mass over-estimates the frequency of linear elements, lumped mass under-estimates it.
        if (std::string(mass) == "consistent") {
          EXPECT_GT(measured.c_s, c_s) << where;
        } else {
          EXPECT_LT(measured.c_s, c_s) << where;
        }
      }
}

// The error of the measured celerity falls as h^2 (linear elements): observed order > 1.9.
TEST(WaveSpeed, ConvergesWithSecondOrderInH) {
  for (Integration integration : testing::kAllIntegrations)
    for (double nu : {0.2, 0.45}) {
      double previous_s = 0, previous_l = 0;
      for (int n : {8, 16, 32}) {
        const RunConfig config = column_config(nu, n, integration, "consistent");
        const DerivedConstants d = config.derived();
        const ColumnSpeeds measured = measure_column_speeds(config);
        const double error_s = std::fabs(measured.c_s / d.c_s - 1), error_l = std::fabs(measured.c_l / d.c_l - 1);
        if (previous_s > 0) {
          EXPECT_GT(std::log2(previous_s / error_s), 1.9) << "shear, n = " << n;
          EXPECT_GT(std::log2(previous_l / error_l), 1.9) << "compression, n = " << n;
        }
        previous_s = error_s;
        previous_l = error_l;
      }
    }
}

}  // namespace
}  // namespace slidewave

// Quasi-static stages (model/layer_model: solve_preload). The discrete layer represents the uniform
// uniaxial-strain compression and the uniform simple shear exactly, so the reactions are exact:
//     normal traction r_y / h = p0 = -Uy E (1-nu) / (H (1+nu)(1-2nu)) at every contact node,
//     T / N = preshear_ratio * f, every node closed and sticking.
#include <gtest/gtest.h>

#include <cmath>

#include "model/layer_model.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

double paper_p0(const RunConfig& c) {
  const double E = c.material.E, nu = c.material.nu, Uy = c.loading.Uy_over_H * c.geometry.H;
  return -Uy * E * (1 - nu) / (c.geometry.H * (1 + nu) * (1 - 2 * nu));
}

struct PreloadErrors {
  double pressure = 0, traction = 0, T_over_N = 0, gap = 0, u_x_top = 0;  ///< max relative errors
  int n_not_stick = 0, max_iterations = 0;
};

/// Max relative errors of solve_preload against the exact uniform state, over both linear solvers, nu,
/// integration and f.
PreloadErrors preload_errors(double tolerance, int elements_per_H) {
  PreloadErrors e;
  for (const char* linear_solver : {"spectral", "cholmod"})
    for (double nu : {0.0, 0.2, 0.45, 0.49})
      for (Integration integration : testing::kAllIntegrations)
        for (double f : {0.5, 1.5}) {
          const RunConfig config = testing::make_config(
              {{"material", {{"nu", nu}}},
               {"friction", {{"f", f}}},
               {"contact", {{"tolerance", tolerance}, {"max_iterations", 100000}}},
               {"numerics", {{"linear_solver", linear_solver}}},
               {"mesh",
                {{"elements_per_H", elements_per_H}, {"integration", testing::integration_name(integration)}}}});
          const std::string where = "nu = " + std::to_string(nu) + " f = " + std::to_string(f) + " " +
                                    testing::integration_name(integration) + " " + linear_solver;
          const LayerModel model(config);
          const double p0 = paper_p0(config), h = model.d.h, Uy = config.loading.Uy_over_H * config.geometry.H;
          EXPECT_NEAR(model.d.p0, p0, 1e-13 * p0) << where;
          PreloadState pre{};
          try {
            pre = solve_preload(model);
          } catch (const std::exception& error) {
            ADD_FAILURE() << where << ": " << error.what();
            continue;
          }
          EXPECT_EQ(static_cast<int>(pre.state.size()), model.mesh.n_contact());
          for (int k = 0; k < model.mesh.n_contact(); ++k) {
            e.n_not_stick += pre.state[k] != ContactState::stick;
            e.pressure = std::max(e.pressure, std::fabs(pre.r(2 * k + 1) / h / p0 - 1));
            e.traction = std::max(e.traction, std::fabs(-pre.r(2 * k) / h / (0.95 * f * p0) - 1));
            e.gap = std::max(e.gap, std::fabs(pre.u(2 * k + 1) / Uy));  // closed: no gap, no penetration
          }
          e.T_over_N = std::max(e.T_over_N, std::fabs(pre.T / pre.N / (0.95 * f) - 1));
          EXPECT_NEAR(pre.N, p0 * model.d.lambda, 1e-8 * p0 * model.d.lambda) << where;
          // Uniform simple shear: tau = G u_x_top / H, so u_x_top = 0.95 f p0 H / G.
          const double G = config.material.E / (2 * (1 + nu));
          e.u_x_top = std::max(e.u_x_top, std::fabs(pre.u_x_top / (0.95 * f * p0 * config.geometry.H / G) - 1));
          e.max_iterations = std::max(e.max_iterations, pre.contact_iterations);
        }
  return e;
}

void record(const PreloadErrors& e) {
  ::testing::Test::RecordProperty("pressure", testing::sci(e.pressure));
  ::testing::Test::RecordProperty("traction", testing::sci(e.traction));
  ::testing::Test::RecordProperty("T_over_N", testing::sci(e.T_over_N));
  ::testing::Test::RecordProperty("sweeps", e.max_iterations);
}

// With the contact solve converged to round-off (tolerance 1e-15) the preload is exact: every node
// carries p0 h and 0.95 f p0 h, T/N = 0.95 f, for nu in {0, 0.2, 0.45, 0.49} and every integration.
TEST(Preload, PressureShearRatioAndStickAtEveryNode) {
  const PreloadErrors e = preload_errors(1e-15, 8);
  record(e);
  EXPECT_EQ(e.n_not_stick, 0);
  EXPECT_LE(e.pressure, 1e-10);
  EXPECT_LE(e.traction, 1e-10);
  EXPECT_LE(e.T_over_N, 1e-10);
  EXPECT_LE(e.gap, 1e-10);
  EXPECT_LE(e.u_x_top, 1e-10);
}

// At the default contact tolerance (1e-10 of p0 h on the last sweep's change) the preload is still
// exact to round-off: both stages start Gauss-Seidel from the all-stick answer, which it only
// verifies (a cold start needed 266-517 sweeps and left nodal errors of up to 4.7e-9).
TEST(Preload, DefaultToleranceAccuracy) {
  const PreloadErrors e = preload_errors(1e-10, 8);
  record(e);
  EXPECT_EQ(e.n_not_stick, 0);
  EXPECT_LE(e.pressure, 1e-11);
  EXPECT_LE(e.traction, 1e-11);
  EXPECT_LE(e.T_over_N, 1e-11);
  EXPECT_LE(e.gap, 1e-11);
  EXPECT_LE(e.max_iterations, 4) << "sweeps of both stages together";
}

// f = 0 is allowed (contracts.md: f >= 0). A frictionless preload has T = 0 and nothing can slip
// against anything, so it must succeed.
TEST(Preload, FrictionlessPreloadSucceeds) {
  const RunConfig config = testing::make_config(
      {{"friction", {{"f", 0.0}}}, {"loading", {{"preshear_ratio", 0.0}}}, {"mesh", {{"elements_per_H", 4}}}});
  PreloadState pre{};
  ASSERT_NO_THROW(pre = solve_preload(LayerModel(config)));
  EXPECT_LE(std::fabs(pre.T), 1e-12 * pre.N);
}

// The displacement field of the preload is the exact linear field: u_y = Uy y / H, u_x = U y / H.
TEST(Preload, DisplacementFieldIsLinearInY) {
  const RunConfig config = testing::make_config({{"material", {{"nu", 0.3}}}, {"mesh", {{"elements_per_H", 6}}}});
  const LayerModel model(config);
  const PreloadState pre = solve_preload(model);
  const double H = config.geometry.H, Uy = config.loading.Uy_over_H * H;
  double max_error = 0;
  for (int node = 0; node < model.mesh.n_nodes(); ++node) {
    const double y = model.mesh.y(node);
    max_error = std::max(max_error, std::fabs(pre.u(2 * node) - pre.u_x_top * y / H) / std::fabs(pre.u_x_top));
    max_error = std::max(max_error, std::fabs(pre.u(2 * node + 1) - Uy * y / H) / std::fabs(Uy));
  }
  EXPECT_LE(max_error, 1e-10);
}

TEST(Preload, ZeroPreshearLeavesNoShear) {
  const RunConfig config =
      testing::make_config({{"loading", {{"preshear_ratio", 0.0}}}, {"mesh", {{"elements_per_H", 4}}}});
  const LayerModel model(config);
  const PreloadState pre = solve_preload(model);
  // Zero up to the contact tolerance of stage 1 (the default 1e-10).
  EXPECT_LE(std::fabs(pre.u_x_top), 1e-9 * model.d.p0 * config.geometry.H / model.d.G);
  EXPECT_LE(std::fabs(pre.T), 1e-9 * pre.N);
}

}  // namespace
}  // namespace slidewave

// The single-mode seed and the sliding start (config group `mode_seed`, model/mode_seed.hpp): the seed's
// field (exact), nothing without the group, and the energy balance of a seeded pair that starts sliding
// (round-off at hht_alpha = 0: the seed and the start velocity are booked in the energy at the start).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "model/layer_model.hpp"
#include "model/mode_seed.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

TEST(ModeSeed, NoGroupNoDisplacement) {
  const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 4}}}}));
  EXPECT_EQ(mode_seed_displacement(m).cwiseAbs().maxCoeff(), 0.0);
}

// u_x = A cos(k x) e^{-k y}, u_y = -A sin(k x) e^{-k y} at the free nodes, u_y = 0 at the contact nodes,
// nothing at the top; k = 2 pi mode / lambda.
TEST(ModeSeed, FieldIsTheHarmonicGradientOfTheMode) {
  const LayerModel m(testing::make_config(
      {{"mesh", {{"elements_per_H", 4}}}, {"mode_seed", {{"amplitude_over_H", 1e-3}, {"mode", 2}}}}));
  const Eigen::VectorXd du = mode_seed_displacement(m);
  ASSERT_EQ(du.size(), m.n_free + m.n_top);
  const double A = 1e-3 * m.d.H, k = 2 * M_PI * 2 / m.d.lambda;
  for (int j = 0; j <= m.mesh.n_y; ++j)
    for (int i = 0; i < m.mesh.n_x; ++i) {
      const int node = m.mesh.node(i, j);
      const double x = i * m.d.h, y = j * m.d.h, decay = j < m.mesh.n_y ? A * std::exp(-k * y) : 0.0;
      EXPECT_NEAR(du(2 * node), decay * std::cos(k * x), 1e-15 * A) << i << " " << j;
      EXPECT_NEAR(du(2 * node + 1), j > 0 ? -decay * std::sin(k * x) : 0.0, 1e-15 * A) << i << " " << j;
    }
}

// A dissimilar pair, seeded and started sliding, f = 1, hht_alpha = 0: the balance closes to round-off, the
// interface slides from the first step (every node slipping), the kinetic energy at t = 0 is the layer's
// translation at V0 (the seed adds none).
TEST(ModeSeed, SlidingStartOfASeededPairKeepsTheEnergyBalance) {
  const RunConfig c = testing::make_config({{"mesh", {{"elements_per_H", 8}}},
                                            {"geometry", {{"lambda_over_H", 1.0}}},
                                            {"friction", {{"f", 1.0}}},
                                            {"loading", {{"V0_over_cs", 0.01}}},
                                            {"substrate", {{"E", 1200.0}, {"nu", 0.2}, {"rho", 1000.0}, {"H", 25.0}}},
                                            {"mode_seed", {{"amplitude_over_H", 1e-5}, {"start", "sliding"}}},
                                            {"perturbation", {{"amplitude", 0.0}}},
                                            {"time", {{"hht_alpha", 0.0}, {"t_end", 100.0}}}});
  const RunRecord rec = simulate(LayerModel(c));
  ASSERT_TRUE(rec.complete);
  const auto& g = rec.global;
  const double mass = c.material.rho * c.geometry.H * c.geometry.H * c.geometry.lambda_over_H;
  EXPECT_NEAR(g.energy_kinetic[0], 0.5 * mass * std::pow(c.derived().V0, 2), 1e-9 * g.energy_kinetic[0]);
  double scale = 0, residual = 0;
  for (size_t n = 0; n < g.t.size(); ++n) scale = std::max(scale, g.energy_kinetic[n] + g.energy_elastic[n]);
  for (size_t n = 0; n < g.t.size(); ++n) residual = std::max(residual, std::fabs(g.energy_balance_residual[n]));
  std::printf("seeded sliding pair: energy residual %.3e of max(E_kin + E_el)\n", residual / scale);
  EXPECT_LT(residual / scale, 1e-9);
  const auto& state = rec.interface.state;
  for (size_t k = state.data.size() - state.n_cols; k < state.data.size(); ++k)  // the last output row
    EXPECT_EQ(state.data[k], static_cast<std::int8_t>(ContactState::slip)) << k;
}

}  // namespace
}  // namespace slidewave

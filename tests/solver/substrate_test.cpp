// The deformable substrate (model/substrate.hpp, docs/substrate.md): the mirroring of the pair's contact
// operator (exact), a substrate 1000x stiffer than the layer against the rigid flat (regression with a
// tolerance from the pair's compliance), and the energy balance of the pair (round-off at hht_alpha = 0).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "contact/delassus.hpp"
#include "fem/quad4.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "model/substrate.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

nlohmann::json substrate(double E, double nu, double rho, double H) {
  return {{"E", E}, {"nu", nu}, {"rho", rho}, {"H", H}};
}

// W_pair = W_L + S W_S S, S = diag(-1, +1) per node, against the explicit product.
TEST(Substrate, PairOperatorIsTheMirroredSum) {
  const int n = 3;
  Eigen::MatrixXd A = Eigen::MatrixXd::Random(2 * n, 2 * n), B = Eigen::MatrixXd::Random(2 * n, 2 * n);
  Eigen::VectorXd s(2 * n);
  for (int k = 0; k < n; ++k) s.segment<2>(2 * k) << -1, 1;
  const Eigen::MatrixXd expected = A + s.asDiagonal() * B * s.asDiagonal();
  EXPECT_EQ((pair_delassus(A, B) - expected).cwiseAbs().maxCoeff(), 0.0);
  Eigen::VectorXd v = Eigen::VectorXd::Random(2 * n), mirrored = v;
  mirror_x_components(mirrored);
  EXPECT_EQ((mirrored - s.asDiagonal() * v).cwiseAbs().maxCoeff(), 0.0);
  const Eigen::VectorXd u_L = Eigen::VectorXd::Random(2 * n + 4), u_S = Eigen::VectorXd::Random(2 * n + 6);
  EXPECT_EQ((relative_contact_displacement(u_L, u_S, 2 * n) - (u_L.head(2 * n) + s.asDiagonal() * u_S.head(2 * n)))
                .cwiseAbs()
                .maxCoeff(),
            0.0);
}

// The mirroring's premise: the element matrices are invariant under the reflection y -> h - y of the square
// (nodes 1 <-> 4, 2 <-> 3, u_y -> -u_y), for every integration and both masses, to round-off. So the
// substrate in its mirrored frame has the layer's element matrices (model/substrate.hpp).
TEST(Substrate, ElementMatricesAreInvariantUnderTheReflection) {
  Eigen::Matrix<double, 8, 8> T = Eigen::Matrix<double, 8, 8>::Zero();
  const int image[4] = {3, 2, 1, 0};
  for (int a = 0; a < 4; ++a) {
    T(2 * a, 2 * image[a]) = 1;
    T(2 * a + 1, 2 * image[a] + 1) = -1;
  }
  for (const Integration integration : testing::kAllIntegrations) {
    const auto K = quad4_stiffness(3e3, 0.3, 0.7, integration);
    EXPECT_LT((T.transpose() * K * T - K).cwiseAbs().maxCoeff(), 1e-12 * K.cwiseAbs().maxCoeff())
        << testing::integration_name(integration);
  }
  for (const MassKind kind : {MassKind::consistent, MassKind::lumped}) {
    const auto M = quad4_mass(2e3, 0.7, kind);
    EXPECT_LT((T.transpose() * M * T - M).cwiseAbs().maxCoeff(), 1e-14 * M.cwiseAbs().maxCoeff());
  }
}

// The substrate body: the layer's n_x and h, H_s / h rows, its own material, the layer's time step.
TEST(Substrate, BodyIsTheMirroredLayerOfItsMaterial) {
  const RunConfig c =
      testing::make_config({{"mesh", {{"elements_per_H", 8}}}, {"substrate", substrate(3e3, 0.3, 2e3, 12.5)}});
  const LayerModel m(c);
  ASSERT_TRUE(m.substrate);
  const LayerModel& s = *m.substrate;
  EXPECT_EQ(s.mesh.n_x, m.mesh.n_x);
  EXPECT_EQ(s.mesh.n_y, 4);
  EXPECT_EQ(s.d.h, m.d.h);
  EXPECT_EQ(s.d.dt, m.d.dt);
  EXPECT_EQ(s.config.material.E, 3e3);
  EXPECT_FALSE(s.substrate);
  EXPECT_FALSE(LayerModel(testing::make_config({{"mesh", {{"elements_per_H", 8}}}})).substrate);
}

// Preload with a substrate: still all-closed, all-stick, T/N = 0.95 f; zero gap; identical bodies share
// the compression exactly.
TEST(Substrate, PreloadOfThePairSticksAtThePreshearRatio) {
  const RunConfig c =
      testing::make_config({{"mesh", {{"elements_per_H", 8}}}, {"substrate", substrate(1e3, 0.2, 1e3, 25.0)}});
  const LayerModel m(c);
  const PreloadState pre = solve_preload(m);
  EXPECT_NEAR(pre.T / pre.N, 0.95 * c.friction.f, 1e-9);
  // The pair's preload pressure (RunConfig::derived): identical bodies in series, half the rigid flat's.
  EXPECT_NEAR(pre.N, m.d.p0 * m.d.lambda, 1e-9 * pre.N);
  EXPECT_NEAR(m.d.p0, 0.5 * testing::make_config({{"mesh", {{"elements_per_H", 8}}}}).derived().p0, 1e-12 * m.d.p0);
  ASSERT_EQ(pre.u_substrate.size(), m.substrate->n_free + m.substrate->n_top);
  const Eigen::VectorXd rel = relative_contact_displacement(pre.u, pre.u_substrate, m.n_contact_dofs);
  for (int k = 0; k < m.mesh.n_contact(); ++k) EXPECT_NEAR(rel(2 * k + 1), 0.0, 1e-12 * m.d.H) << k;
  // Identical bodies of equal thickness share the uniform compression (which the element represents exactly):
  // the interface moves down by half the top displacement, u_y = Uy H / 2 on both sides (u_y' = -u_y).
  const double half = 0.5 * c.loading.Uy_over_H * c.geometry.H;
  for (int k = 0; k < m.mesh.n_contact(); ++k) {
    EXPECT_NEAR(pre.u(2 * k + 1), half, 1e-9 * std::fabs(half)) << k;
    EXPECT_NEAR(pre.u_substrate(2 * k + 1), -half, 1e-9 * std::fabs(half)) << k;
  }
}

// Dissimilar bodies (E_s = 3 E, nu_s = 0.45, H_s = H / 2): the preload's normal force is the pressure of
// both bodies in series under uniaxial strain, -Uy / (H / M + H_s / M_s), which /setup writes as p0.
TEST(Substrate, PreloadPressureIsThatOfBothBodiesInSeries) {
  const RunConfig c =
      testing::make_config({{"mesh", {{"elements_per_H", 8}}}, {"substrate", substrate(3e3, 0.45, 1e3, 12.5)}});
  const LayerModel m(c);
  const PreloadState pre = solve_preload(m);
  const double M = m.d.lame_lambda + 2 * m.d.G, M_s = 3e3 * 0.55 / (1.45 * 0.1);
  const double p0 = -c.loading.Uy_over_H * c.geometry.H / (c.geometry.H / M + 12.5 / M_s);
  EXPECT_NEAR(m.d.p0, p0, 1e-12 * p0);
  EXPECT_NEAR(pre.N, p0 * m.d.lambda, 1e-9 * pre.N);
}

struct StiffComparison {
  double max_dT_over_N;  ///< max |T/N (substrate) - T/N (rigid)| over the steps before the first slip
  long first_slip_rigid, first_slip_substrate;  ///< step of the first slipping node (-1: none)
  double T_over_N_at_onset;
};

long first_slip_step(const RunRecord& rec) {
  const int n = rec.interface.state.n_cols;
  for (int row = 0; row < rec.interface.state.n_rows(); ++row)
    for (int k = 0; k < n; ++k)
      if (rec.interface.state.data[row * n + k] == static_cast<std::int8_t>(ContactState::slip)) return row;
  return -1;
}

// A substrate 1000x stiffer than the layer, a quarter of its thickness: the pair's static shear compliance
// H/G + H_s/G_s exceeds the layer's by H_s G / (H G_s) = 2.5e-4, so before onset T/N moves by about that
// fraction of its rise (0.05 f) and the onset step by 2.5e-4 of the ~100 steps to it: the same step. The
// test asks for T/N within 1e-3 (absolute, T/N ~ 1.4) and the same first-slip step. No seed (amplitude 0):
// both runs are then x-uniform until onset.
TEST(Substrate, StiffSubstrateReproducesTheRigidFlat) {
  const nlohmann::json base = {{"mesh", {{"elements_per_H", 8}}},
                               {"loading", {{"V0_over_cs", 1e-4}}},
                               {"perturbation", {{"amplitude", 0.0}}},
                               {"output", {{"interface_stride", 1}}},
                               {"time", {{"t_end", 120.0}}}};
  nlohmann::json stiff = base;
  stiff["substrate"] = substrate(1e6, 0.2, 1e3, 25.0 / 4);
  const RunRecord rigid = simulate(LayerModel(testing::make_config(base)));
  const RunRecord pair = simulate(LayerModel(testing::make_config(stiff)));
  ASSERT_TRUE(rigid.complete);
  ASSERT_TRUE(pair.complete);
  StiffComparison r{0, first_slip_step(rigid), first_slip_step(pair), 0};
  ASSERT_GT(r.first_slip_rigid, 0) << "the rigid run must reach onset";
  for (long n = 0; n < r.first_slip_rigid && n < static_cast<long>(pair.global.t.size()); ++n)
    r.max_dT_over_N = std::max(r.max_dT_over_N, std::fabs(pair.global.T_over_N[n] - rigid.global.T_over_N[n]));
  r.T_over_N_at_onset = rigid.global.T_over_N[r.first_slip_rigid - 1];
  RecordProperty("max_dT_over_N", testing::sci(r.max_dT_over_N));
  RecordProperty("first_slip_step", std::to_string(r.first_slip_rigid));
  std::printf(
      "stiff substrate: max |d(T/N)| before onset %.3e, first slip at step %ld (rigid) and %ld (pair), "
      "T/N before onset %.6f\n",
      r.max_dT_over_N, r.first_slip_rigid, r.first_slip_substrate, r.T_over_N_at_onset);
  EXPECT_LT(r.max_dT_over_N, 1e-3);
  EXPECT_EQ(r.first_slip_substrate, r.first_slip_rigid);
}

struct PairBalance {
  double max_abs_relative;      ///< max |residual| / max (E_kin + E_el)
  double max_abs_hht_relative;  ///< max |residual + D_hht| / max (E_kin + E_el) (with the decomposition)
  int n_slip_samples;
  bool complete;
};

PairBalance pair_balance(const nlohmann::json& overrides) {
  const RunRecord rec = simulate(LayerModel(testing::make_config(overrides)));
  const auto& g = rec.global;
  double scale = 0;
  for (size_t n = 0; n < g.t.size(); ++n) scale = std::max(scale, g.energy_kinetic[n] + g.energy_elastic[n]);
  PairBalance b{0, 0, 0, rec.complete};
  for (size_t n = 0; n < g.t.size(); ++n) {
    b.max_abs_relative = std::max(b.max_abs_relative, std::fabs(g.energy_balance_residual[n]) / scale);
    if (!g.dissipation_hht.empty())
      b.max_abs_hht_relative =
          std::max(b.max_abs_hht_relative, std::fabs(g.energy_balance_residual[n] + g.dissipation_hht[n]) / scale);
  }
  for (auto s : rec.interface.state.data) b.n_slip_samples += s == static_cast<std::int8_t>(ContactState::slip);
  return b;
}

// Identical materials, a sliding pair at hht_alpha = 0: both ledgers together close to round-off.
TEST(Substrate, EnergyOfThePairClosesAtAlphaZero) {
  const PairBalance b = pair_balance({{"mesh", {{"elements_per_H", 8}}},
                                      {"friction", {{"f", 0.3}}},
                                      {"loading", {{"V0_over_cs", 1e-3}}},
                                      {"substrate", substrate(1e3, 0.2, 1e3, 12.5)},
                                      {"time", {{"hht_alpha", 0.0}, {"t_end", 200.0}}}});
  ASSERT_TRUE(b.complete);
  RecordProperty("max_abs_relative_residual", testing::sci(b.max_abs_relative));
  std::printf("pair energy residual at alpha = 0: %.3e of max(E_kin + E_el), %d slip samples\n", b.max_abs_relative,
              b.n_slip_samples);
  EXPECT_GT(b.n_slip_samples, 0) << "the pair must slide";
  EXPECT_LT(b.max_abs_relative, 1e-9);
}

// hht_alpha = 0.1 with the decomposition: the residual is the HHT dissipation of both bodies, to round-off.
TEST(Substrate, HhtDissipationOfThePairAccountsForTheResidual) {
  const PairBalance b = pair_balance({{"mesh", {{"elements_per_H", 8}}},
                                      {"friction", {{"f", 0.3}}},
                                      {"loading", {{"V0_over_cs", 1e-3}}},
                                      {"substrate", substrate(3e3, 0.3, 2e3, 12.5)},
                                      {"output", {{"energy_decomposition", "hht"}}},
                                      {"time", {{"t_end", 200.0}}}});
  ASSERT_TRUE(b.complete);
  std::printf("pair residual + D_hht at alpha = 0.1: %.3e of max(E_kin + E_el)\n", b.max_abs_hht_relative);
  EXPECT_GT(b.n_slip_samples, 0);
  EXPECT_LT(b.max_abs_hht_relative, 1e-9);
}

}  // namespace
}  // namespace slidewave

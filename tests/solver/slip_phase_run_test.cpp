// The slip phase inside simulate() (model/stick_phase/slip_phase_run.hpp): a run's rows against the same run
// stepped plainly (the oracle), through the onset and a few hundred slip steps; and where the phase applies.
// (Resuming inside the phase, bit for bit through the checkpoint file, is in resume_test.cpp: its Coulomb,
// Prakash–Clifton and stop_after_opening cases stop after the onset.)
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>

#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "model/stick_phase/slip_phase_run.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

/// First step solved by Gauss–Seidel: the first slip (-1: none).
std::int64_t first_slip(const RunRecord& r) {
  const auto& it = r.global.contact_iterations;
  const auto found = std::find_if(it.begin() + 1, it.end(), [](int sweeps) { return sweeps > 0; });
  return found == it.end() ? -1 : found - it.begin();
}

double largest(const std::vector<double>& x) {
  double m = 0;
  for (double value : x) m = std::max(m, std::fabs(value));
  return m;
}

/// Largest difference of two series from `from` on, against `scale`.
double difference(const std::vector<double>& a, const std::vector<double>& b, std::size_t from, double scale) {
  double d = 0;
  for (std::size_t i = from; i < std::min(a.size(), b.size()); ++i) d = std::max(d, std::fabs(a[i] - b[i]));
  return d / scale;
}

/// First step from which |a - b| exceeds `bound` times the largest |b| (-1: never).
std::int64_t first_departure(const std::vector<double>& a, const std::vector<double>& b, double bound) {
  const double scale = largest(b);
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    if (std::fabs(a[i] - b[i]) > bound * scale) return static_cast<std::int64_t>(i);
  return -1;
}

RunRecord paper_case(const char* linear_solver, bool in_wavenumbers) {
  LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 16}}},
                                     {"time", {{"t_end", 1000.0}}},
                                     {"output", {{"interface_stride", 1}}},
                                     {"numerics", {{"linear_solver", linear_solver}}}}));
  m.steps_in_wavenumbers = in_wavenumbers;
  return simulate(m);
}

// H/16, the paper's case to 1000 s: onset at step 960 (of 1292), then ~330 slip steps with opening pulses.
// Once nodes slip and open, the problem itself amplifies round-off (measured: a difference of 1e-10 of the
// largest force grows to 1e-4 in ~120 steps), so the slip phase is held to two things: the plain step's
// rows to round-off over the onset and the first 150 slip steps; and, after that, a departure from the
// plain run no sooner than that of another round-off of the same discrete problem (the plain step on
// CHOLMOD's factorization instead of the spectral one). Measured: T departs by 1e-10 / 1e-8 / 1e-6 of its
// largest at steps 1162 / 1208 / 1245 (CHOLMOD: 1160 / 1203 / 1242).
TEST(SlipPhaseRun, RecordsThePlainRunToRoundOffThroughTheSlipPhase) {
  const RunRecord a = paper_case("spectral", true), b = paper_case("spectral", false), c = paper_case("cholmod", false);
  const std::int64_t onset = first_slip(b);
  ASSERT_GT(onset, 100);
  ASSERT_EQ(a.global.t.size(), b.global.t.size());
  ASSERT_GT(static_cast<std::int64_t>(b.global.t.size()) - onset, 300) << "the slip phase is compared";
  EXPECT_EQ(first_slip(a), onset);
  // Over the onset and 150 slip steps: round-off.
  const std::size_t window = static_cast<std::size_t>(onset) + 150;
  const auto head = [window](const std::vector<double>& x) {
    return std::vector<double>(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(std::min(window, x.size())));
  };
  const GlobalSeries &ga = a.global, &gb = b.global;
  const double T = difference(head(ga.T), head(gb.T), 0, largest(gb.T)),
               N = difference(head(ga.N), head(gb.N), 0, largest(gb.N));
  const double energy = largest(gb.energy_elastic);
  double energies = 0;
  using Field = std::vector<double> GlobalSeries::*;
  for (const Field field : {&GlobalSeries::energy_kinetic, &GlobalSeries::energy_elastic, &GlobalSeries::work_external,
                            &GlobalSeries::dissipation_friction, &GlobalSeries::work_contact_normal,
                            &GlobalSeries::energy_balance_residual})
    energies = std::max(energies, difference(head(ga.*field), head(gb.*field), 0, energy));
  const std::size_t n_nodes = static_cast<std::size_t>(b.interface.state.n_cols);
  const auto node_head = [&](const std::vector<double>& x) {
    return std::vector<double>(x.begin(), x.begin() + static_cast<std::ptrdiff_t>(window * n_nodes));
  };
  const InterfaceSeries &ia = a.interface, &ib = b.interface;
  const double tractions = difference(node_head(ia.tangential_traction.data), node_head(ib.tangential_traction.data), 0,
                                      largest(ib.tangential_traction.data));
  std::printf("[slip phase vs plain, onset step %lld, to step %zu] T %.2e, N %.2e, energies %.2e, tractions %.2e\n",
              static_cast<long long>(onset), window, T, N, energies, tractions);
  EXPECT_LT(T, 1e-10);
  EXPECT_LT(N, 1e-10);
  EXPECT_LT(energies, 1e-10);
  EXPECT_LT(tractions, 1e-10);
  EXPECT_TRUE(std::equal(ib.state.data.begin(), ib.state.data.begin() + static_cast<std::ptrdiff_t>(window * n_nodes),
                         ia.state.data.begin()))
      << "the same contact states";
  // After it: the problem's own growth of round-off.
  for (const double bound : {1e-10, 1e-8, 1e-6}) {
    const std::int64_t ours = first_departure(ga.T, gb.T, bound), other = first_departure(c.global.T, gb.T, bound);
    std::printf("[departure by %.0e of the largest T] slip phase at step %lld, CHOLMOD at step %lld\n", bound,
                static_cast<long long>(ours), static_cast<long long>(other));
    EXPECT_GE(ours < 0 ? INT64_MAX : ours, (other < 0 ? INT64_MAX : other) - 20) << bound;
  }
}

TEST(SlipPhaseRun, AppliesOnTheRigidFlatUnlessTheLedgerBooksTheHhtTerms) {
  EXPECT_TRUE(slip_phase_applies(LayerModel(testing::make_config())));
  EXPECT_TRUE(
      slip_phase_applies(LayerModel(testing::make_config({{"friction", {{"regularization", "prakash_clifton"}}}}))));
  EXPECT_FALSE(slip_phase_applies(LayerModel(testing::make_config({{"output", {{"energy_decomposition", "hht"}}}}))));
  RunConfig pair = testing::make_config();
  pair.substrate = SubstrateConfig{3 * pair.material.E, pair.material.nu, pair.material.rho, pair.geometry.H};
  EXPECT_FALSE(slip_phase_applies(LayerModel(pair)));
  LayerModel plain(testing::make_config());
  plain.steps_in_wavenumbers = false;
  EXPECT_FALSE(slip_phase_applies(plain));
  EXPECT_FALSE(slip_phase_applies(LayerModel(testing::make_config({{"numerics", {{"linear_solver", "cholmod"}}}}))));
}

}  // namespace
}  // namespace slidewave

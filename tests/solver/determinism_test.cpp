// Same configuration, same build => bit-identical interface and global series (model/simulation).
#include <gtest/gtest.h>

#include <cstring>
#include <vector>

#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

template <typename T>
bool bit_identical(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

RunConfig sliding_config(long long seed) {
  // nu = 0.2, f = 1.5 at H/8 past the onset: slip, so the contact solve has real work to do.
  return testing::make_config({{"mesh", {{"elements_per_H", 8}}},
                               {"time", {{"t_end", 1000.0}}},
                               {"perturbation", {{"seed", seed}}},
                               {"output", {{"interface_stride", 1}, {"snapshot_times", {500.0}}}}});
}

TEST(Determinism, TwoRunsAreBitIdentical) {
  const RunConfig config = sliding_config(1);
  const RunRecord a = simulate(LayerModel(config)), b = simulate(LayerModel(config));
  ASSERT_TRUE(a.complete);
  const auto &ia = a.interface, &ib = b.interface;
  EXPECT_TRUE(bit_identical(ia.x, ib.x));
  EXPECT_TRUE(bit_identical(ia.t, ib.t));
  EXPECT_TRUE(bit_identical(ia.slip_velocity.data, ib.slip_velocity.data));
  EXPECT_TRUE(bit_identical(ia.slip.data, ib.slip.data));
  EXPECT_TRUE(bit_identical(ia.opening.data, ib.opening.data));
  EXPECT_TRUE(bit_identical(ia.normal_traction.data, ib.normal_traction.data));
  EXPECT_TRUE(bit_identical(ia.tangential_traction.data, ib.tangential_traction.data));
  EXPECT_TRUE(bit_identical(ia.state.data, ib.state.data));
  const auto &ga = a.global, &gb = b.global;
  for (const auto member :
       {&GlobalSeries::t, &GlobalSeries::T, &GlobalSeries::N, &GlobalSeries::T_over_N, &GlobalSeries::energy_kinetic,
        &GlobalSeries::energy_elastic, &GlobalSeries::work_external, &GlobalSeries::dissipation_friction,
        &GlobalSeries::work_contact_normal, &GlobalSeries::energy_balance_residual, &GlobalSeries::contact_residual})
    EXPECT_TRUE(bit_identical(ga.*member, gb.*member));
  EXPECT_TRUE(bit_identical(ga.contact_iterations, gb.contact_iterations));
  ASSERT_EQ(a.snapshots.size(), 1u);
  ASSERT_EQ(b.snapshots.size(), 1u);
  EXPECT_TRUE(bit_identical(a.snapshots[0].displacement, b.snapshots[0].displacement));
  EXPECT_TRUE(bit_identical(a.snapshots[0].velocity, b.snapshots[0].velocity));
  EXPECT_EQ(a.t_first_opening, b.t_first_opening);
  EXPECT_EQ(a.n_steps_done, b.n_steps_done);
  // The run really slid (otherwise the comparison is trivial).
  int n_slip = 0;
  for (auto s : ia.state.data) n_slip += s == static_cast<std::int8_t>(ContactState::slip);
  EXPECT_GT(n_slip, 0);
}

// The seed is what the run depends on: another seed gives another (still valid) run.
TEST(Determinism, TheSeedChangesTheRun) {
  const RunRecord a = simulate(LayerModel(sliding_config(1))), b = simulate(LayerModel(sliding_config(2)));
  EXPECT_FALSE(bit_identical(a.interface.slip_velocity.data, b.interface.slip_velocity.data));
}

}  // namespace
}  // namespace slidewave

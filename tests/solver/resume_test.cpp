// Continuing the loop from a captured state (model/run_observer, model/loop_state_arrays): the rows of
// a run stopped after step K and continued from its state at K are, bit for bit, the rows of the
// uninterrupted run; for Coulomb and Prakash–Clifton friction (which carries a memory), with
// stop_after_opening shortening t_end and snapshots on both sides of K. The state arrays survive the
// checkpoint file unchanged.
#include <gtest/gtest.h>

#include <atomic>
#include <cstring>

#include "hdf5_test_support.hpp"
#include "io/checkpoint.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

/// Keeps every row (the record is not drained) and the state after step `capture_at`; with a start
/// state, continues from it.
class CapturingObserver : public RunObserver {
 public:
  explicit CapturingObserver(std::int64_t capture_at, const StateArrays* start = nullptr)
      : capture_at_(capture_at), start_(start) {}
  void after_step(RunRecord& record, const Capture& capture) override {
    if (record.global.t.size() == static_cast<std::size_t>(capture_at_ + 1) && !captured_) {
      state = capture();
      rows_then = record;
      captured_ = true;
    }
  }
  void at_end(RunRecord&, const Capture&) override {}
  const StateArrays* start_state() const override { return start_; }
  StateArrays state;
  RunRecord rows_then;

 private:
  std::int64_t capture_at_;
  const StateArrays* start_;
  bool captured_ = false;
};

template <typename T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

/// `first` then `rest` equals `whole`, series by series, bit for bit.
void expect_concatenation(const RunRecord& whole, const RunRecord& first, const RunRecord& rest) {
  const auto joined = [](auto a, const auto& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
  };
  const auto& g = whole.global;
  using G = std::vector<double> GlobalSeries::*;
  for (G field :
       {&GlobalSeries::t, &GlobalSeries::T, &GlobalSeries::N, &GlobalSeries::T_over_N, &GlobalSeries::energy_kinetic,
        &GlobalSeries::energy_elastic, &GlobalSeries::work_external, &GlobalSeries::dissipation_friction,
        &GlobalSeries::work_contact_normal, &GlobalSeries::energy_balance_residual, &GlobalSeries::contact_residual})
    EXPECT_TRUE(same_bits(g.*field, joined(first.global.*field, rest.global.*field)));
  EXPECT_EQ(g.contact_iterations, joined(first.global.contact_iterations, rest.global.contact_iterations));
  const auto& s = whole.interface;
  EXPECT_TRUE(same_bits(s.t, joined(first.interface.t, rest.interface.t)));
  using I = Series2D<double> InterfaceSeries::*;
  for (I field : {&InterfaceSeries::slip_velocity, &InterfaceSeries::slip, &InterfaceSeries::opening,
                  &InterfaceSeries::normal_traction, &InterfaceSeries::tangential_traction})
    EXPECT_TRUE(same_bits((s.*field).data, joined((first.interface.*field).data, (rest.interface.*field).data)));
  EXPECT_EQ(s.state.data, joined(first.interface.state.data, rest.interface.state.data));
  ASSERT_EQ(whole.snapshots.size(), first.snapshots.size() + rest.snapshots.size());
  for (std::size_t k = 0; k < whole.snapshots.size(); ++k) {
    const Snapshot& part = k < first.snapshots.size() ? first.snapshots[k] : rest.snapshots[k - first.snapshots.size()];
    EXPECT_EQ(whole.snapshots[k].t, part.t);
    EXPECT_TRUE(same_bits(whole.snapshots[k].displacement, part.displacement)) << "snapshot " << k;
  }
  EXPECT_EQ(whole.n_steps_done, rest.n_steps_done);
  EXPECT_EQ(whole.end_reason, rest.end_reason);
  EXPECT_EQ(whole.complete, rest.complete);
  EXPECT_EQ(whole.t_first_opening, rest.t_first_opening);
}

void check_resume(const nlohmann::json& overrides, std::int64_t stop_after) {
  const RunConfig config = testing::make_config(overrides);
  const LayerModel model(config);
  const RunRecord whole = simulate(model);
  ASSERT_GT(whole.n_steps_done, stop_after + 10);

  CapturingObserver first(stop_after);
  simulate(model, {}, nullptr, nullptr, &first);
  ASSERT_EQ(first.rows_then.global.t.size(), static_cast<std::size_t>(stop_after + 1));
  // Through the checkpoint file, as --resume reads it.
  const testing::TempDir dir("resume");
  Checkpoint checkpoint;
  checkpoint.state = first.state;
  write_checkpoint(dir / "c.h5", checkpoint);
  const StateArrays restored = read_checkpoint(dir / "c.h5").state;

  CapturingObserver continued(-1, &restored);
  const RunRecord rest = simulate(model, {}, nullptr, nullptr, &continued);
  expect_concatenation(whole, first.rows_then, rest);
}

TEST(Resume, CoulombWithSnapshotsOnBothSides) {
  check_resume({{"mesh", {{"elements_per_H", 8}}},
                {"time", {{"t_end", 1600.0}}},
                {"output", {{"interface_stride", 3}, {"snapshot_times", {0, 100, 1500}}}}},
               1500);
}

// A deformable substrate (docs/substrate.md): the checkpoint carries its dynamics and its ledger too.
TEST(Resume, WithASubstrateCarriesBothBodies) {
  check_resume(
      {{"mesh", {{"elements_per_H", 8}}},
       {"friction", {{"f", 0.3}}},
       {"loading", {{"V0_over_cs", 1e-3}}},
       {"substrate", {{"E", 3e3}, {"nu", 0.3}, {"rho", 2e3}, {"H", 12.5}}},
       {"time", {{"t_end", 200.0}}},
       {"output", {{"interface_stride", 3}, {"snapshot_times", {0, 50, 150}}, {"energy_decomposition", "hht"}}}},
      100);
}

/// First step at which a contact node slips (from the interface rows, stride 1).
std::int64_t first_slip_step(const RunRecord& rec) {
  const auto& state = rec.interface.state;
  for (std::size_t i = 0; i < state.data.size(); ++i)
    if (state.data[i] == static_cast<std::int8_t>(ContactState::slip))
      return static_cast<std::int64_t>(i / state.n_cols);
  return -1;
}

TEST(Resume, PrakashCliftonCarriesItsMemory) {
  // The friction memory matters only once nodes slip: the state is taken after slip onset.
  const nlohmann::json overrides = {{"mesh", {{"elements_per_H", 8}}},
                                    {"friction", {{"regularization", "prakash_clifton"}, {"pc_velocity", 0.3}}},
                                    {"time", {{"t_end", 1600.0}}},
                                    {"output", {{"interface_stride", 1}}}};
  const std::int64_t onset = first_slip_step(simulate(LayerModel(testing::make_config(overrides))));
  ASSERT_GT(onset, 0) << "the run must slip";
  check_resume(overrides, onset + 20);
}

TEST(Resume, AfterStopAfterOpeningShortenedTheRun) {
  // H/16 opens (Simulation.StopAfterOpening); the state is taken after the opening, so the shortened
  // t_end and end_reason must come from the checkpoint.
  const RunConfig config = testing::make_config(
      {{"mesh", {{"elements_per_H", 16}}}, {"time", {{"t_end", 3000.0}, {"stop_after_opening", 50.0}}}});
  const RunRecord whole = simulate(LayerModel(config));
  ASSERT_EQ(whole.end_reason, "stop_after_opening");
  const auto step_after_opening = static_cast<std::int64_t>(whole.t_first_opening / config.derived().dt) + 5;
  check_resume({{"mesh", {{"elements_per_H", 16}}}, {"time", {{"t_end", 3000.0}, {"stop_after_opening", 50.0}}}},
               step_after_opening);
}

TEST(Resume, StateOfAnotherModelIsRefused) {
  const RunConfig small = testing::make_config({{"mesh", {{"elements_per_H", 4}}}, {"time", {{"t_end", 30.0}}}});
  CapturingObserver first(5);
  simulate(LayerModel(small), {}, nullptr, nullptr, &first);
  const RunConfig bigger = testing::make_config({{"mesh", {{"elements_per_H", 8}}}, {"time", {{"t_end", 30.0}}}});
  CapturingObserver continued(-1, &first.state);
  try {
    simulate(LayerModel(bigger), {}, nullptr, nullptr, &continued);
    ADD_FAILURE() << "expected a size mismatch";
  } catch (const std::runtime_error& e) {
    EXPECT_NE(std::string(e.what()).find("this model"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slidewave

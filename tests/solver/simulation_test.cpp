// Run control of stage 3 (model/simulation): how a run ends (t_end, stop_after_opening,
// contact_not_converged, interrupted), what the record holds then, and the CLI exit code.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

void expect_consistent_lengths(const RunRecord& rec, int stride) {
  EXPECT_EQ(rec.global.t.size(), static_cast<size_t>(rec.n_steps_done + 1));
  EXPECT_EQ(rec.global.energy_balance_residual.size(), rec.global.t.size());
  EXPECT_EQ(rec.interface.t.size(), static_cast<size_t>(rec.n_steps_done / stride + 1));
  EXPECT_EQ(rec.interface.slip_velocity.n_rows(), static_cast<int>(rec.interface.t.size()));
  EXPECT_EQ(rec.interface.state.n_rows(), static_cast<int>(rec.interface.t.size()));
}

TEST(Simulation, RunsToTEnd) {
  const RunConfig config = testing::make_config({{"mesh", {{"elements_per_H", 4}}}, {"time", {{"t_end", 100.0}}}});
  const RunRecord rec = simulate(LayerModel(config));
  const double dt = config.derived().dt;
  EXPECT_TRUE(rec.complete);
  EXPECT_EQ(rec.end_reason, "t_end");
  // The run ends with the first step that reaches t_end (here 130 steps, t = 100.7 s).
  EXPECT_EQ(rec.n_steps_done, static_cast<int>(std::ceil(100.0 / dt)));
  EXPECT_GE(rec.global.t.back(), 100.0);
  EXPECT_LT(rec.global.t.back(), 100.0 + dt);
  EXPECT_NEAR(rec.global.t.back(), rec.n_steps_done * dt, 1e-12);
  expect_consistent_lengths(rec, config.output.interface_stride);
  // t = 0 is the end of stage 2: T/N = preshear_ratio f, all stick, no slip yet.
  EXPECT_NEAR(rec.global.T_over_N[0], 0.95 * 1.5, 1e-9);
  for (int k = 0; k < rec.interface.state.n_cols; ++k) {
    EXPECT_EQ(rec.interface.state.data[k], static_cast<std::int8_t>(ContactState::stick));
    EXPECT_EQ(rec.interface.slip_velocity.data[k], 0.0);
    EXPECT_EQ(rec.interface.slip.data[k], 0.0);
  }
  EXPECT_EQ(rec.global.energy_balance_residual[0], 0.0);
}

TEST(Simulation, StopAfterOpening) {
  const RunConfig config = testing::make_config(
      {{"mesh", {{"elements_per_H", 16}}}, {"time", {{"t_end", 3000.0}, {"stop_after_opening", 50.0}}}});
  const RunRecord rec = simulate(LayerModel(config));
  const double dt = config.derived().dt;
  ASSERT_GT(rec.t_first_opening, 0) << "nu = 0.2, f = 1.5 opens (see Smoke.*)";
  EXPECT_TRUE(rec.complete);
  EXPECT_EQ(rec.end_reason, "stop_after_opening");
  EXPECT_NEAR(rec.global.t.back(), rec.t_first_opening + 50.0, dt);
  expect_consistent_lengths(rec, config.output.interface_stride);
  // The opening time is the first step with u_y above the threshold, 1 % of |Uy| (simulation.hpp).
  EXPECT_DOUBLE_EQ(opening_threshold(config), 1e-2 * 0.001 * 25.0);
}

// The preload only verifies its warm start (one sweep per stage), so an iteration cap of 2 passes
// the preload and fails the first dynamic step that needs more sweeps: the run stops incomplete with
// end_reason contact_not_converged, keeping what it computed so far.
TEST(Simulation, ContactNotConvergedEndsTheRunIncomplete) {
  const RunConfig config = testing::make_config(
      {{"mesh", {{"elements_per_H", 8}}}, {"contact", {{"max_iterations", 2}}}, {"time", {{"t_end", 3000.0}}}});
  const RunRecord rec = simulate(LayerModel(config));
  EXPECT_FALSE(rec.complete);
  EXPECT_EQ(rec.end_reason, "contact_not_converged");
  EXPECT_LT(rec.global.t.back(), 3000.0);
  expect_consistent_lengths(rec, config.output.interface_stride);
}

TEST(Simulation, StopRequestEndsTheRunIncomplete) {
  const RunConfig config = testing::make_config({{"mesh", {{"elements_per_H", 4}}}, {"time", {{"t_end", 100.0}}}});
  const std::atomic<bool> stop{true};
  const RunRecord rec = simulate(LayerModel(config), {}, &stop);
  EXPECT_FALSE(rec.complete);
  EXPECT_EQ(rec.end_reason, "interrupted");
  EXPECT_EQ(rec.n_steps_done, 0);
  expect_consistent_lengths(rec, config.output.interface_stride);
}

// A run that ends early exits 1, says why on stderr and keeps what it computed (complete = 0).
TEST(SimulationCli, ContactFailureExits1AndKeepsTheIncompleteRun) {
  const auto dir = std::filesystem::temp_directory_path() / ("slidewave_test_cli_fail_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const auto config = dir / "run.json", out = dir / "run.h5", err = dir / "stderr.txt";
  std::ofstream(config) << R"({"mesh": {"elements_per_H": 8}, "contact": {"max_iterations": 2}})";
  const int status = std::system(
      (std::string(SLIDEWAVE_BIN) + " run " + config.string() + " -o " + out.string() + " 2> " + err.string()).c_str());
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 1);
  EXPECT_TRUE(std::filesystem::exists(out));
  std::ifstream stream(err);
  const std::string message((std::istreambuf_iterator<char>(stream)), std::istreambuf_iterator<char>());
  EXPECT_NE(message.find("contact_not_converged"), std::string::npos) << message;
  EXPECT_NE(message.find("complete = 0"), std::string::npos) << message;
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slidewave

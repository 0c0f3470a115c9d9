// Checkpoint file (io/checkpoint): the loop state comes back bit for bit (NaN, -0, subnormals, int64
// extremes), the write is atomic (a failed write leaves the earlier checkpoint and no temporary), and
// a checkpoint names exactly what keeps it from resuming a run (build, configuration keys).
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "hdf5_test_support.hpp"
#include "io/checkpoint.hpp"
#include "io/hdf5_support.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

using testing::TempDir;

Checkpoint sample(const RunConfig& config) {
  Checkpoint c;
  c.config_json = config.to_json().dump();
  c.build = current_build();
  c.stream.n_global_rows = 1234;
  c.stream.n_interface_rows = 309;
  c.stream.n_snapshots = 2;
  c.stream.digests = {{"/global/T", 0xfedcba9876543210ull}, {"/interface/state", 1}, {"/snapshots/0001/t", 0}};
  c.state.reals["u"] = {1.0, -0.0, std::nan(""), std::numeric_limits<double>::denorm_min(), 1e308, M_PI};
  c.state.reals["empty"] = {};
  c.state.integers["step"] = {42};
  c.state.integers["state"] = {std::numeric_limits<std::int64_t>::min(), -1, 0,
                               std::numeric_limits<std::int64_t>::max()};
  return c;
}

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
}

TEST(Checkpoint, RoundTripIsBitExact) {
  const TempDir dir("checkpoint_roundtrip");
  const RunConfig config = testing::make_config();
  const Checkpoint written = sample(config);
  write_checkpoint(dir / "run.checkpoint.h5", written);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"run.checkpoint.h5"}) << "no temporary left";
  const Checkpoint read = read_checkpoint(dir / "run.checkpoint.h5");
  EXPECT_EQ(read.config_json, written.config_json);
  EXPECT_EQ(read.build, written.build);
  EXPECT_TRUE(read.stream == written.stream);
  ASSERT_EQ(read.state.reals.size(), written.state.reals.size());
  for (const auto& [name, values] : written.state.reals)
    EXPECT_TRUE(same_bits(read.state.reals.at(name), values)) << name;
  EXPECT_EQ(read.state.integers, written.state.integers);
}

TEST(Checkpoint, ReplacesAtomicallyAndAFailedWriteKeepsTheEarlierOne) {
  const TempDir dir("checkpoint_atomic");
  const RunConfig config = testing::make_config();
  Checkpoint c = sample(config);
  write_checkpoint(dir / "run.checkpoint.h5", c);
  c.state.integers["step"] = {43};
  write_checkpoint(dir / "run.checkpoint.h5", c);
  EXPECT_EQ(read_checkpoint(dir / "run.checkpoint.h5").state.integers.at("step"), std::vector<std::int64_t>{43});
  // The target is made unreplaceable (a non-empty folder): the rename fails, the temporary goes.
  const TempDir blocked("checkpoint_blocked");
  std::filesystem::create_directories(blocked.path / "run.checkpoint.h5" / "inside");
  try {
    write_checkpoint(blocked / "run.checkpoint.h5", c);
    ADD_FAILURE() << "expected an IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("run.checkpoint.h5"), std::string::npos) << e.what();
  }
  EXPECT_EQ(blocked.entries(), std::vector<std::string>{"run.checkpoint.h5"});
  EXPECT_THROW(write_checkpoint(dir / "no_such_folder/run.checkpoint.h5", c), IoError);
}

TEST(Checkpoint, TakesTheModeTheUmaskGives) {
  const TempDir dir("checkpoint_mode");
  const mode_t old = ::umask(027);
  write_checkpoint(dir / "c.h5", sample(testing::make_config()));
  ::umask(old);
  struct stat info {};
  ASSERT_EQ(::stat((dir / "c.h5").c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 0777, 0640u);
}

TEST(Checkpoint, NamesWhatKeepsItFromResuming) {
  const RunConfig config = testing::make_config({{"time", {{"t_end", 1500.0}}}});
  const Checkpoint c = sample(config);
  EXPECT_TRUE(checkpoint_mismatches(c, config).empty());

  nlohmann::json quiet = config.to_json();
  quiet["output"]["progress"] = "always";
  EXPECT_TRUE(checkpoint_mismatches(c, parse_run_config(quiet)).empty()) << "progress does not change results";

  const RunConfig longer = testing::make_config({{"time", {{"t_end", 2000.0}}}, {"friction", {{"f", 1.2}}}});
  const auto problems = checkpoint_mismatches(c, longer);
  ASSERT_EQ(problems.size(), 2u);
  EXPECT_EQ(problems[0], "friction.f: 1.5 in the checkpoint, 1.2 now");
  EXPECT_EQ(problems[1], "time.t_end: 1500.0 in the checkpoint, 2000.0 now");

  Checkpoint other_build = c;
  other_build.build = "slidewave 0.0.9 (git 0123456789ab)";
  const auto build_problems = checkpoint_mismatches(other_build, config);
  ASSERT_EQ(build_problems.size(), 1u);
  EXPECT_NE(build_problems[0].find("build: written by slidewave 0.0.9 (git 0123456789ab), this is slidewave"),
            std::string::npos)
      << build_problems[0];
}

TEST(Checkpoint, ReadingSomethingElseIsAnIoError) {
  const TempDir dir("checkpoint_other");
  EXPECT_THROW(read_checkpoint(dir / "missing.h5"), IoError);
  {
    const hid_t file = H5Fcreate((dir / "other.h5").c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
    H5Fclose(file);
  }
  try {
    read_checkpoint(dir / "other.h5");
    ADD_FAILURE() << "expected an IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("not a slidewave checkpoint"), std::string::npos) << e.what();
  }
}

TEST(Checkpoint, ADamagedOneIsAnIoError) {
  const TempDir dir("checkpoint_damaged");
  Checkpoint c = sample(testing::make_config());
  write_checkpoint(dir / "c.h5", c);
  {
    const hid_t file = H5Fopen((dir / "c.h5").c_str(), H5F_ACC_RDWR, H5P_DEFAULT);
    const hid_t set = H5Dopen2(file, "integers/step", H5P_DEFAULT);
    const std::int64_t edited = 99999999;
    H5Dwrite(set, H5T_NATIVE_INT64, H5S_ALL, H5S_ALL, H5P_DEFAULT, &edited);
    H5Dclose(set);
    H5Fclose(file);
  }
  try {
    read_checkpoint(dir / "c.h5");
    ADD_FAILURE() << "expected an IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("damaged"), std::string::npos) << e.what();
  }
}

TEST(Checkpoint, CountersMustMatchTheRowCounts) {
  const RunConfig config = testing::make_config({{"output", {{"interface_stride", 4}}}});
  Checkpoint c = sample(config);
  c.stream = StreamPosition{};
  c.stream.n_global_rows = 1235;    // t = 0 and 1234 steps
  c.stream.n_interface_rows = 309;  // t = 0 and every 4th step
  c.stream.n_snapshots = 2;
  c.state.integers["counters"] = {1234, 2, 0};
  EXPECT_EQ(inconsistent_counters(c, config), "");
  c.state.integers["counters"] = {99999999, 2, 0};
  EXPECT_NE(inconsistent_counters(c, config).find("step 99999999"), std::string::npos);
  c.state.integers["counters"] = {1234, 3, 0};
  EXPECT_NE(inconsistent_counters(c, config), "");
  c.state.integers.erase("counters");
  EXPECT_NE(inconsistent_counters(c, config), "");
}

TEST(Checkpoint, Path) {
  EXPECT_EQ(checkpoint_path_for("out/run.h5"), "out/run.checkpoint.h5");
  EXPECT_EQ(checkpoint_path_for("run"), "run.checkpoint.h5");
}

}  // namespace
}  // namespace slidewave

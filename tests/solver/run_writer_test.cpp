// Streaming run file (io/run_writer): rows drained in arbitrary blocks give the same datasets, byte for
// byte, as the record written at once; every dataset carries a Fletcher32 checksum that catches a
// corrupted chunk; the partial file is readable between flushes; copy_prefix carries a partial file's
// rows over only when they are the ones a checkpoint counted; a full disk (RLIMIT_FSIZE) gives an
// IoError naming the file and the OS reason and leaves nothing; files get the umask's mode.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>

#include <csignal>
#include <fstream>

#include "hdf5_test_support.hpp"
#include "io/hdf5_support.hpp"
#include "io/run_file.hpp"
#include "io/run_writer.hpp"
#include "io/xdmf.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"

namespace slidewave {
namespace {

using testing::TempDir;

using testing::kSmallRunInput;
using testing::small_run;

/// Rows [g0, g1) of the global series, [i0, i1) of the interface series and snapshots [s0, s1) of `all`,
/// with the layout (x, columns, mesh) and outcome of `all`.
RunRecord rows_of(const RunRecord& all, size_t g0, size_t g1, size_t i0, size_t i1, size_t s0, size_t s1) {
  RunRecord block = all;
  const auto cut = [](auto& v, size_t a, size_t b, size_t width) {
    v.assign(v.begin() + a * width, v.begin() + b * width);
  };
  auto& g = block.global;
  for (auto* v : {&g.t, &g.T, &g.N, &g.T_over_N, &g.energy_kinetic, &g.energy_elastic, &g.work_external,
                  &g.dissipation_friction, &g.work_contact_normal, &g.energy_balance_residual, &g.contact_residual})
    cut(*v, g0, g1, 1);
  cut(g.contact_iterations, g0, g1, 1);
  auto& s = block.interface;
  const size_t n_c = s.x.size();
  cut(s.t, i0, i1, 1);
  for (auto* v : {&s.slip_velocity, &s.slip, &s.opening, &s.normal_traction, &s.tangential_traction})
    cut(v->data, i0, i1, n_c);
  cut(s.state.data, i0, i1, n_c);
  cut(block.snapshots, s0, s1, 1);
  return block;
}

TEST(RunWriter, PutsInPlaceOnlyItsOwnFile) {
  // Another run (a second process into the same output) replaced the working file under this writer:
  // it must not go into place as this run's result (issue 21 item 1).
  const TempDir dir("writer_own_file");
  const auto& [config, rec] = small_run();
  RunWriter mine(dir / "run.partial.h5", config, Provenance{"mine", kSmallRunInput});
  RunRecord rows = rec;
  mine.finish(rows);
  RunWriter other(dir / "run.partial.h5", config, Provenance{"other", kSmallRunInput});
  RunRecord other_rows = rec;
  other.finish(other_rows);
  try {
    mine.put_in_place(dir / "run.h5");
    ADD_FAILURE() << "expected an IoError";
  } catch (const IoError& e) {
    EXPECT_NE(std::string(e.what()).find("another run wrote it"), std::string::npos) << e.what();
  }
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"run.partial.h5"}) << "no RUN.h5, no sidecar";
  // Truncated behind its back: not readable, not put in place either.
  RunWriter truncated(dir / "cut.partial.h5", config, Provenance{"cut", kSmallRunInput});
  RunRecord cut_rows = rec;
  truncated.finish(cut_rows);
  std::filesystem::resize_file(dir / "cut.partial.h5", 96);
  EXPECT_THROW(truncated.put_in_place(dir / "cut.h5"), IoError);
  EXPECT_FALSE(std::filesystem::exists(dir / "cut.h5"));
}

TEST(RunWriter, DrainedInBlocksEqualsWholeFile) {
  const TempDir dir("writer_blocks");
  const auto& [config, rec] = small_run();
  const Provenance provenance{"call", kSmallRunInput};
  write_run_file(dir / "whole.h5", config, rec, provenance);

  const size_t n_g = rec.global.t.size(), n_i = rec.interface.t.size();
  ASSERT_GT(n_g, 40u);
  RunWriter writer(dir / "streamed.partial.h5", config, provenance);
  // Uneven blocks, a block without interface rows, snapshots in separate drains.
  const size_t g_cuts[] = {0, 1, 2, 17, 18, 40, n_g}, i_cuts[] = {0, 1, 1, 6, 6, 14, n_i},
               s_cuts[] = {0, 1, 1, 1, 2, 2, 2};
  for (int b = 0; b + 1 < 7; ++b) {
    RunRecord block = rows_of(rec, g_cuts[b], g_cuts[b + 1], i_cuts[b], i_cuts[b + 1], s_cuts[b], s_cuts[b + 1]);
    writer.drain(block);
    EXPECT_TRUE(block.global.t.empty() && block.interface.t.empty() && block.snapshots.empty()) << "drained";
    EXPECT_FALSE(block.interface.x.empty()) << "the layout stays";
  }
  EXPECT_EQ(writer.position().n_global_rows, static_cast<std::int64_t>(n_g));
  EXPECT_EQ(writer.position().n_interface_rows, static_cast<std::int64_t>(n_i));
  EXPECT_EQ(writer.position().n_snapshots, 2);
  RunRecord outcome = rows_of(rec, 0, 0, 0, 0, 0, 0);
  writer.finish(outcome);
  writer.put_in_place(dir / "streamed.h5");
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"streamed.h5", "streamed.interface.xdmf", "streamed.xdmf",
                                                     "whole.h5", "whole.interface.xdmf", "whole.xdmf"}));

  const auto whole = testing::read_all_datasets(dir / "whole.h5");
  const auto streamed = testing::read_all_datasets(dir / "streamed.h5");
  EXPECT_EQ(whole.size(), 8u + 12u + 2u + 2u * 2u);
  ASSERT_EQ(whole.size(), streamed.size());
  for (const auto& [name, raw] : whole) {
    ASSERT_TRUE(streamed.count(name)) << name;
    EXPECT_TRUE(streamed.at(name) == raw) << name << " differs";
    EXPECT_FALSE(raw.bytes.empty()) << name;
  }
  // And equal to the record itself (not only to the other writer).
  const auto& T = whole.at("/global/T");
  ASSERT_EQ(T.bytes.size(), n_g * sizeof(double));
  EXPECT_EQ(std::memcmp(T.bytes.data(), rec.global.T.data(), T.bytes.size()), 0);
  const auto& state = whole.at("/interface/state");
  EXPECT_EQ(state.shape, (std::vector<hsize_t>{n_i, rec.interface.x.size()}));
  EXPECT_EQ(std::memcmp(state.bytes.data(), rec.interface.state.data.data(), state.bytes.size()), 0);
}

TEST(RunWriter, EveryDatasetHasAFletcher32Checksum) {
  const TempDir dir("writer_fletcher");
  write_run_file(dir / "run.h5", small_run().config, small_run().record, {"call", "{}"});
  const auto datasets = testing::read_all_datasets(dir / "run.h5");
  const hid_t file = H5Fopen((dir / "run.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  for (const auto& [name, raw] : datasets) {
    const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    const hid_t plist = H5Dget_create_plist(set);
    unsigned flags = 0;
    size_t n_values = 0;
    EXPECT_GE(H5Pget_filter_by_id2(plist, H5Z_FILTER_FLETCHER32, &flags, &n_values, nullptr, 0, nullptr, nullptr), 0)
        << name << " has no Fletcher32 filter";
    H5Pclose(plist);
    H5Dclose(set);
  }
  H5Fclose(file);
}

TEST(RunWriter, CorruptedChunkIsReportedOnRead) {
  const TempDir dir("writer_corrupt");
  write_run_file(dir / "run.h5", small_run().config, small_run().record, {"call", "{}"});
  haddr_t address = 0;
  {
    const hid_t file = H5Fopen((dir / "run.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
    const hid_t set = H5Dopen2(file, "/global/T", H5P_DEFAULT);
    hsize_t offset[1];
    unsigned mask;
    hsize_t size;
    const hid_t space = H5Dget_space(set);
    ASSERT_GE(H5Dget_chunk_info(set, space, 0, offset, &mask, &address, &size), 0);
    H5Sclose(space);
    H5Dclose(set);
    H5Fclose(file);
  }
  {
    std::fstream f(dir / "run.h5", std::ios::in | std::ios::out | std::ios::binary);
    f.seekg(static_cast<std::streamoff>(address + 8));
    char byte = 0;
    f.read(&byte, 1);
    byte ^= 0x5a;
    f.seekp(static_cast<std::streamoff>(address + 8));
    f.write(&byte, 1);
  }
  const auto datasets = testing::read_all_datasets(dir / "run.h5");
  EXPECT_TRUE(datasets.at("/global/T").bytes.empty()) << "the read must fail on the checksum";
  EXPECT_FALSE(datasets.at("/global/N").bytes.empty()) << "other datasets stay readable";
}

TEST(RunWriter, PartialFileIsReadableAfterAFlushAndSaysInterrupted) {
  const TempDir dir("writer_partial");
  const auto& [config, rec] = small_run();
  RunWriter writer(dir / "run.partial.h5", config, {"call", "{}"});
  RunRecord first = rows_of(rec, 0, 30, 0, 10, 0, 1);
  first.complete = false;
  first.end_reason = "interrupted";
  first.n_steps_done = 29;
  writer.flush_to_disk(first);
  // Read while the writer still holds the file open (as after a kill).
  const auto datasets = testing::read_all_datasets(dir / "run.partial.h5");
  EXPECT_EQ(datasets.at("/global/t").shape, std::vector<hsize_t>{30});
  EXPECT_EQ(datasets.at("/interface/opening").shape, (std::vector<hsize_t>{10, rec.interface.x.size()}));
  const hid_t file = H5Fopen((dir / "run.partial.h5").c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(h5::read_int_attribute(file, "complete", "f"), 0);
  EXPECT_EQ(h5::read_string_attribute(file, "end_reason", "f"), "interrupted");
  EXPECT_EQ(h5::read_int_attribute(file, "n_steps_done", "f"), 29);
  H5Fclose(file);
}

TEST(RunWriter, CopyPrefixCarriesTheCheckpointedRowsOver) {
  const TempDir dir("writer_prefix");
  const auto& [config, rec] = small_run();
  const size_t n_g = rec.global.t.size(), n_i = rec.interface.t.size();
  write_run_file(dir / "whole.h5", config, rec, {"call", "{}"});
  StreamPosition checkpointed;
  {
    RunWriter earlier(dir / "run.partial.h5", config, {"call", "{}"});
    RunRecord first = rows_of(rec, 0, 31, 0, 11, 0, 1);
    earlier.flush_to_disk(first);
    checkpointed = earlier.position();
    RunRecord after = rows_of(rec, 31, 45, 11, 15, 1, 1);  // written after the checkpoint: dropped on resume
    earlier.drain(after);
  }  // closed without finishing, like an interrupted run
  {
    RunWriter resumed(dir / "resumed.h5.tmp", config, {"call", "{}"});
    resumed.copy_prefix(dir / "run.partial.h5", checkpointed);
    EXPECT_TRUE(resumed.position() == checkpointed);
    RunRecord rest = rows_of(rec, 31, n_g, 11, n_i, 1, 2);
    resumed.finish(rest);
    resumed.put_in_place(dir / "resumed.h5");
  }
  const auto whole = testing::read_all_datasets(dir / "whole.h5");
  const auto resumed = testing::read_all_datasets(dir / "resumed.h5");
  ASSERT_EQ(whole.size(), resumed.size());
  for (const auto& [name, raw] : whole) EXPECT_TRUE(resumed.at(name) == raw) << name;

  // A position the file does not hold: more rows than it has, or other bytes.
  StreamPosition too_far = checkpointed;
  too_far.n_global_rows = 1000;
  StreamPosition other_bytes = checkpointed;
  other_bytes.digests["/global/T"] ^= 1;
  for (const auto* position : {&too_far, &other_bytes}) {
    RunWriter again(dir / "again.h5", config, {"call", "{}"});
    EXPECT_THROW(again.copy_prefix(dir / "run.partial.h5", *position), StreamMismatch);
    again.discard();
  }
  RunWriter missing(dir / "again.h5", config, {"call", "{}"});
  EXPECT_THROW(missing.copy_prefix(dir / "no_such.h5", checkpointed), StreamMismatch);
  missing.discard();
}

/// Runs `write` under a 64 KiB file-size limit with SIGXFSZ ignored (writes fail with EFBIG, as on a
/// full disk); restores both afterwards.
template <typename F>
void with_small_file_limit(F write) {
  rlimit old_limit{};
  getrlimit(RLIMIT_FSIZE, &old_limit);
  const auto old_handler = std::signal(SIGXFSZ, SIG_IGN);
  rlimit small = old_limit;
  small.rlim_cur = 64 * 1024;
  setrlimit(RLIMIT_FSIZE, &small);
  write();
  setrlimit(RLIMIT_FSIZE, &old_limit);
  std::signal(SIGXFSZ, old_handler);
}

TEST(RunWriter, FullDiskNamesTheFileAndTheReasonAndLeavesNothing) {
  const TempDir dir("writer_full");
  RunRecord big = small_run().record;
  big.snapshots.clear();
  for (int copy = 0; copy < 6; ++copy) {  // well over 64 KiB of interface rows
    auto& s = big.interface;
    for (auto* v : {&s.slip_velocity, &s.slip, &s.opening, &s.normal_traction, &s.tangential_traction})
      v->data.insert(v->data.end(), v->data.begin(), v->data.end());
    s.state.data.insert(s.state.data.end(), s.state.data.begin(), s.state.data.end());
    s.t.insert(s.t.end(), s.t.begin(), s.t.end());
  }
  std::string message;
  with_small_file_limit([&] {
    try {
      write_run_file(dir / "run.h5", small_run().config, big, {"call", "{}"});
    } catch (const IoError& e) {
      message = e.what();
    }
  });
  EXPECT_NE(message.find(dir / "run.h5"), std::string::npos) << message;
  EXPECT_NE(message.find("File too large"), std::string::npos) << message;
  EXPECT_TRUE(dir.entries().empty()) << "left: " << (dir.entries().empty() ? "" : dir.entries()[0]);
}

TEST(RunWriter, FilesTakeTheModeTheUmaskGives) {
  for (mode_t mask : {022, 002, 077}) {
    const TempDir dir("writer_mode");
    const mode_t old = ::umask(mask);
    write_run_file(dir / "run.h5", small_run().config, small_run().record, {"call", "{}"});
    ::umask(old);
    for (const char* name : {"run.h5", "run.xdmf", "run.interface.xdmf"}) {
      struct stat info {};
      ASSERT_EQ(::stat((dir / name).c_str(), &info), 0) << name;
      EXPECT_EQ(info.st_mode & 0777, 0666 & ~mask) << name << " with umask " << std::oct << mask;
    }
  }
}

}  // namespace
}  // namespace slidewave

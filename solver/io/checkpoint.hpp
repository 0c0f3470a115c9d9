#pragma once
// RUN.checkpoint.h5: everything `slidewave run --resume` needs to continue a run so that its datasets
// come out bit-identical to an uninterrupted run: the loop state (named arrays of doubles and
// integers, bit-exact), how far the partial file RUN.partial.h5 is (rows and their digests), and the
// fingerprint of what may resume it (the resolved configuration and the build).
// Written atomically: temporary file, fsync, rename, fsync of the folder.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "config/run_config.hpp"
#include "io/run_writer.hpp"
#include "model/run_observer.hpp"

namespace slidewave {

struct Checkpoint {
  std::string config_json;  ///< resolved configuration of the run (RunConfig::to_json().dump())
  std::string build;        ///< current_build() of the solver that wrote it
  StreamPosition stream;    ///< what RUN.partial.h5 holds at this state
  StateArrays state;        ///< the loop's evolving state (model/loop_state_arrays.hpp)
};

/// RUN.h5 -> RUN.checkpoint.h5 (the extension .h5 is replaced if present, else appended to).
std::string checkpoint_path_for(const std::string& h5_path);

/// "slidewave <version> (git <commit>)": a checkpoint resumes only in the build that wrote it.
std::string current_build();

/// Writes `checkpoint` to `path` atomically. Throws IoError naming the file and the reason (the
/// temporary file is removed; an earlier checkpoint at `path` stays as it was).
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

/// Reads a checkpoint. Throws IoError naming the file when it is unreadable or not a checkpoint.
Checkpoint read_checkpoint(const std::string& path);

/// What keeps `checkpoint` from resuming a run of `config` in this build, one line each ("build: ...",
/// "time.t_end: 1500 in the checkpoint, 2000 now"); empty when it may resume. Keys that do not change
/// the results (output.progress, output.checkpoint_interval) may differ.
std::vector<std::string> checkpoint_mismatches(const Checkpoint& checkpoint, const RunConfig& config);

}  // namespace slidewave

#pragma once
// RUN.checkpoint.h5: everything `slidewave run --resume` needs to continue a run so that its datasets
// come out bit-identical to an uninterrupted run: the loop state (named arrays of doubles and
// integers, bit-exact), how far the partial file RUN.partial.h5 is (rows and their digests), and the
// fingerprint of what may resume it (the resolved configuration and the build), and a digest of all
// of it (FNV-1a over every dataset's bytes and every attribute), checked on reading.
// Written atomically: temporary file "<path>.tmp.<run id>" (io/run_id.hpp), fsync, rename, fsync of
// the folder.
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "config/run_config.hpp"
#include "io/run_id.hpp"
#include "io/run_writer.hpp"
#include "model/run_observer.hpp"

namespace slidewave {

struct Checkpoint {
  std::string config_json;            ///< resolved configuration of the run (RunConfig::to_json().dump())
  std::string build;                  ///< current_build() of the solver that wrote it
  StreamPosition stream;              ///< what RUN.partial.h5 holds at this state
  StateArrays state;                  ///< the loop's evolving state (model/loop_state_arrays.hpp)
  std::string run_id = new_run_id();  ///< the run that wrote it (names its temporary file)
};

/// RUN.h5 -> RUN.checkpoint.h5 (the extension .h5 is replaced if present, else appended to).
std::string checkpoint_path_for(const std::string& h5_path);

/// "slidewave <version> (git <commit>)": a checkpoint resumes only in the build that wrote it.
std::string current_build();

/// Writes `checkpoint` to `path` atomically. Throws IoError naming the file and the reason (the
/// temporary file is removed; an earlier checkpoint at `path` stays as it was).
void write_checkpoint(const std::string& path, const Checkpoint& checkpoint);

/// Reads a checkpoint. Throws IoError naming the file when it is unreadable, not a checkpoint (of this
/// format), or damaged (its content does not match its digest).
Checkpoint read_checkpoint(const std::string& path);

/// Why the checkpoint's step counters disagree with the rows it says the partial file holds (one
/// /global row per step and at t = 0, an /interface row every output.interface_stride steps, its
/// snapshot count); empty when they agree. A disagreement means a damaged or edited checkpoint.
std::string inconsistent_counters(const Checkpoint& checkpoint, const RunConfig& config);

/// What keeps `checkpoint` from resuming a run of `config` in this build, one line each ("build: ...",
/// "time.t_end: 1500 in the checkpoint, 2000 now"); empty when it may resume. Keys that do not change
/// the results (output.progress, output.checkpoint_interval) may differ.
std::vector<std::string> checkpoint_mismatches(const Checkpoint& checkpoint, const RunConfig& config);

}  // namespace slidewave

#pragma once
// What run.h5 (format_version 2, or 3 with a substrate: docs/contracts.md section 2) says about itself: the header
// written when the file is created (provenance and resolved configuration at the root; /setup: the verbatim input and
// every derived constant) and the outcome (root: complete, end_reason, n_steps_done, t_first_opening; /setup:
// u_x_preshear and opening_threshold, known after the preload), rewritten whenever it changes (checkpoints, the end).
#include <hdf5.h>

#include <string>

#include "config/run_config.hpp"
#include "io/run_id.hpp"
#include "model/run_record.hpp"

namespace slidewave {

inline constexpr int kRunFormatVersion = 2;
/// A run with a deformable substrate (docs/substrate.md): relative interface fields, /substrate_snapshots and
/// the substrate's constants in /setup. A rigid-flat run keeps writing kRunFormatVersion (its file unchanged).
inline constexpr int kRunFormatVersionSubstrate = 3;

/// The format_version a run of `config` writes.
inline int run_format_version(const RunConfig& config) {
  return config.substrate.present() ? kRunFormatVersionSubstrate : kRunFormatVersion;
}

struct Provenance {
  std::string call;                   ///< the command line
  std::string config_input;           ///< the verbatim input file
  std::string run_id = new_run_id();  ///< this run (root attribute run_id; names its temporary files)
};

/// Root attributes that do not change during the run, and /setup with the constants known before the
/// run. Throws IoError naming `path`.
void write_run_header(hid_t file, const std::string& path, const RunConfig& config, const Provenance& provenance);

/// Outcome attributes from the record, replacing earlier values. Throws IoError naming `path`.
void write_run_outcome(hid_t file, const std::string& path, const RunRecord& record);

}  // namespace slidewave

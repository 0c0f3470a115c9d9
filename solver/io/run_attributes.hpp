#pragma once
// What run.h5 says about itself (docs/contracts.md section 2): the header written when the file is
// created (provenance, resolved and verbatim configuration, derived constants) and the outcome
// (complete, end_reason, n_steps_done, ...), rewritten whenever it changes (checkpoints, the end).
#include <hdf5.h>

#include <string>

#include "config/run_config.hpp"
#include "model/run_record.hpp"

namespace slidewave {

inline constexpr int kRunFormatVersion = 1;

struct Provenance {
  std::string call;          ///< the command line
  std::string config_input;  ///< the verbatim input file
};

/// Root attributes that do not change during the run, and /setup. Throws IoError naming `path`.
void write_run_header(hid_t file, const std::string& path, const RunConfig& config, const Provenance& provenance);

/// Outcome attributes from the record (complete, end_reason, n_steps_done, t_first_opening,
/// u_x_preshear), replacing earlier values. Throws IoError naming `path`.
void write_run_outcome(hid_t file, const std::string& path, const RunRecord& record);

}  // namespace slidewave

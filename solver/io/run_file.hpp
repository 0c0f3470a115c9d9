#pragma once
// Writes run.h5 (format_version 1, docs/contracts.md section 2) and its XDMF sidecars (io/xdmf.hpp)
// that ParaView opens. Both are written to a temporary name and renamed, so a failed
// or killed run never leaves a file that looks complete (an incomplete run is written with
// complete = 0 and its end_reason).
#include <string>

#include "config/run_config.hpp"
#include "model/run_record.hpp"

namespace slidewave {

inline constexpr int kRunFormatVersion = 1;

struct Provenance {
  std::string call;          ///< the command line
  std::string config_input;  ///< the verbatim input file
};

/// Throws std::runtime_error on any HDF5 failure (and removes the temporary file).
void write_run_file(const std::string& path, const RunConfig& config, const RunRecord& record,
                    const Provenance& provenance);

}  // namespace slidewave

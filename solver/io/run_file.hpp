#pragma once
// Writes a whole run.h5 at once from a record held in memory (tests, tools): the same datasets,
// attributes and checksums as the streaming writer (io/run_writer.hpp), which it uses. The file is
// written under a temporary name and renamed, so a failed write never leaves a file that looks
// complete; the XDMF sidecars (io/xdmf.hpp) go into place after it.
#include <string>

#include "config/run_config.hpp"
#include "io/run_attributes.hpp"
#include "model/run_record.hpp"

namespace slidewave {

/// Throws IoError (io/hdf5_support.hpp) on any failure, naming the file and the reason, and removes
/// the temporary file.
void write_run_file(const std::string& path, const RunConfig& config, const RunRecord& record,
                    const Provenance& provenance);

}  // namespace slidewave

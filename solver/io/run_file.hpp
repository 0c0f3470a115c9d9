#pragma once
// Writes a whole run.h5 at once from a record held in memory (tests, tools): the same datasets,
// attributes and checksums as the streaming writer (io/run_writer.hpp), which it uses. The file is
// written under a temporary name and renamed, so a failed write never leaves a file that looks
// complete; the XDMF sidecar that ParaView opens goes into place after it.
#include <string>

#include "config/run_config.hpp"
#include "io/run_attributes.hpp"
#include "model/run_record.hpp"

namespace slidewave {

/// Throws IoError (io/hdf5_support.hpp) on any failure, naming the file and the reason, and removes
/// the temporary file.
void write_run_file(const std::string& path, const RunConfig& config, const RunRecord& record,
                    const Provenance& provenance);

/// Path of the XDMF sidecar of an HDF5 path (RUN.h5 -> RUN.xdmf).
std::string xdmf_path_for(const std::string& h5_path);

/// The file name of a path (the sidecar refers to RUN.h5 by it, so that the pair can move together).
std::string base_name(const std::string& path);

/// Writes the bulk XDMF sidecar for the record's snapshot times and mesh, pointing into `h5_name`;
/// checked after the file is flushed and closed. Throws IoError naming the file.
void write_bulk_xdmf(const std::string& path, const std::string& h5_name, const RunRecord& record);

}  // namespace slidewave

#pragma once
// XDMF sidecars of run.h5, so that ParaView (or any XDMF reader) opens a run without custom code.
// They hold no data: every DataItem points into RUN.h5 by its base name, so they stay valid when the
// pair is moved together (docs/contracts.md, section 2).
//   RUN.xdmf            the bulk snapshots: quadrilateral mesh, displacement and velocity per time
//   RUN.interface.xdmf  the interface series: a line over x (rectilinear, 1 x n_c), one grid per
//                       output time, with slip_velocity, slip, opening, normal_traction,
//                       tangential_traction and state as node attributes (hyperslabs of /interface)
// ParaView opens both with its "XDMF Reader" (vtkXdmfReader, XDMF 2; tests/paraview); its Xdmf3
// readers read the bulk file but leave out the hyperslab attributes of the interface file.
// Both are written under a temporary name first and renamed only once RUN.h5 is in place, so a
// sidecar never points at a missing file.
#include <string>

#include "model/run_record.hpp"

namespace slidewave {

/// Bulk sidecar path of a run file: RUN.h5 -> RUN.xdmf (the extension is replaced, if any).
std::string xdmf_path_for(const std::string& h5_path);

/// Interface sidecar path of a run file: RUN.h5 -> RUN.interface.xdmf.
std::string interface_xdmf_path_for(const std::string& h5_path);

/// Writes the bulk sidecar of `record.snapshots` to `path`, pointing into the file named `h5_name`.
/// Throws std::runtime_error when the file cannot be written.
void write_bulk_xdmf(const std::string& path, const std::string& h5_name, const RunRecord& record);

/// Writes the interface sidecar of `record.interface` to `path`, pointing into `h5_name`.
/// Throws std::runtime_error when the file cannot be written.
void write_interface_xdmf(const std::string& path, const std::string& h5_name, const RunRecord& record);

/// Writes the sidecars the record has data for (bulk: snapshots; interface: output times) beside
/// `h5_path` under the temporary names "<sidecar>.tmp.<run_id>" (io/run_id.hpp). On failure removes
/// them and throws.
void stage_xdmf_sidecars(const std::string& h5_path, const RunRecord& record, const std::string& run_id);

/// Renames the staged sidecars into place (call after RUN.h5 itself was renamed). Throws on failure.
void publish_xdmf_sidecars(const std::string& h5_path, const RunRecord& record, const std::string& run_id);

/// Removes the staged sidecars (RUN.h5 could not be put in place).
void discard_xdmf_sidecars(const std::string& h5_path, const std::string& run_id);

}  // namespace slidewave

#include "io/xdmf.hpp"

#include <cstdio>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <tuple>

#include "io/run_id.hpp"
#include "io/run_layout.hpp"

namespace slidewave {
namespace {

std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::string without_extension(const std::string& path) {
  const auto dot = path.find_last_of('.');
  const auto slash = path.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return has_ext ? path.substr(0, dot) : path;
}

/// A stream that prints doubles with all their digits: a reader's time must equal the HDF5 one.
std::ofstream open_exact(const std::string& path) {
  std::ofstream out(path);
  out.precision(std::numeric_limits<double>::max_digits10);
  return out;
}

/// Both sidecars are one temporal collection of uniform grids, one a time step.
std::ofstream begin_temporal_collection(const std::string& path, const char* name) {
  std::ofstream out = open_exact(path);
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"" << name << "\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  return out;
}

/// Opens the grid of time step k, named PREFIX_k with k zero-padded to `digits` digits.
void begin_time_step(std::ofstream& out, const char* prefix, int digits, std::size_t k, double t) {
  char id[32];
  std::snprintf(id, sizeof id, "%0*zu", digits, k);
  out << "   <Grid Name=\"" << prefix << "_" << id << "\" GridType=\"Uniform\">\n"
      << "    <Time Value=\"" << t << "\"/>\n";
}

void end_temporal_collection(std::ofstream& out, const std::string& path) {
  out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  out.close();
  if (!out) throw std::runtime_error("cannot write " + path);
}

std::string hdf_item(const std::string& dimensions, const char* number_type, int precision, const std::string& target) {
  return "<DataItem Dimensions=\"" + dimensions + "\" NumberType=\"" + number_type + "\" Precision=\"" +
         std::to_string(precision) + "\" Format=\"HDF\">" + target + "</DataItem>";
}

struct InterfaceField {
  const char* name;
  const char* number_type;
  int precision;
};
// The /interface series of docs/contracts.md section 2, (n_out x n_c) each.
constexpr InterfaceField kInterfaceFields[] = {
    {"slip_velocity", "Float", 8},       {"slip", "Float", 8}, {"opening", "Float", 8}, {"normal_traction", "Float", 8},
    {"tangential_traction", "Float", 8}, {"state", "Char", 1},
};

bool has_interface(const RunRecord& record) { return !record.interface.t.empty(); }
bool has_bulk(const RunRecord& record) { return !record.snapshots.empty(); }

}  // namespace

std::string xdmf_path_for(const std::string& h5_path) { return without_extension(h5_path) + ".xdmf"; }

std::string interface_xdmf_path_for(const std::string& h5_path) {
  return without_extension(h5_path) + ".interface.xdmf";
}

/// The mesh and fields of one body at snapshot `id`, under `group` (/snapshots or /substrate_snapshots).
void write_body(std::ofstream& out, const std::string& h5_name, const SnapshotMesh& mesh, const std::string& group,
                const std::string& id) {
  const std::string n_nodes = std::to_string(mesh.coordinates.size() / 2);
  const std::string n_elements = std::to_string(mesh.connectivity.size() / 4);
  out << "    <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << n_elements << "\">\n     "
      << hdf_item(n_elements + " 4", "Int", 8, h5_name + ":" + group + "/connectivity") << "\n    </Topology>\n"
      << "    <Geometry GeometryType=\"XY\">\n     "
      << hdf_item(n_nodes + " 2", "Float", 8, h5_name + ":" + group + "/coordinates") << "\n    </Geometry>\n";
  for (const char* field : {"displacement", "velocity"})
    out << "    <Attribute Name=\"" << field << "\" AttributeType=\"Vector\" Center=\"Node\">\n     "
        << hdf_item(n_nodes + " 2", "Float", 8, h5_name + ":" + group + "/" + id + "/" + field)
        << "\n    </Attribute>\n";
}

void write_bulk_xdmf(const std::string& path, const std::string& h5_name, const RunRecord& rec) {
  // With a substrate (docs/substrate.md) each time is a spatial collection of the layer and the substrate.
  const bool substrate = !rec.substrate_snapshot_mesh.coordinates.empty();
  std::ofstream out = begin_temporal_collection(path, "layer");
  for (size_t s = 0; s < rec.snapshots.size(); ++s) {
    const std::string id = run_layout::snapshot_id(s);
    if (!substrate) {
      begin_time_step(out, "snapshot", 4, s, rec.snapshots[s].t);
      write_body(out, h5_name, rec.snapshot_mesh, "/snapshots", id);
      out << "   </Grid>\n";
      continue;
    }
    out << "   <Grid Name=\"snapshot_" << id << "\" GridType=\"Collection\" CollectionType=\"Spatial\">\n"
        << "    <Time Value=\"" << rec.snapshots[s].t << "\"/>\n";
    for (const auto& [name, mesh, group] :
         {std::tuple{"layer", &rec.snapshot_mesh, "/snapshots"},
          std::tuple{"substrate", &rec.substrate_snapshot_mesh, "/substrate_snapshots"}}) {
      out << "   <Grid Name=\"" << name << "_" << id << "\" GridType=\"Uniform\">\n";
      write_body(out, h5_name, *mesh, group, id);
      out << "   </Grid>\n";
    }
    out << "   </Grid>\n";
  }
  end_temporal_collection(out, path);
}

// The line is a 2-D rectilinear mesh of 1 x n_c nodes (VX = /interface/x, VY = 0): no connectivity
// to store, and readers treat it as a line that ParaView's "Plot Data" draws against x. Row k of
// each (n_out x n_c) dataset is selected with a hyperslab (start k 0, stride 1 1, count 1 n_c).
void write_interface_xdmf(const std::string& path, const std::string& h5_name, const RunRecord& rec) {
  const auto& s = rec.interface;
  const std::string n_c = std::to_string(s.x.size());
  const std::string n_out = std::to_string(s.t.size());
  std::ofstream out = begin_temporal_collection(path, "interface");
  for (size_t k = 0; k < s.t.size(); ++k) {
    begin_time_step(out, "interface", 5, k, s.t[k]);
    out << "    <Topology TopologyType=\"2DRectMesh\" Dimensions=\"1 " << n_c << "\"/>\n"
        << "    <Geometry GeometryType=\"VXVY\">\n     " << hdf_item(n_c, "Float", 8, h5_name + ":/interface/x") << "\n"
        << "     <DataItem Dimensions=\"1\" NumberType=\"Float\" Precision=\"8\" Format=\"XML\">0</DataItem>\n"
        << "    </Geometry>\n";
    for (const auto& field : kInterfaceFields)
      out << "    <Attribute Name=\"" << field.name << "\" AttributeType=\"Scalar\" Center=\"Node\">\n"
          << "     <DataItem ItemType=\"HyperSlab\" Dimensions=\"1 " << n_c << "\" Type=\"HyperSlab\">\n"
          << "      <DataItem Dimensions=\"3 2\" Format=\"XML\">" << k << " 0 1 1 1 " << n_c << "</DataItem>\n      "
          << hdf_item(n_out + " " + n_c, field.number_type, field.precision, h5_name + ":/interface/" + field.name)
          << "\n     </DataItem>\n    </Attribute>\n";
    out << "   </Grid>\n";
  }
  end_temporal_collection(out, path);
}

void stage_xdmf_sidecars(const std::string& h5_path, const RunRecord& record, const std::string& run_id) {
  const std::string h5_name = base_name(h5_path);
  try {
    if (has_bulk(record)) write_bulk_xdmf(temporary_path_for(xdmf_path_for(h5_path), run_id), h5_name, record);
    if (has_interface(record))
      write_interface_xdmf(temporary_path_for(interface_xdmf_path_for(h5_path), run_id), h5_name, record);
  } catch (...) {
    discard_xdmf_sidecars(h5_path, run_id);
    throw;
  }
}

void publish_xdmf_sidecars(const std::string& h5_path, const RunRecord& record, const std::string& run_id) {
  for (const auto& [present, sidecar] : {std::pair{has_bulk(record), xdmf_path_for(h5_path)},
                                         std::pair{has_interface(record), interface_xdmf_path_for(h5_path)}}) {
    const std::string staged = temporary_path_for(sidecar, run_id);
    if (present && std::rename(staged.c_str(), sidecar.c_str()) != 0)
      throw std::runtime_error("cannot rename " + staged + " to " + sidecar);
  }
}

void discard_xdmf_sidecars(const std::string& h5_path, const std::string& run_id) {
  std::remove(temporary_path_for(xdmf_path_for(h5_path), run_id).c_str());
  std::remove(temporary_path_for(interface_xdmf_path_for(h5_path), run_id).c_str());
}

}  // namespace slidewave

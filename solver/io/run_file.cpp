#include "io/run_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>

#include "io/hdf5_support.hpp"
#include "io/run_writer.hpp"

namespace slidewave {

std::string xdmf_path_for(const std::string& h5_path) {
  const auto dot = h5_path.find_last_of('.');
  const auto slash = h5_path.find_last_of('/');
  const bool has_ext = dot != std::string::npos && (slash == std::string::npos || dot > slash);
  return (has_ext ? h5_path.substr(0, dot) : h5_path) + ".xdmf";
}

std::string base_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

void write_bulk_xdmf(const std::string& path, const std::string& h5_name, const RunRecord& rec) {
  const size_t n_nodes = rec.snapshot_mesh.coordinates.size() / 2;
  const size_t n_elements = rec.snapshot_mesh.connectivity.size() / 4;
  errno = 0;
  std::ofstream out(path);
  out << "<?xml version=\"1.0\" ?>\n<Xdmf Version=\"3.0\">\n <Domain>\n"
      << "  <Grid Name=\"layer\" GridType=\"Collection\" CollectionType=\"Temporal\">\n";
  for (size_t s = 0; s < rec.snapshots.size(); ++s) {
    char id[32];
    std::snprintf(id, sizeof id, "%04zu", s);
    out << "   <Grid Name=\"snapshot_" << id << "\" GridType=\"Uniform\">\n"
        << "    <Time Value=\"" << rec.snapshots[s].t << "\"/>\n"
        << "    <Topology TopologyType=\"Quadrilateral\" NumberOfElements=\"" << n_elements << "\">\n"
        << "     <DataItem Dimensions=\"" << n_elements << " 4\" NumberType=\"Int\" Precision=\"8\" Format=\"HDF\">"
        << h5_name << ":/snapshots/connectivity</DataItem>\n    </Topology>\n"
        << "    <Geometry GeometryType=\"XY\">\n     <DataItem Dimensions=\"" << n_nodes
        << " 2\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">" << h5_name
        << ":/snapshots/coordinates</DataItem>\n    </Geometry>\n";
    for (const char* field : {"displacement", "velocity"})
      out << "    <Attribute Name=\"" << field << "\" AttributeType=\"Vector\" Center=\"Node\">\n"
          << "     <DataItem Dimensions=\"" << n_nodes << " 2\" NumberType=\"Float\" Precision=\"8\" Format=\"HDF\">"
          << h5_name << ":/snapshots/" << id << "/" << field << "</DataItem>\n    </Attribute>\n";
    out << "   </Grid>\n";
  }
  out << "  </Grid>\n </Domain>\n</Xdmf>\n";
  out.close();  // flushes: a full disk shows only here
  if (!out) {
    const std::string reason = errno ? std::strerror(errno) : "write failed";
    std::remove(path.c_str());
    throw IoError("cannot write " + path + ": " + reason);
  }
}

void write_run_file(const std::string& path, const RunConfig& config, const RunRecord& rec,
                    const Provenance& provenance) {
  RunWriter writer(path + ".tmp." + std::to_string(::getpid()), config, provenance);
  try {
    RunRecord rows = rec;  // drained by the writer
    writer.finish(rows);
    writer.put_in_place(path);
  } catch (...) {
    writer.discard();
    throw;
  }
}

}  // namespace slidewave

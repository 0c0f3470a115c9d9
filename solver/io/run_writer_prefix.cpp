#include <algorithm>

#include "io/hdf5_support.hpp"
#include "io/run_layout.hpp"
#include "io/run_writer.hpp"

// RunWriter::copy_prefix: the part of the writer that --resume uses (io/run_session.hpp).
namespace slidewave {

using h5::Handle;
using namespace run_layout;

void RunWriter::copy_prefix(const std::string& earlier_path, const StreamPosition& position) {
  Handle earlier(H5Fopen(earlier_path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!earlier.valid()) throw StreamMismatch("cannot open " + earlier_path + ": " + h5::last_error_reason());
  try {
    RunRecord block;
    block.interface.x = h5::read_dataset<double>(earlier, "/interface/x", earlier_path);
    const int n_c = static_cast<int>(block.interface.x.size());
    for (auto* s : {&block.interface.slip_velocity, &block.interface.slip, &block.interface.opening,
                    &block.interface.normal_traction, &block.interface.tangential_traction})
      s->n_cols = n_c;
    block.interface.state.n_cols = n_c;
    ensure_layout(block);
    // Rows in blocks (memory stays flat), appended through the same path as during the run.
    const auto read_rows = [&](const std::string& name, auto* out, std::int64_t first, std::int64_t n, int cols) {
      using T = std::remove_pointer_t<decltype(out)>;
      const Handle set = h5::dataset_open(earlier, name, earlier_path);
      Handle space(H5Dget_space(set), H5Sclose);
      hsize_t dims[2] = {0, 0};
      H5Sget_simple_extent_dims(space, dims, nullptr);
      if (static_cast<std::int64_t>(dims[0]) < first + n)
        throw StreamMismatch(earlier_path + ": " + name + " holds " + std::to_string(dims[0]) +
                             " rows, the checkpoint counts " + std::to_string(first + n));
      const hsize_t start[2] = {static_cast<hsize_t>(first), 0},
                    count[2] = {static_cast<hsize_t>(n), static_cast<hsize_t>(cols)};
      h5::check(H5Sselect_hyperslab(space, H5S_SELECT_SET, start, nullptr, count, nullptr), earlier_path, "select in");
      Handle memory(H5Screate_simple(cols ? 2 : 1, count, nullptr), H5Sclose);
      h5::check(H5Dread(set, h5::native_type<T>(), memory, space, H5P_DEFAULT, out), earlier_path,
                "read " + name + " from");
    };
    const std::int64_t block_rows = static_cast<std::int64_t>(kGlobalBlockRows);
    for (std::int64_t first = 0; first < position.n_global_rows; first += block_rows) {
      const std::int64_t n = std::min(block_rows, position.n_global_rows - first);
      for (const GlobalColumn* c : global_columns_) {
        auto& v = block.global.*(c->values);
        v.resize(n);
        read_rows(std::string("/global/") + c->name, v.data(), first, n, 0);
      }
      block.global.contact_iterations.resize(n);
      read_rows("/global/contact_iterations", block.global.contact_iterations.data(), first, n, 0);
      drain(block);
    }
    const std::int64_t interface_rows = static_cast<std::int64_t>(interface_block_rows_);
    for (std::int64_t first = 0; first < position.n_interface_rows; first += interface_rows) {
      const std::int64_t n = std::min(interface_rows, position.n_interface_rows - first);
      block.interface.t.resize(n);
      read_rows("/interface/t", block.interface.t.data(), first, n, 0);
      for (const auto& c : kInterfaceColumns) {
        auto& v = (block.interface.*c.values).data;
        v.resize(n * n_c);
        read_rows(std::string("/interface/") + c.name, v.data(), first, n, n_c);
      }
      block.interface.state.data.resize(n * n_c);
      read_rows("/interface/state", block.interface.state.data.data(), first, n, n_c);
      drain(block);
    }
    // A run with a substrate (format 3) has each snapshot of the substrate beside the layer's.
    const bool substrate = position.n_snapshots > 0 && H5Lexists(earlier, "substrate_snapshots", H5P_DEFAULT) > 0;
    if (position.n_snapshots > 0) {
      block.snapshot_mesh.coordinates = h5::read_dataset<double>(earlier, "/snapshots/coordinates", earlier_path);
      block.snapshot_mesh.connectivity =
          h5::read_dataset<std::int64_t>(earlier, "/snapshots/connectivity", earlier_path);
    }
    if (substrate) {
      block.substrate_snapshot_mesh.coordinates =
          h5::read_dataset<double>(earlier, "/substrate_snapshots/coordinates", earlier_path);
      block.substrate_snapshot_mesh.connectivity =
          h5::read_dataset<std::int64_t>(earlier, "/substrate_snapshots/connectivity", earlier_path);
    }
    for (std::int64_t k = 0; k < position.n_snapshots; ++k) {
      const std::string group = "/snapshots/" + snapshot_id(static_cast<std::size_t>(k));
      const Handle one = h5::group_open(earlier, group, earlier_path);
      Snapshot snapshot{h5::read_double_attribute(one, "t", earlier_path),
                        h5::read_dataset<double>(one, "displacement", earlier_path),
                        h5::read_dataset<double>(one, "velocity", earlier_path)};
      block.snapshots.push_back(std::move(snapshot));
      if (substrate) {
        const Handle below =
            h5::group_open(earlier, "/substrate_snapshots/" + snapshot_id(static_cast<std::size_t>(k)), earlier_path);
        block.substrate_snapshots.push_back(Snapshot{h5::read_double_attribute(below, "t", earlier_path),
                                                     h5::read_dataset<double>(below, "displacement", earlier_path),
                                                     h5::read_dataset<double>(below, "velocity", earlier_path)});
      }
      drain(block);
    }
  } catch (const IoError& e) {
    throw StreamMismatch(e.what());
  }
  if (position_.n_global_rows != position.n_global_rows || position_.n_interface_rows != position.n_interface_rows ||
      position_.n_snapshots != position.n_snapshots)
    throw StreamMismatch(earlier_path + ": row counts differ from the checkpoint's");
  for (const auto& [name, digest] : position.digests) {
    const auto found = position_.digests.find(name);
    if (found == position_.digests.end() || found->second != digest)
      throw StreamMismatch(earlier_path + ": " + name + " does not hold the bytes the checkpoint counted");
  }
}

}  // namespace slidewave

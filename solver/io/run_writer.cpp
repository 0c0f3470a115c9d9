#include "io/run_writer.hpp"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>

#include "config/strict_json.hpp"
#include "io/hdf5_support.hpp"
#include "io/run_layout.hpp"
#include "io/xdmf.hpp"

namespace slidewave {

using h5::Handle;
using namespace run_layout;

namespace {

constexpr std::uint64_t kFnvOffset = 1469598103934665603ull, kFnvPrime = 1099511628211ull;

/// FNV-1a over whole elements (a double or an int as one 64-bit word): independent of how the rows
/// were batched, so a digest computed while streaming equals one computed when reading back.
template <typename T>
std::uint64_t digest_update(std::uint64_t h, const T* data, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    std::uint64_t word = 0;
    std::memcpy(&word, data + i, sizeof(T));
    h = (h ^ word) * kFnvPrime;
  }
  return h;
}

/// Chunk rows for about 32 KiB per chunk.
hsize_t chunk_rows(std::size_t element_size, int n_cols) {
  return std::max<hsize_t>(1, 32768 / (element_size * std::max(1, n_cols)));
}

void describe(hid_t set, const DatasetText& text, const std::string& file) {
  h5::write_string_attribute(set, "unit", text.unit, file);
  h5::write_string_attribute(set, "description", text.description, file);
}

/// A fixed-size dataset written at once, chunked as a whole with a checksum (and compressed if asked).
template <typename T>
void write_fixed(hid_t parent, const std::string& name, const std::vector<T>& data, hsize_t rows, hsize_t cols,
                 const DatasetText& text, bool compress, const std::string& file) {
  const int rank = cols ? 2 : 1;
  const hsize_t dims[2] = {rows, cols};
  const hsize_t chunk[2] = {std::max<hsize_t>(rows, 1), std::max<hsize_t>(cols, 1)};
  Handle space(H5Screate_simple(rank, dims, nullptr), H5Sclose);
  Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
  const std::string what = "create dataset " + name + " in";
  h5::check(H5Pset_chunk(plist, rank, chunk), file, what);
  if (compress) {
    h5::check(H5Pset_shuffle(plist), file, what);
    h5::check(H5Pset_deflate(plist, 4), file, what);
  }
  h5::check(H5Pset_fletcher32(plist), file, what);
  const hid_t id = H5Dcreate2(parent, name.c_str(), h5::native_type<T>(), space, H5P_DEFAULT, plist, H5P_DEFAULT);
  h5::check(id, file, what);
  Handle set(id, H5Dclose);
  if (!data.empty())
    h5::check(H5Dwrite(set, h5::native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), file,
              "write dataset " + name + " to");
  describe(set, text, file);
}

}  // namespace

/// One extendible dataset of a series: rows appended at the end, digest of every element written.
struct RunWriter::Series {
  Handle set;
  hid_t type;
  std::size_t element_size;
  int n_cols;  ///< 0: one value per row (1-D dataset)
  std::int64_t n_rows = 0;
  std::uint64_t digest = kFnvOffset;

  template <typename T>
  static std::unique_ptr<Series> create(hid_t group, const std::string& name, int n_cols, const DatasetText& text,
                                        const std::string& file) {
    const int rank = n_cols ? 2 : 1;
    const hsize_t dims[2] = {0, static_cast<hsize_t>(n_cols)};
    const hsize_t max_dims[2] = {H5S_UNLIMITED, static_cast<hsize_t>(n_cols)};
    const hsize_t chunk[2] = {chunk_rows(sizeof(T), n_cols), static_cast<hsize_t>(n_cols)};
    Handle space(H5Screate_simple(rank, dims, max_dims), H5Sclose);
    Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose);
    const std::string what = "create dataset " + name + " in";
    h5::check(H5Pset_chunk(plist, rank, chunk), file, what);
    h5::check(H5Pset_fletcher32(plist), file, what);
    // Rows are appended in order, so a chunk once left is not written again: one chunk of cache is enough, where
    // HDF5's default 1 MiB per dataset would hold ~30 finished chunks of every series until the file closes.
    Handle access(H5Pcreate(H5P_DATASET_ACCESS), H5Pclose);
    h5::check(H5Pset_chunk_cache(access, H5D_CHUNK_CACHE_NSLOTS_DEFAULT,
                                 chunk[0] * std::max<hsize_t>(1, chunk[1]) * sizeof(T), 1.0),
              file, what);
    const hid_t id = H5Dcreate2(group, name.c_str(), h5::native_type<T>(), space, H5P_DEFAULT, plist, access);
    h5::check(id, file, what);
    auto series = std::make_unique<Series>();
    series->set = Handle(id, H5Dclose);
    series->type = h5::native_type<T>();
    series->element_size = sizeof(T);
    series->n_cols = n_cols;
    describe(series->set, text, file);
    return series;
  }

  /// Appends n_new rows from `data` (row-major, n_new * max(1, n_cols) elements).
  template <typename T>
  void append(const T* data, std::int64_t n_new, const std::string& file, const std::string& name) {
    if (n_new <= 0) return;
    const int rank = n_cols ? 2 : 1;
    const std::string what = "append to " + name + " in";
    const hsize_t new_dims[2] = {static_cast<hsize_t>(n_rows + n_new), static_cast<hsize_t>(n_cols)};
    h5::check(H5Dset_extent(set, new_dims), file, what);
    Handle file_space(H5Dget_space(set), H5Sclose);
    const hsize_t start[2] = {static_cast<hsize_t>(n_rows), 0};
    const hsize_t count[2] = {static_cast<hsize_t>(n_new), static_cast<hsize_t>(n_cols)};
    h5::check(H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, count, nullptr), file, what);
    Handle memory_space(H5Screate_simple(rank, count, nullptr), H5Sclose);
    h5::check(H5Dwrite(set, type, memory_space, file_space, H5P_DEFAULT, data), file, what);
    digest = digest_update(digest, data, static_cast<std::size_t>(n_new) * std::max(1, n_cols));
    n_rows += n_new;
  }
};

struct RunWriter::Files {
  Handle file, interface, global, snapshots, substrate_snapshots;
  /// Closes the groups, then the file (so that the file really closes); returns the file's status.
  herr_t close() {
    substrate_snapshots.close();
    snapshots.close();
    interface.close();
    global.close();
    return file.close();
  }
};

RunWriter::RunWriter(std::string working_path, const RunConfig& config, const Provenance& provenance)
    : path_(std::move(working_path)), run_id_(provenance.run_id), files_(std::make_unique<Files>()) {
  for (const auto& c : kGlobalColumns) global_columns_.push_back(&c);
  if (config.output.energy_decomposition)
    for (const auto& c : kHhtColumns) global_columns_.push_back(&c);
  h5::silence_errors();
  errno = 0;
  // The root attribute config and /setup/config_input hold the configuration: any size.
  const hid_t file = H5Fcreate(path_.c_str(), H5F_ACC_TRUNC, h5::large_attribute_properties(H5P_FILE_CREATE),
                               h5::large_attribute_access());
  if (file < 0) throw IoError("cannot create " + path_ + ": " + h5::last_error_reason());
  files_->file = Handle(file, H5Fclose);
  try {
    write_run_header(file, path_, config, provenance);
    RunRecord nothing_yet;
    nothing_yet.end_reason = "interrupted";  // what a killed run's partial file will say
    write_run_outcome(file, path_, nothing_yet);
  } catch (...) {
    discard();
    throw;
  }
}

RunWriter::~RunWriter() {
  series_.clear();
  if (files_) files_->close();
}

void RunWriter::ensure_layout(const RunRecord& record) {
  if (files_->interface.valid()) return;
  const hid_t file = files_->file;
  n_contact_ = record.interface.slip.n_cols;
  outline_.interface.x = record.interface.x;
  // A chunk of interface rows per drain of the record (and at least one row).
  interface_block_rows_ = std::max<std::size_t>(1, chunk_rows(sizeof(double), n_contact_));
  files_->interface = h5::group_create(file, "interface", path_);
  files_->global = h5::group_create(file, "global", path_);
  write_fixed(files_->interface, "x", record.interface.x, record.interface.x.size(), 0, kInterfaceXText, false, path_);
  series_["/interface/t"] = Series::create<double>(files_->interface, "t", 0, kInterfaceTimeText, path_);
  for (const auto& c : kInterfaceColumns)
    series_[std::string("/interface/") + c.name] =
        Series::create<double>(files_->interface, c.name, n_contact_, c.text, path_);
  series_["/interface/state"] = Series::create<std::int8_t>(files_->interface, "state", n_contact_, kStateText, path_);
  for (const GlobalColumn* c : global_columns_)
    series_[std::string("/global/") + c->name] = Series::create<double>(files_->global, c->name, 0, c->text, path_);
  series_["/global/contact_iterations"] =
      Series::create<int>(files_->global, "contact_iterations", 0, kIterationsText, path_);
}

void RunWriter::write_snapshot(const Snapshot& snapshot, const SnapshotMesh& mesh, const Snapshot* substrate,
                               const SnapshotMesh& substrate_mesh) {
  const hsize_t n_nodes = mesh.coordinates.size() / 2;
  if (!files_->snapshots.valid()) {
    files_->snapshots = h5::group_create(files_->file, "snapshots", path_);
    write_fixed(files_->snapshots, "coordinates", mesh.coordinates, n_nodes, 2,
                {"m", "node coordinates of the unwrapped mesh (the column x = lambda repeats x = 0)"}, true, path_);
    write_fixed(files_->snapshots, "connectivity", mesh.connectivity, mesh.connectivity.size() / 4, 4,
                {"1", "quadrilateral nodes, counter-clockwise"}, true, path_);
    outline_.snapshot_mesh = mesh;
  }
  const std::string id = snapshot_id(static_cast<std::size_t>(position_.n_snapshots));
  const Handle one = h5::group_create(files_->snapshots, id, path_);
  h5::write_double_attribute(one, "t", snapshot.t, path_);
  write_fixed(one, "displacement", snapshot.displacement, n_nodes, 2, {"m", "nodal displacement"}, true, path_);
  write_fixed(one, "velocity", snapshot.velocity, n_nodes, 2, {"m/s", "nodal velocity"}, true, path_);
  const std::string base = "/snapshots/" + id + "/";
  position_.digests[base + "t"] = digest_update(kFnvOffset, &snapshot.t, 1);
  position_.digests[base + "displacement"] =
      digest_update(kFnvOffset, snapshot.displacement.data(), snapshot.displacement.size());
  position_.digests[base + "velocity"] = digest_update(kFnvOffset, snapshot.velocity.data(), snapshot.velocity.size());
  if (substrate) {  // the same snapshot of the substrate (format 3, docs/substrate.md)
    const hsize_t n_below = substrate_mesh.coordinates.size() / 2;
    if (!files_->substrate_snapshots.valid()) {
      files_->substrate_snapshots = h5::group_create(files_->file, "substrate_snapshots", path_);
      outline_.substrate_snapshot_mesh = substrate_mesh;
      write_fixed(files_->substrate_snapshots, "coordinates", substrate_mesh.coordinates, n_below, 2,
                  {"m", "node coordinates of the substrate's unwrapped mesh (y <= 0, the interface at y = 0)"}, true,
                  path_);
      write_fixed(files_->substrate_snapshots, "connectivity", substrate_mesh.connectivity,
                  substrate_mesh.connectivity.size() / 4, 4,
                  {"1", "quadrilateral nodes (counter-clockwise in the mirrored frame y' = -y)"}, true, path_);
    }
    const Handle below = h5::group_create(files_->substrate_snapshots, id, path_);
    h5::write_double_attribute(below, "t", substrate->t, path_);
    write_fixed(below, "displacement", substrate->displacement, n_below, 2, {"m", "nodal displacement"}, true, path_);
    write_fixed(below, "velocity", substrate->velocity, n_below, 2, {"m/s", "nodal velocity"}, true, path_);
    const std::string base_below = "/substrate_snapshots/" + id + "/";
    position_.digests[base_below + "displacement"] =
        digest_update(kFnvOffset, substrate->displacement.data(), substrate->displacement.size());
    position_.digests[base_below + "velocity"] =
        digest_update(kFnvOffset, substrate->velocity.data(), substrate->velocity.size());
  }
  outline_.snapshots.push_back(Snapshot{snapshot.t, {}, {}});
  ++position_.n_snapshots;
}

void RunWriter::drain(RunRecord& record) {
  if (record.interface.x.empty()) return;  // nothing recorded yet: the layout is not known
  ensure_layout(record);
  auto& s = record.interface;
  const std::int64_t n_interface = static_cast<std::int64_t>(s.t.size());
  series_["/interface/t"]->append(s.t.data(), n_interface, path_, "/interface/t");
  for (const auto& c : kInterfaceColumns) {
    const std::string name = std::string("/interface/") + c.name;
    series_[name]->append((s.*c.values).data.data(), n_interface, path_, name);
    (s.*c.values).data.clear();
  }
  series_["/interface/state"]->append(s.state.data.data(), n_interface, path_, "/interface/state");
  s.state.data.clear();
  s.t.clear();

  auto& g = record.global;
  const std::int64_t n_global = static_cast<std::int64_t>(g.t.size());
  for (const GlobalColumn* c : global_columns_) {
    const std::string name = std::string("/global/") + c->name;
    std::vector<double>& values = g.*(c->values);
    if (static_cast<std::int64_t>(values.size()) != n_global)
      throw IoError(path_ + ": " + name + " has " + std::to_string(values.size()) + " rows, /global/t " +
                    std::to_string(n_global) + " (internal error)");
    series_[name]->append(values.data(), n_global, path_, name);
    values.clear();
  }
  series_["/global/contact_iterations"]->append(g.contact_iterations.data(), n_global, path_,
                                                "/global/contact_iterations");
  g.contact_iterations.clear();

  for (std::size_t k = 0; k < record.snapshots.size(); ++k)
    write_snapshot(record.snapshots[k], record.snapshot_mesh,
                   k < record.substrate_snapshots.size() ? &record.substrate_snapshots[k] : nullptr,
                   record.substrate_snapshot_mesh);
  record.snapshots.clear();
  record.substrate_snapshots.clear();

  position_.n_global_rows += n_global;
  position_.n_interface_rows += n_interface;
  for (const auto& [name, series] : series_) position_.digests[name] = series->digest;
}

void RunWriter::flush_to_disk(RunRecord& record) {
  drain(record);
  RunRecord outcome_if_killed;
  outcome_if_killed.complete = false;
  outcome_if_killed.end_reason = "interrupted";
  outcome_if_killed.n_steps_done = record.n_steps_done;
  outcome_if_killed.t_first_opening = record.t_first_opening;
  outcome_if_killed.u_x_preshear = record.u_x_preshear;
  outcome_if_killed.opening_threshold = record.opening_threshold;
  write_run_outcome(files_->file, path_, outcome_if_killed);
  h5::flush_to_disk(files_->file, path_);
}

void RunWriter::finish(RunRecord& record) {
  drain(record);
  write_run_outcome(files_->file, path_, record);
  if (files_->interface.valid()) outline_.interface.t = h5::read_dataset<double>(files_->interface, "t", path_);
  series_.clear();
  // Closing flushes what HDF5 still holds: a full disk shows here at the latest.
  errno = 0;
  h5::check(files_->close(), path_, "write");
}

void RunWriter::check_own_file() const {
  const std::string head = "cannot put " + path_ + " in place: ";
  errno = 0;
  Handle file(H5Fopen(path_.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw IoError(head + "it is not readable: " + h5::last_error_reason());
  const htri_t has_id = H5Aexists(file, "run_id");
  const std::string id = has_id > 0 ? h5::read_string_attribute(file, "run_id", path_) : "none";
  if (id != run_id_)
    throw IoError(head + "another run wrote it (run_id " + excerpt(id) + ", this run " + run_id_ + ")");
  for (const auto& [name, n_rows] :
       {std::pair{"/global/t", position_.n_global_rows}, std::pair{"/interface/t", position_.n_interface_rows}}) {
    if (n_rows == 0) continue;
    const Handle set = h5::dataset_open(file, name, path_);
    Handle space(H5Dget_space(set), H5Sclose);
    if (H5Sget_simple_extent_npoints(space) != n_rows)
      throw IoError(head + std::string(name) + " does not hold the " + std::to_string(n_rows) + " rows this run wrote");
  }
}

void RunWriter::put_in_place(const std::string& final_path) {
  check_own_file();
  try {
    stage_xdmf_sidecars(final_path, outline_, run_id_);
  } catch (const std::exception& e) {
    throw IoError(e.what());
  }
  if (std::rename(path_.c_str(), final_path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    discard_xdmf_sidecars(final_path, run_id_);
    throw IoError("cannot rename " + path_ + " to " + final_path + ": " + reason);
  }
  path_ = final_path;
  try {
    publish_xdmf_sidecars(final_path, outline_, run_id_);
  } catch (const std::exception& e) {
    throw IoError(e.what());
  }
}

void RunWriter::write_sidecars() {
  try {
    stage_xdmf_sidecars(path_, outline_, run_id_);
    publish_xdmf_sidecars(path_, outline_, run_id_);
  } catch (const std::exception& e) {
    discard_xdmf_sidecars(path_, run_id_);
    throw IoError(e.what());
  }
}

void RunWriter::move_to(const std::string& new_path) {
  if (std::rename(path_.c_str(), new_path.c_str()) != 0)
    throw IoError("cannot rename " + path_ + " to " + new_path + ": " + std::strerror(errno));
  path_ = new_path;
}

void RunWriter::close() noexcept {
  series_.clear();
  if (files_) files_->close();
}

void RunWriter::discard() noexcept {
  series_.clear();
  if (files_) files_->close();
  std::remove(path_.c_str());
}

}  // namespace slidewave

#include "io/checkpoint.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <set>

#include "git_version.hpp"
#include "io/hdf5_support.hpp"
#include "io/run_id.hpp"

namespace slidewave {

using h5::Handle;

namespace {

// 2: the state digest (checkpoints of format 1 are not resumed: the run starts over).
constexpr const char* kFormat = "slidewave checkpoint 2";

std::string folder_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : (slash == 0 ? "/" : path.substr(0, slash));
}

template <typename T>
void write_array(hid_t group, const std::string& name, const std::vector<T>& values, const std::string& file) {
  const hsize_t dims[1] = {values.size()};
  Handle space(H5Screate_simple(1, dims, nullptr), H5Sclose);
  const hid_t id = H5Dcreate2(group, name.c_str(), h5::native_type<T>(), space, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
  h5::check(id, file, "create " + name + " in");
  Handle set(id, H5Dclose);
  if (!values.empty())
    h5::check(H5Dwrite(set, h5::native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), file,
              "write " + name + " to");
}

template <typename T>
std::vector<T> read_array(hid_t group, const std::string& name, const std::string& file) {
  const Handle set = h5::dataset_open(group, name, file);
  Handle space(H5Dget_space(set), H5Sclose);
  std::vector<T> values(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  if (!values.empty())
    h5::check(H5Dread(set, h5::native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, values.data()), file,
              "read " + name + " from");
  return values;
}

/// Names of the datasets of a group.
std::vector<std::string> members(hid_t group) {
  std::vector<std::string> names;
  H5Literate(
      group, H5_INDEX_NAME, H5_ITER_INC, nullptr,
      [](hid_t, const char* name, const H5L_info_t*, void* out) -> herr_t {
        static_cast<std::vector<std::string>*>(out)->push_back(name);
        return 0;
      },
      &names);
  return names;
}

/// FNV-1a (64 bit) over bytes, the digest of everything a checkpoint holds: a flipped bit anywhere in
/// its datasets or attributes changes it (HDF5 itself checks nothing in an unfiltered dataset).
class Digest {
 public:
  Digest& add(const void* data, std::size_t n) {
    const auto* bytes = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < n; ++i) h_ = (h_ ^ bytes[i]) * 1099511628211ull;
    return *this;
  }
  Digest& add(const std::string& text) { return add_size(text.size()).add(text.data(), text.size()); }
  Digest& add_size(std::uint64_t n) { return add(&n, sizeof n); }
  template <typename T>
  Digest& add(const std::vector<T>& values) {
    return add_size(values.size()).add(values.data(), values.size() * sizeof(T));
  }
  std::int64_t bits() const {
    std::int64_t b;
    std::memcpy(&b, &h_, sizeof b);
    return b;
  }

 private:
  std::uint64_t h_ = 1469598103934665603ull;
};

std::int64_t state_digest(const Checkpoint& c) {
  Digest d;
  d.add(c.build).add(c.config_json).add(c.run_id);
  d.add_size(static_cast<std::uint64_t>(c.stream.n_global_rows))
      .add_size(static_cast<std::uint64_t>(c.stream.n_interface_rows))
      .add_size(static_cast<std::uint64_t>(c.stream.n_snapshots));
  for (const auto& [name, digest] : c.stream.digests) d.add(name).add_size(digest);
  for (const auto& [name, values] : c.state.reals) d.add(name).add(values);
  for (const auto& [name, values] : c.state.integers) d.add(name).add(values);
  return d.bits();
}

void write_contents(hid_t file, const std::string& path, const Checkpoint& c) {
  h5::write_string_attribute(file, "format", kFormat, path);
  h5::write_string_attribute(file, "build", c.build, path);
  h5::write_string_attribute(file, "config", c.config_json, path);
  h5::write_string_attribute(file, "run_id", c.run_id, path);
  h5::write_int_attribute(file, "state_digest", state_digest(c), path);
  const Handle stream = h5::group_create(file, "stream", path);
  h5::write_int_attribute(stream, "n_global_rows", c.stream.n_global_rows, path);
  h5::write_int_attribute(stream, "n_interface_rows", c.stream.n_interface_rows, path);
  h5::write_int_attribute(stream, "n_snapshots", c.stream.n_snapshots, path);
  std::string names;
  std::vector<std::int64_t> digests;
  for (const auto& [name, digest] : c.stream.digests) {
    names += name + "\n";
    std::int64_t bits;
    std::memcpy(&bits, &digest, sizeof bits);
    digests.push_back(bits);
  }
  h5::write_string_attribute(stream, "digest_names", names, path);
  write_array(stream, "digests", digests, path);
  const Handle reals = h5::group_create(file, "reals", path);
  for (const auto& [name, values] : c.state.reals) write_array(reals, name, values, path);
  const Handle integers = h5::group_create(file, "integers", path);
  for (const auto& [name, values] : c.state.integers) write_array(integers, name, values, path);
}

/// Flattens a JSON object to "group.key" -> value text.
void flatten(const nlohmann::json& j, const std::string& prefix, std::map<std::string, std::string>& out) {
  if (j.is_object()) {
    for (const auto& [key, value] : j.items()) flatten(value, prefix.empty() ? key : prefix + "." + key, out);
  } else {
    out[prefix] = j.dump();
  }
}

}  // namespace

std::string checkpoint_path_for(const std::string& h5_path) {
  const std::string ext = ".h5";
  const bool has_ext =
      h5_path.size() > ext.size() && h5_path.compare(h5_path.size() - ext.size(), ext.size(), ext) == 0;
  return (has_ext ? h5_path.substr(0, h5_path.size() - ext.size()) : h5_path) + ".checkpoint.h5";
}

std::string current_build() { return std::string("slidewave ") + kVersion + " (git " + kGitCommit + ")"; }

void write_checkpoint(const std::string& path, const Checkpoint& checkpoint) {
  h5::silence_errors();
  const std::string temporary = temporary_path_for(path, checkpoint.run_id);
  errno = 0;
  // The root attribute config holds the resolved configuration: any size.
  const hid_t id = H5Fcreate(temporary.c_str(), H5F_ACC_EXCL, h5::large_attribute_properties(H5P_FILE_CREATE),
                             h5::large_attribute_access());
  if (id < 0) throw IoError("cannot create " + temporary + ": " + h5::last_error_reason());
  Handle file(id, H5Fclose);
  try {
    write_contents(file, temporary, checkpoint);
    h5::flush_to_disk(file, temporary);
    errno = 0;
    h5::check(file.close(), temporary, "write");
  } catch (...) {
    file.close();
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    const std::string reason = std::strerror(errno);
    std::remove(temporary.c_str());
    throw IoError("cannot rename " + temporary + " to " + path + ": " + reason);
  }
  // The rename itself is on disk only once the folder is.
  const int folder = ::open(folder_of(path).c_str(), O_RDONLY | O_DIRECTORY);
  if (folder >= 0) {
    ::fsync(folder);
    ::close(folder);
  }
}

Checkpoint read_checkpoint(const std::string& path) {
  h5::silence_errors();
  errno = 0;
  Handle file(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose);
  if (!file.valid()) throw IoError("cannot open " + path + ": " + h5::last_error_reason());
  const htri_t has_format = H5Aexists(file, "format");
  if (has_format <= 0 || h5::read_string_attribute(file, "format", path) != kFormat)
    throw IoError("cannot read " + path + ": not a slidewave checkpoint (format '" + std::string(kFormat) + "')");
  Checkpoint c;
  c.build = h5::read_string_attribute(file, "build", path);
  c.config_json = h5::read_string_attribute(file, "config", path);
  c.run_id = h5::read_string_attribute(file, "run_id", path);
  const long long recorded_digest = h5::read_int_attribute(file, "state_digest", path);
  const Handle stream = h5::group_open(file, "stream", path);
  c.stream.n_global_rows = h5::read_int_attribute(stream, "n_global_rows", path);
  c.stream.n_interface_rows = h5::read_int_attribute(stream, "n_interface_rows", path);
  c.stream.n_snapshots = h5::read_int_attribute(stream, "n_snapshots", path);
  const std::string names = h5::read_string_attribute(stream, "digest_names", path);
  const auto digests = read_array<std::int64_t>(stream, "digests", path);
  std::size_t start = 0, k = 0;
  for (auto end = names.find('\n'); end != std::string::npos; start = end + 1, end = names.find('\n', start), ++k) {
    if (k >= digests.size()) throw IoError("cannot read " + path + ": fewer digests than names");
    std::uint64_t digest;
    std::memcpy(&digest, &digests[k], sizeof digest);
    c.stream.digests[names.substr(start, end - start)] = digest;
  }
  const Handle reals = h5::group_open(file, "reals", path);
  for (const auto& name : members(reals)) c.state.reals[name] = read_array<double>(reals, name, path);
  const Handle integers = h5::group_open(file, "integers", path);
  for (const auto& name : members(integers)) c.state.integers[name] = read_array<std::int64_t>(integers, name, path);
  if (state_digest(c) != recorded_digest)
    throw IoError(path + " is damaged: its content does not match the digest written with it");
  return c;
}

std::string inconsistent_counters(const Checkpoint& checkpoint, const RunConfig& config) {
  const auto found = checkpoint.state.integers.find("counters");
  if (found == checkpoint.state.integers.end() || found->second.size() < 2) return "it has no step counters";
  const std::int64_t step = found->second[0], next_snapshot = found->second[1];
  const auto& s = checkpoint.stream;
  // One /global row at t = 0 and one per step; /interface rows at t = 0 and every interface_stride steps.
  if (step < 0 || s.n_global_rows != step + 1 || s.n_interface_rows != step / config.output.interface_stride + 1 ||
      s.n_snapshots != next_snapshot)
    return "it counts step " + std::to_string(step) + " and snapshot " + std::to_string(next_snapshot) + ", but " +
           std::to_string(s.n_global_rows) + " /global rows, " + std::to_string(s.n_interface_rows) +
           " /interface rows and " + std::to_string(s.n_snapshots) + " snapshots in the partial file";
  return "";
}

std::vector<std::string> checkpoint_mismatches(const Checkpoint& checkpoint, const RunConfig& config) {
  std::vector<std::string> problems;
  if (checkpoint.build != current_build())
    problems.push_back("build: written by " + checkpoint.build + ", this is " + current_build());
  std::map<std::string, std::string> then, now;
  try {
    flatten(nlohmann::json::parse(checkpoint.config_json), "", then);
  } catch (const nlohmann::json::exception&) {
    problems.push_back("config: the checkpoint's configuration is not JSON");
    return problems;
  }
  flatten(config.to_json(), "", now);
  const std::set<std::string> free_to_differ = {"output.progress", "output.checkpoint_interval"};
  std::set<std::string> keys;
  for (const auto& [key, value] : then) keys.insert(key);
  for (const auto& [key, value] : now) keys.insert(key);
  for (const auto& key : keys) {
    if (free_to_differ.count(key)) continue;
    const auto a = then.find(key), b = now.find(key);
    const std::string was = a == then.end() ? "absent" : a->second, is = b == now.end() ? "absent" : b->second;
    if (was != is) problems.push_back(key + ": " + was + " in the checkpoint, " + is + " now");
  }
  return problems;
}

}  // namespace slidewave

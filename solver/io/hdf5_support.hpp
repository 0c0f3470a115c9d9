#pragma once
// Small layer over the HDF5 C API shared by the run-file writers and the checkpoint file:
// handles that close themselves exactly once, errors turned into IoError naming the file and the
// operating system's reason (errno text found on HDF5's error stack), and the attribute helpers.
#include <hdf5.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace slidewave {

/// An output file could not be written or read (full disk, unwritable folder, HDF5 failure).
/// what() names the file and the reason; the CLI exits with the I/O code (4).
class IoError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

namespace h5 {

/// Turns off HDF5's automatic error printing: failures become IoError with our message.
void silence_errors();

/// Keeps HDF5 from closing, at exit, files whose close failed (HDF5 1.10 then crashes in
/// H5F_term_package: a full disk turned into exit 139). Every file is closed explicitly anyway.
/// Call first thing in main(), before any other HDF5 call (later it has no effect).
void skip_library_cleanup_at_exit();

/// The reason of the last HDF5 failure: the OS error text of the innermost error on HDF5's stack
/// ("File too large", "No space left on device") when there is one, else HDF5's own description.
std::string last_error_reason();

/// Throws IoError("cannot <what> <file>: <reason>") when status < 0; returns the status otherwise.
herr_t check(herr_t status, const std::string& file, const std::string& what);

/// An HDF5 identifier closed once, by its owner (never twice, also when closing fails).
class Handle {
 public:
  Handle() = default;
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle(Handle&& other) noexcept { *this = std::move(other); }
  Handle& operator=(Handle&& other) noexcept;
  ~Handle() { close(); }
  hid_t get() const { return id_; }
  operator hid_t() const { return id_; }
  bool valid() const { return id_ >= 0; }
  /// Closes now; returns HDF5's status (the handle is released whatever it is).
  herr_t close();

 private:
  hid_t id_ = -1;
  herr_t (*close_)(hid_t) = nullptr;
};

/// Creation properties of a file (its root group) or a group whose attributes may be of any size:
/// attributes kept in dense storage (a fractal heap) from the first one. Compact storage, HDF5's
/// default, holds an attribute in the object header, whose messages are limited to 64 KiB: a longer
/// configuration (whitespace, 9000 snapshot times) failed as "object header message is too large".
Handle large_attribute_properties(hid_t property_class);
/// File access properties that let the above take effect: objects in the HDF5 1.8 format (version-2
/// object headers), which every reader since 1.8 (2008) opens; chunk indexes stay those of 1.8 too.
Handle large_attribute_access();

/// Checked constructors: throw IoError naming `file` when HDF5 returns a negative id.
/// group_create() takes the group's creation properties (default: HDF5's).
Handle group_create(hid_t parent, const std::string& name, const std::string& file, hid_t properties = H5P_DEFAULT);
Handle group_open(hid_t parent, const std::string& name, const std::string& file);
Handle dataset_open(hid_t parent, const std::string& name, const std::string& file);

void write_string_attribute(hid_t object, const std::string& name, const std::string& value, const std::string& file);
void write_int_attribute(hid_t object, const std::string& name, long long value, const std::string& file);
void write_double_attribute(hid_t object, const std::string& name, double value, const std::string& file);
/// Replaces an attribute that may already exist (deleted first: string sizes change).
void replace_string_attribute(hid_t object, const std::string& name, const std::string& value, const std::string& file);
void replace_int_attribute(hid_t object, const std::string& name, long long value, const std::string& file);
void replace_double_attribute(hid_t object, const std::string& name, double value, const std::string& file);

std::string read_string_attribute(hid_t object, const std::string& name, const std::string& file);
long long read_int_attribute(hid_t object, const std::string& name, const std::string& file);
double read_double_attribute(hid_t object, const std::string& name, const std::string& file);

/// Memory type of a C++ element type (double, int8, int, int64).
template <typename T>
hid_t native_type() {
  if constexpr (std::is_same<T, double>::value) return H5T_NATIVE_DOUBLE;
  if constexpr (std::is_same<T, std::int8_t>::value) return H5T_NATIVE_INT8;
  if constexpr (std::is_same<T, int>::value) return H5T_NATIVE_INT;
  if constexpr (std::is_same<T, std::int64_t>::value) return H5T_NATIVE_INT64;
}

/// A whole dataset in memory (any shape, row-major). Throws IoError naming `file`.
template <typename T>
std::vector<T> read_dataset(hid_t parent, const std::string& name, const std::string& file) {
  const Handle set = dataset_open(parent, name, file);
  Handle space(H5Dget_space(set), H5Sclose);
  std::vector<T> data(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)));
  if (!data.empty())
    check(H5Dread(set, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), file,
          "read dataset " + name + " from");
  return data;
}

/// Flushes the file and asks the OS to put it on disk (fsync), so that what a checkpoint counts is there.
void flush_to_disk(hid_t file, const std::string& path);

}  // namespace h5
}  // namespace slidewave

#include "io/hdf5_support.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace slidewave::h5 {

void silence_errors() { H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr); }

void skip_library_cleanup_at_exit() { H5dont_atexit(); }

namespace {

struct ReasonSearch {
  std::string os_reason;  ///< text after "error message = '" (HDF5's POSIX drivers put strerror there)
  std::string innermost;  ///< description of the innermost error
};

herr_t visit_error(unsigned n, const H5E_error2_t* error, void* data) {
  auto* search = static_cast<ReasonSearch*>(data);
  const std::string desc = error->desc ? error->desc : "";
  if (n == 0) search->innermost = desc;
  const std::string key = "error message = '";
  const auto start = desc.find(key);
  if (search->os_reason.empty() && start != std::string::npos) {
    const auto end = desc.find('\'', start + key.size());
    search->os_reason =
        desc.substr(start + key.size(), end == std::string::npos ? std::string::npos : end - start - key.size());
  }
  return 0;
}

}  // namespace

std::string last_error_reason() {
  ReasonSearch search;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_UPWARD, visit_error, &search);
  if (!search.os_reason.empty()) return search.os_reason;
  // errno only when HDF5 recorded nothing: after an HDF5 failure of its own (a Fletcher32 checksum
  // mismatch) errno is whatever an earlier call left ("No such file or directory").
  if (!search.innermost.empty()) return "HDF5: " + search.innermost;
  return errno != 0 ? std::strerror(errno) : "HDF5 error";
}

herr_t check(herr_t status, const std::string& file, const std::string& what) {
  if (status < 0) throw IoError("cannot " + what + " " + file + ": " + last_error_reason());
  return status;
}

Handle& Handle::operator=(Handle&& other) noexcept {
  if (this != &other) {
    close();
    id_ = other.id_;
    close_ = other.close_;
    other.id_ = -1;
  }
  return *this;
}

herr_t Handle::close() {
  if (id_ < 0 || !close_) return 0;
  const hid_t id = id_;
  id_ = -1;  // released first: a failing close is never retried (a second H5Fclose crashes HDF5)
  return close_(id);
}

namespace {
Handle checked(hid_t id, herr_t (*close)(hid_t), const std::string& file, const std::string& what) {
  if (id < 0) throw IoError("cannot " + what + " in " + file + ": " + last_error_reason());
  return Handle(id, close);
}
}  // namespace

Handle large_attribute_properties(hid_t property_class) {
  Handle properties(H5Pcreate(property_class), H5Pclose);
  if (!properties.valid() || H5Pset_attr_phase_change(properties, 0, 0) < 0)
    throw IoError("cannot set up attribute storage: " + last_error_reason());
  return properties;
}

Handle large_attribute_access() {
  Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  if (!access.valid() || H5Pset_libver_bounds(access, H5F_LIBVER_V18, H5F_LIBVER_V18) < 0)
    throw IoError("cannot set up attribute storage: " + last_error_reason());
  return access;
}

Handle group_create(hid_t parent, const std::string& name, const std::string& file, hid_t properties) {
  return checked(H5Gcreate2(parent, name.c_str(), H5P_DEFAULT, properties, H5P_DEFAULT), H5Gclose, file,
                 "create group " + name);
}
Handle group_open(hid_t parent, const std::string& name, const std::string& file) {
  return checked(H5Gopen2(parent, name.c_str(), H5P_DEFAULT), H5Gclose, file, "open group " + name);
}
Handle dataset_open(hid_t parent, const std::string& name, const std::string& file) {
  return checked(H5Dopen2(parent, name.c_str(), H5P_DEFAULT), H5Dclose, file, "open dataset " + name);
}

void write_string_attribute(hid_t object, const std::string& name, const std::string& value, const std::string& file) {
  const std::string what = "write attribute " + name + " to";
  Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  check(H5Tset_size(type, value.empty() ? 1 : value.size()), file, what);
  check(H5Tset_cset(type, H5T_CSET_UTF8), file, what);
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr = checked(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, file,
                        "create attribute " + name);
  check(H5Awrite(attr, type, value.empty() ? "" : value.c_str()), file, what);
}

namespace {
template <typename T>
void write_number_attribute(hid_t object, const std::string& name, T value, hid_t type, const std::string& file) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  Handle attr = checked(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose, file,
                        "create attribute " + name);
  check(H5Awrite(attr, type, &value), file, "write attribute " + name + " to");
}
void delete_if_exists(hid_t object, const std::string& name, const std::string& file) {
  const htri_t exists = H5Aexists(object, name.c_str());
  check(exists, file, "look up attribute " + name + " in");
  if (exists > 0) check(H5Adelete(object, name.c_str()), file, "delete attribute " + name + " in");
}
}  // namespace

void write_int_attribute(hid_t object, const std::string& name, long long value, const std::string& file) {
  write_number_attribute(object, name, value, H5T_NATIVE_LLONG, file);
}
void write_double_attribute(hid_t object, const std::string& name, double value, const std::string& file) {
  write_number_attribute(object, name, value, H5T_NATIVE_DOUBLE, file);
}
void replace_string_attribute(hid_t object, const std::string& name, const std::string& value,
                              const std::string& file) {
  delete_if_exists(object, name, file);
  write_string_attribute(object, name, value, file);
}
void replace_int_attribute(hid_t object, const std::string& name, long long value, const std::string& file) {
  delete_if_exists(object, name, file);
  write_int_attribute(object, name, value, file);
}
void replace_double_attribute(hid_t object, const std::string& name, double value, const std::string& file) {
  delete_if_exists(object, name, file);
  write_double_attribute(object, name, value, file);
}

std::string read_string_attribute(hid_t object, const std::string& name, const std::string& file) {
  Handle attr = checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, file, "open attribute " + name);
  Handle type(H5Aget_type(attr), H5Tclose);
  if (H5Tget_class(type) != H5T_STRING || H5Tis_variable_str(type) > 0)
    throw IoError("cannot read " + file + ": attribute " + name + " is not a fixed-length string");
  std::vector<char> buffer(H5Tget_size(type) + 1, '\0');
  check(H5Aread(attr, type, buffer.data()), file, "read attribute " + name + " from");
  return std::string(buffer.data(), strnlen(buffer.data(), buffer.size()));
}

long long read_int_attribute(hid_t object, const std::string& name, const std::string& file) {
  Handle attr = checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, file, "open attribute " + name);
  long long value = 0;
  check(H5Aread(attr, H5T_NATIVE_LLONG, &value), file, "read attribute " + name + " from");
  return value;
}

double read_double_attribute(hid_t object, const std::string& name, const std::string& file) {
  Handle attr = checked(H5Aopen(object, name.c_str(), H5P_DEFAULT), H5Aclose, file, "open attribute " + name);
  double value = 0;
  check(H5Aread(attr, H5T_NATIVE_DOUBLE, &value), file, "read attribute " + name + " from");
  return value;
}

void flush_to_disk(hid_t file, const std::string& path) {
  check(H5Fflush(file, H5F_SCOPE_GLOBAL), path, "flush");
  void* handle = nullptr;
  check(H5Fget_vfd_handle(file, H5P_DEFAULT, &handle), path, "get the descriptor of");
  if (::fsync(*static_cast<int*>(handle)) != 0) throw IoError("cannot sync " + path + ": " + std::strerror(errno));
}

}  // namespace slidewave::h5

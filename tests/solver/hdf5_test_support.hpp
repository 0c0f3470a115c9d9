#pragma once
// Helpers of the run-file tests: a small real run, the datasets of an HDF5 file, and every dataset
// read as raw bytes with its shape (the oracle of "same datasets, byte for byte").
#include <hdf5.h>

#include <map>
#include <string>
#include <vector>

#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"

namespace slidewave::testing {

/// As in main(): a test that makes a close fail (full disk) must not crash the binary at exit.
inline const bool kSkipHdf5CleanupAtExit = (H5dont_atexit(), true);

/// The input of the small real run (H/4, 60 s: a few thousand steps), kept verbatim for provenance.
inline const char* const kSmallRunInput = R"({"mesh": {"elements_per_H": 4}, "time": {"t_end": 60.0},
  "output": {"interface_stride": 3, "snapshot_times": [0, 30], "progress": "never"}})";

struct SmallRun {
  RunConfig config;
  RunRecord record;
};

/// kSmallRunInput simulated once per test binary.
inline const SmallRun& small_run() {
  static const SmallRun run = [] {
    const RunConfig config = parse_run_config(nlohmann::json::parse(kSmallRunInput));
    return SmallRun{config, simulate(LayerModel(config))};
  }();
  return run;
}

/// The path (without the leading '/') of every dataset in an open file, in the file's name order.
inline std::vector<std::string> dataset_names(hid_t file) {
  std::vector<std::string> names;
  H5Ovisit(
      file, H5_INDEX_NAME, H5_ITER_NATIVE,
      [](hid_t, const char* name, const H5O_info_t* info, void* data) -> herr_t {
        if (info->type == H5O_TYPE_DATASET) static_cast<std::vector<std::string>*>(data)->push_back(name);
        return 0;
      },
      &names);
  return names;
}

/// A dataset as stored: element class and size, shape, raw bytes in memory order.
struct RawDataset {
  H5T_class_t type_class;
  size_t element_size;
  std::vector<hsize_t> shape;
  std::vector<unsigned char> bytes;
  bool operator==(const RawDataset& o) const {
    return type_class == o.type_class && element_size == o.element_size && shape == o.shape && bytes == o.bytes;
  }
};

/// Every dataset of the file by path; an unreadable one (e.g. a checksum error) has no bytes and size 0.
inline std::map<std::string, RawDataset> read_all_datasets(const std::string& path) {
  std::map<std::string, RawDataset> out;
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  if (file < 0) return out;
  for (const auto& name : dataset_names(file)) {
    const hid_t set = H5Dopen2(file, name.c_str(), H5P_DEFAULT);
    const hid_t type = H5Dget_type(set), space = H5Dget_space(set);
    RawDataset raw;
    raw.type_class = H5Tget_class(type);
    raw.element_size = H5Tget_size(type);
    raw.shape.resize(H5Sget_simple_extent_ndims(space));
    H5Sget_simple_extent_dims(space, raw.shape.data(), nullptr);
    raw.bytes.resize(H5Sget_simple_extent_npoints(space) * raw.element_size);
    const hid_t memory_type = H5Tget_native_type(type, H5T_DIR_ASCEND);
    if (!raw.bytes.empty() && H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.bytes.data()) < 0) {
      raw.bytes.clear();
      raw.element_size = 0;
    }
    H5Tclose(memory_type);
    H5Sclose(space);
    H5Tclose(type);
    H5Dclose(set);
    out["/" + name] = std::move(raw);
  }
  H5Fclose(file);
  return out;
}

}  // namespace slidewave::testing

// run.h5 (io/run_file, docs/contracts.md §2): write a real run, read it back with the HDF5 C API
// (provenance, resolved and verbatim config, shapes, unit/description on every dataset, values bit
// for bit), and check that failed writes leave nothing behind.
#include <gtest/gtest.h>
#include <hdf5.h>
#include <unistd.h>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>

#include "git_version.hpp"
#include "hdf5_test_support.hpp"
#include "io/run_file.hpp"
#include "io/xdmf.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"

namespace slidewave {
namespace {

namespace fs = std::filesystem;

using testing::dataset_names;
using testing::kSmallRunInput;
using testing::small_run;
using testing::TempDir;

// ---- minimal HDF5 readers ----------------------------------------------------------------------

std::string read_string_attribute(hid_t object, const char* name) {
  const hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
  if (attr < 0) return "<missing " + std::string(name) + ">";
  const hid_t type = H5Aget_type(attr);
  std::string value;
  if (H5Tget_class(type) == H5T_STRING && !H5Tis_variable_str(type)) {
    std::vector<char> buffer(H5Tget_size(type) + 1, '\0');
    H5Aread(attr, type, buffer.data());
    value.assign(buffer.data(), strnlen(buffer.data(), buffer.size()));
  } else {
    value = "<not a fixed-length string>";
  }
  H5Tclose(type);
  H5Aclose(attr);
  return value;
}

template <typename T>
T read_number_attribute(hid_t object, const char* name) {
  T value{};
  const hid_t attr = H5Aopen(object, name, H5P_DEFAULT);
  EXPECT_GE(attr, 0) << name;
  if (attr < 0) return value;
  H5Aread(attr, std::is_integral<T>::value ? H5T_NATIVE_LLONG : H5T_NATIVE_DOUBLE, &value);
  H5Aclose(attr);
  return value;
}

std::vector<std::string> attribute_names(hid_t object) {
  std::vector<std::string> names;
  hsize_t index = 0;
  H5Aiterate2(
      object, H5_INDEX_NAME, H5_ITER_INC, &index,
      [](hid_t, const char* name, const H5A_info_t*, void* out) -> herr_t {
        static_cast<std::vector<std::string>*>(out)->push_back(name);
        return 0;
      },
      &names);
  std::sort(names.begin(), names.end());
  return names;
}

std::vector<hsize_t> dataset_shape(hid_t file, const std::string& path) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  std::vector<hsize_t> dims(H5Sget_simple_extent_ndims(space));
  H5Sget_simple_extent_dims(space, dims.data(), nullptr);
  H5Sclose(space);
  H5Dclose(set);
  return dims;
}

template <typename T>
std::vector<T> read_dataset(hid_t file, const std::string& path, hid_t memory_type) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return {};
  const hid_t space = H5Dget_space(set);
  std::vector<T> data(H5Sget_simple_extent_npoints(space));
  if (!data.empty()) H5Dread(set, memory_type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data());
  H5Sclose(space);
  H5Dclose(set);
  return data;
}

std::string dataset_attribute(hid_t file, const std::string& path, const char* name) {
  const hid_t set = H5Dopen2(file, path.c_str(), H5P_DEFAULT);
  if (set < 0) return "<missing dataset>";
  std::string value = read_string_attribute(set, name);
  H5Dclose(set);
  return value;
}

// ---- the small real run (hdf5_test_support.hpp) written and read back ------------------------------

TEST(RunFile, RoundTripWithProvenance) {
  const TempDir dir("h5_roundtrip");
  const auto& [config, rec] = small_run();
  const std::string path = (dir.path / "run.h5").string();
  const Provenance provenance{"slidewave run config.json -o run.h5", kSmallRunInput};
  ASSERT_NO_THROW(write_run_file(path, config, rec, provenance));
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"run.h5", "run.interface.xdmf", "run.xdmf"}))
      << "no temporary left";

  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  // Provenance and run attributes.
  EXPECT_EQ(read_number_attribute<long long>(file, "format_version"), 2);
  EXPECT_EQ(read_string_attribute(file, "creator"), "slidewave");
  EXPECT_EQ(read_string_attribute(file, "slidewave_version"), kVersion);
  const std::string commit = read_string_attribute(file, "git_commit");
  EXPECT_EQ(commit, kGitCommit);
  EXPECT_TRUE(std::regex_match(commit, std::regex("([0-9a-f]{12}(-dirty)?)|unknown"))) << commit;
  EXPECT_EQ(read_string_attribute(file, "call"), provenance.call);
  EXPECT_TRUE(
      std::regex_match(read_string_attribute(file, "created_utc"), std::regex(R"(\d{4}-\d\d-\d\dT\d\d:\d\d:\d\dZ)")));
  const auto resolved = nlohmann::json::parse(read_string_attribute(file, "config"));
  EXPECT_EQ(resolved, config.to_json());
  EXPECT_EQ(parse_run_config(resolved).to_json(), config.to_json()) << "the resolved config reruns the run";
  EXPECT_EQ(read_number_attribute<long long>(file, "complete"), 1);
  EXPECT_EQ(read_string_attribute(file, "end_reason"), "t_end");
  EXPECT_EQ(read_number_attribute<long long>(file, "n_steps_done"), rec.n_steps_done);
  EXPECT_EQ(read_number_attribute<double>(file, "t_first_opening"), rec.t_first_opening);
  // /setup: the verbatim input and every derived constant, as attributes (format 2: not at the root).
  const hid_t setup = H5Gopen2(file, "setup", H5P_DEFAULT);
  ASSERT_GE(setup, 0);
  EXPECT_EQ(read_string_attribute(setup, "config_input"), kSmallRunInput) << "verbatim input";
  const DerivedConstants d = config.derived();
  const struct {
    const char* name;
    double value;
  } numbers[] = {{"E", config.material.E},
                 {"nu", config.material.nu},
                 {"rho", config.material.rho},
                 {"H", d.H},
                 {"lambda", d.lambda},
                 {"h", d.h},
                 {"f", config.friction.f},
                 {"c_s", d.c_s},
                 {"c_l", d.c_l},
                 {"p0", d.p0},
                 {"V0", d.V0},
                 {"dt", d.dt},
                 {"t_end", config.time.t_end},
                 {"hht_alpha", config.time.hht_alpha},
                 {"t_onset_estimate", d.t_onset_estimate},
                 {"u_x_preshear", rec.u_x_preshear},
                 {"opening_threshold", opening_threshold(config)}};
  std::vector<std::string> setup_names{"config_input"};
  for (const auto& n : numbers) {
    EXPECT_EQ(read_number_attribute<double>(setup, n.name), n.value) << n.name;
    setup_names.push_back(n.name);
  }
  std::sort(setup_names.begin(), setup_names.end());
  EXPECT_EQ(attribute_names(setup), setup_names);
  const std::vector<std::string> root_names{
      "call",           "complete",   "config",       "created_utc", "creator",           "end_reason",
      "format_version", "git_commit", "n_steps_done", "run_id",      "slidewave_version", "t_first_opening"};
  EXPECT_EQ(attribute_names(file), root_names) << "the root keeps provenance and outcome only";
  EXPECT_EQ(rec.opening_threshold, opening_threshold(config)) << "the threshold the loop used";
  EXPECT_EQ(read_number_attribute<double>(setup, "opening_threshold"), 1e-2 * 0.001 * 25.0);
  H5Gclose(setup);

  // Interface series: (n_out, n_c), values bit for bit.
  const hsize_t n_out = rec.interface.t.size(), n_c = rec.interface.x.size();
  EXPECT_EQ(n_c, 8u);
  EXPECT_EQ(n_out, static_cast<hsize_t>(rec.n_steps_done / 3 + 1));
  EXPECT_EQ(dataset_shape(file, "/interface/x"), std::vector<hsize_t>{n_c});
  EXPECT_EQ(dataset_shape(file, "/interface/t"), std::vector<hsize_t>{n_out});
  const std::pair<const char*, const Series2D<double>*> interface_fields[] = {
      {"slip_velocity", &rec.interface.slip_velocity},
      {"slip", &rec.interface.slip},
      {"opening", &rec.interface.opening},
      {"normal_traction", &rec.interface.normal_traction},
      {"tangential_traction", &rec.interface.tangential_traction}};
  for (const auto& [name, series] : interface_fields) {
    const std::string p = std::string("/interface/") + name;
    EXPECT_EQ(dataset_shape(file, p), (std::vector<hsize_t>{n_out, n_c})) << p;
    EXPECT_EQ(read_dataset<double>(file, p, H5T_NATIVE_DOUBLE), series->data) << p;
  }
  EXPECT_EQ(dataset_shape(file, "/interface/state"), (std::vector<hsize_t>{n_out, n_c}));
  EXPECT_EQ(read_dataset<std::int8_t>(file, "/interface/state", H5T_NATIVE_INT8), rec.interface.state.data);
  EXPECT_EQ(read_dataset<double>(file, "/interface/t", H5T_NATIVE_DOUBLE), rec.interface.t);

  // Global series: every step from t = 0.
  const hsize_t n_steps = rec.global.t.size();
  EXPECT_EQ(n_steps, static_cast<hsize_t>(rec.n_steps_done + 1));
  const std::pair<const char*, const std::vector<double>*> global_fields[] = {
      {"t", &rec.global.t},
      {"T", &rec.global.T},
      {"N", &rec.global.N},
      {"T_over_N", &rec.global.T_over_N},
      {"energy_kinetic", &rec.global.energy_kinetic},
      {"energy_elastic", &rec.global.energy_elastic},
      {"work_external", &rec.global.work_external},
      {"dissipation_friction", &rec.global.dissipation_friction},
      {"work_contact_normal", &rec.global.work_contact_normal},
      {"energy_balance_residual", &rec.global.energy_balance_residual},
      {"contact_residual", &rec.global.contact_residual}};
  for (const auto& [name, values] : global_fields) {
    const std::string p = std::string("/global/") + name;
    EXPECT_EQ(dataset_shape(file, p), std::vector<hsize_t>{n_steps}) << p;
    EXPECT_EQ(read_dataset<double>(file, p, H5T_NATIVE_DOUBLE), *values) << p;
  }
  EXPECT_EQ(read_dataset<int>(file, "/global/contact_iterations", H5T_NATIVE_INT), rec.global.contact_iterations);

  // Snapshots: unwrapped mesh (n_x + 1) x (n_y + 1) nodes, one group per requested time.
  const hsize_t n_nodes_full = (8 + 1) * (4 + 1);
  ASSERT_EQ(rec.snapshots.size(), 2u);
  EXPECT_EQ(dataset_shape(file, "/snapshots/coordinates"), (std::vector<hsize_t>{n_nodes_full, 2}));
  EXPECT_EQ(dataset_shape(file, "/snapshots/connectivity"), (std::vector<hsize_t>{8 * 4, 4}));
  for (int s = 0; s < 2; ++s) {
    char id[12];  // any int: -Wformat-truncation
    std::snprintf(id, sizeof id, "%04d", s);
    for (const char* field : {"displacement", "velocity"}) {
      const std::string p = std::string("/snapshots/") + id + "/" + field;
      EXPECT_EQ(dataset_shape(file, p), (std::vector<hsize_t>{n_nodes_full, 2})) << p;
    }
    EXPECT_EQ(read_dataset<double>(file, std::string("/snapshots/") + id + "/displacement", H5T_NATIVE_DOUBLE),
              rec.snapshots[s].displacement);
    const hid_t group = H5Gopen2(file, (std::string("/snapshots/") + id).c_str(), H5P_DEFAULT);
    EXPECT_EQ(read_number_attribute<double>(group, "t"), rec.snapshots[s].t);
    H5Gclose(group);
  }

  // Every dataset carries unit and description.
  const std::vector<std::string> datasets = dataset_names(file);
  EXPECT_GE(datasets.size(), 8u + 12u + 2u + 4u);
  for (const auto& p : datasets) {
    const std::string unit = dataset_attribute(file, p, "unit"),
                      description = dataset_attribute(file, p, "description");
    EXPECT_FALSE(unit.empty() || unit[0] == '<') << p << " unit: " << unit;
    EXPECT_FALSE(description.empty() || description[0] == '<') << p << " description: " << description;
  }
  EXPECT_EQ(dataset_attribute(file, "/interface/slip_velocity", "unit"), "m/s");
  EXPECT_EQ(dataset_attribute(file, "/interface/normal_traction", "unit"), "Pa");
  EXPECT_EQ(dataset_attribute(file, "/global/T", "unit"), "N/m");
  H5Fclose(file);

  // XDMF sidecar points into the file by its base name.
  std::ifstream xdmf(dir.path / "run.xdmf");
  std::stringstream text;
  text << xdmf.rdbuf();
  EXPECT_NE(text.str().find("run.h5:/snapshots/0001/displacement"), std::string::npos);
  std::ifstream interface_xdmf(dir.path / "run.interface.xdmf");
  std::stringstream interface_text;
  interface_text << interface_xdmf.rdbuf();
  EXPECT_NE(interface_text.str().find("run.h5:/interface/slip_velocity"), std::string::npos);
}

TEST(RunFile, IncompleteRunIsMarked) {
  const TempDir dir("h5_incomplete");
  RunRecord rec = small_run().record;
  rec.complete = false;
  rec.end_reason = "contact_not_converged";
  const std::string path = (dir.path / "run.h5").string();
  write_run_file(path, small_run().config, rec, {"call", "{}"});
  const hid_t file = H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT);
  ASSERT_GE(file, 0);
  EXPECT_EQ(read_number_attribute<long long>(file, "complete"), 0);
  EXPECT_EQ(read_string_attribute(file, "end_reason"), "contact_not_converged");
  H5Fclose(file);
}

TEST(RunFile, UnwritableDirectoryThrowsAndLeavesNothing) {
  const TempDir dir("h5_unwritable");
  const fs::path path = dir.path / "no_such_directory" / "run.h5";
  EXPECT_THROW(write_run_file(path.string(), small_run().config, small_run().record, {"call", "{}"}),
               std::runtime_error);
  EXPECT_TRUE(dir.entries().empty());
}

// The final rename fails (the target is a directory): the temporary is removed and nothing that
// looks like output appears, without snapshots and with them (the XDMF sidecar).
TEST(RunFile, FailedRenameLeavesNothing) {
  for (bool with_snapshots : {false, true}) {
    const TempDir dir("h5_rename");
    fs::create_directories(dir.path / "run.h5");  // a directory where the file should go
    RunRecord rec = small_run().record;
    if (!with_snapshots) rec.snapshots.clear();
    EXPECT_THROW(write_run_file((dir.path / "run.h5").string(), small_run().config, rec, {"call", "{}"}),
                 std::runtime_error);
    EXPECT_EQ(dir.entries(), std::vector<std::string>{"run.h5"}) << "with_snapshots = " << with_snapshots;
    EXPECT_TRUE(fs::is_directory(dir.path / "run.h5"));
  }
}

TEST(RunFile, XdmfPath) {
  EXPECT_EQ(xdmf_path_for("out/run.h5"), "out/run.xdmf");
  EXPECT_EQ(xdmf_path_for("run"), "run.xdmf");
  EXPECT_EQ(xdmf_path_for("a.b/run"), "a.b/run.xdmf");
  EXPECT_EQ(interface_xdmf_path_for("out/run.h5"), "out/run.interface.xdmf");
  EXPECT_EQ(interface_xdmf_path_for("a.b/run"), "a.b/run.interface.xdmf");
}

}  // namespace
}  // namespace slidewave

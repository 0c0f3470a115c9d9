#include "io/run_file.hpp"

#include <hdf5.h>
#include <unistd.h>

#include <cstdio>
#include <ctime>
#include <stdexcept>
#include <vector>

#include "git_version.hpp"
#include "io/xdmf.hpp"

namespace slidewave {
namespace {

void check(herr_t status, const std::string& what) {
  if (status < 0) throw std::runtime_error("HDF5: " + what + " failed");
}
hid_t check_id(hid_t id, const std::string& what) {
  if (id < 0) throw std::runtime_error("HDF5: " + what + " failed");
  return id;
}

void attribute_string(hid_t object, const std::string& name, const std::string& value) {
  const hid_t type = check_id(H5Tcopy(H5T_C_S1), "string type");
  check(H5Tset_size(type, value.empty() ? 1 : value.size()), "string size");
  check(H5Tset_cset(type, H5T_CSET_UTF8), "string charset");
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = check_id(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), name);
  check(H5Awrite(attr, type, value.empty() ? "" : value.c_str()), name);
  H5Aclose(attr);
  H5Sclose(space);
  H5Tclose(type);
}

template <typename T>
void attribute_number(hid_t object, const std::string& name, T value) {
  const hid_t type = std::is_integral<T>::value ? H5T_NATIVE_LLONG : H5T_NATIVE_DOUBLE;
  const hid_t space = H5Screate(H5S_SCALAR);
  const hid_t attr = check_id(H5Acreate2(object, name.c_str(), type, space, H5P_DEFAULT, H5P_DEFAULT), name);
  if constexpr (std::is_integral<T>::value) {
    const long long v = value;
    check(H5Awrite(attr, type, &v), name);
  } else {
    const double v = value;
    check(H5Awrite(attr, type, &v), name);
  }
  H5Aclose(attr);
  H5Sclose(space);
}

template <typename T>
hid_t native_type() {
  if constexpr (std::is_same<T, double>::value) return H5T_NATIVE_DOUBLE;
  if constexpr (std::is_same<T, std::int8_t>::value) return H5T_NATIVE_INT8;
  if constexpr (std::is_same<T, int>::value) return H5T_NATIVE_INT;
  if constexpr (std::is_same<T, std::int64_t>::value) return H5T_NATIVE_INT64;
}

/// Dataset of shape (rows) or (rows x cols), compressed and chunked when 2-D, with unit and description.
template <typename T>
void dataset(hid_t group, const std::string& name, const std::vector<T>& data, hsize_t rows, hsize_t cols,
             const std::string& unit, const std::string& description) {
  const int rank = cols ? 2 : 1;
  const hsize_t dims[2] = {rows, cols};
  const hid_t space = H5Screate_simple(rank, dims, nullptr);
  const hid_t plist = H5Pcreate(H5P_DATASET_CREATE);
  if (rank == 2 && rows > 0 && cols > 0) {
    const hsize_t chunk[2] = {std::min<hsize_t>(rows, 64), cols};
    check(H5Pset_chunk(plist, 2, chunk), name + " chunk");
    check(H5Pset_shuffle(plist), name + " shuffle");
    check(H5Pset_deflate(plist, 4), name + " deflate");
  }
  const hid_t set = check_id(
      H5Dcreate2(group, name.c_str(), native_type<T>(), space, H5P_DEFAULT, plist, H5P_DEFAULT), name);
  if (!data.empty()) check(H5Dwrite(set, native_type<T>(), H5S_ALL, H5S_ALL, H5P_DEFAULT, data.data()), name);
  attribute_string(set, "unit", unit);
  attribute_string(set, "description", description);
  H5Dclose(set);
  H5Pclose(plist);
  H5Sclose(space);
}

template <typename T>
void series(hid_t group, const std::string& name, const Series2D<T>& s, const std::string& unit,
            const std::string& description) {
  dataset(group, name, s.data, s.n_rows(), s.n_cols, unit, description);
}

void vector1(hid_t group, const std::string& name, const std::vector<double>& v, const std::string& unit,
             const std::string& description) {
  dataset(group, name, v, v.size(), 0, unit, description);
}

std::string utc_now() {
  char buffer[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buffer;
}

}  // namespace

void write_run_file(const std::string& path, const RunConfig& config, const RunRecord& rec,
                    const Provenance& provenance) {
  const std::string temporary = path + ".tmp." + std::to_string(::getpid());
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);  // errors become exceptions with our messages
  const hid_t file = H5Fcreate(temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, H5P_DEFAULT);
  if (file < 0) throw std::runtime_error("cannot create " + temporary);
  try {
    const DerivedConstants d = config.derived();
    attribute_number(file, "format_version", kRunFormatVersion);
    attribute_string(file, "creator", "slidewave");
    attribute_string(file, "slidewave_version", kVersion);
    attribute_string(file, "git_commit", kGitCommit);
    attribute_string(file, "call", provenance.call);
    attribute_string(file, "created_utc", utc_now());
    attribute_string(file, "config", config.to_json().dump());
    attribute_number(file, "complete", rec.complete ? 1 : 0);
    attribute_string(file, "end_reason", rec.end_reason);
    attribute_number(file, "n_steps_done", rec.n_steps_done);
    attribute_number(file, "t_first_opening", rec.t_first_opening);
    attribute_number(file, "u_x_preshear", rec.u_x_preshear);
    attribute_number(file, "E", config.material.E);
    attribute_number(file, "nu", config.material.nu);
    attribute_number(file, "rho", config.material.rho);
    attribute_number(file, "H", d.H);
    attribute_number(file, "lambda", d.lambda);
    attribute_number(file, "h", d.h);
    attribute_number(file, "f", config.friction.f);
    attribute_number(file, "c_s", d.c_s);
    attribute_number(file, "c_l", d.c_l);
    attribute_number(file, "p0", d.p0);
    attribute_number(file, "V0", d.V0);
    attribute_number(file, "dt", d.dt);
    attribute_number(file, "t_end", config.time.t_end);
    attribute_number(file, "hht_alpha", config.time.hht_alpha);
    attribute_number(file, "t_onset_estimate", d.t_onset_estimate);

    const hid_t setup = H5Gcreate2(file, "setup", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT);
    attribute_string(setup, "config_input", provenance.config_input);
    H5Gclose(setup);

    const auto& s = rec.interface;
    const hid_t gi = check_id(H5Gcreate2(file, "interface", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "interface");
    vector1(gi, "x", s.x, "m", "position of the contact nodes (x = lambda is x = 0)");
    vector1(gi, "t", s.t, "s", "output times, stage-3 clock");
    series(gi, "slip_velocity", s.slip_velocity, "m/s", "du_x/dt over the step ending at t (contact nodes)");
    series(gi, "slip", s.slip, "m", "u_x of the contact nodes relative to t = 0");
    series(gi, "opening", s.opening, "m", "u_y of the contact nodes (gap to the rigid flat)");
    series(gi, "normal_traction", s.normal_traction, "Pa", "contact pressure, compression positive (R_n/h)");
    series(gi, "tangential_traction", s.tangential_traction, "Pa",
           "frictional traction, positive when resisting sliding in +x (-R_t/h)");
    series(gi, "state", s.state, "1", "0 open, 1 stick, 2 slip");
    H5Gclose(gi);

    const auto& g = rec.global;
    const hid_t gg = check_id(H5Gcreate2(file, "global", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "global");
    vector1(gg, "t", g.t, "s", "time of every step, stage-3 clock");
    vector1(gg, "T", g.T, "N/m", "tangential force on the interface, -sum R_t, per unit depth");
    vector1(gg, "N", g.N, "N/m", "normal force on the interface, sum R_n, per unit depth");
    vector1(gg, "T_over_N", g.T_over_N, "1", "apparent friction T/N");
    vector1(gg, "energy_kinetic", g.energy_kinetic, "J/m", "kinetic energy 1/2 v.M v");
    vector1(gg, "energy_elastic", g.energy_elastic, "J/m", "elastic energy 1/2 u.K u (includes the preload)");
    vector1(gg, "work_external", g.work_external, "J/m", "work of the imposed top displacement since t = 0");
    vector1(gg, "dissipation_friction", g.dissipation_friction, "J/m",
            "frictional dissipation -sum 1/2 (R_t(n)+R_t(n+1)) du_x since t = 0");
    vector1(gg, "work_contact_normal", g.work_contact_normal, "J/m",
            "energy lost by the normal contact forces, -sum 1/2 (R_n(n)+R_n(n+1)) du_y");
    vector1(gg, "energy_balance_residual", g.energy_balance_residual, "J/m",
            "E_kin + E_el + D_fric + W_normal - E(0) - W_ext (HHT dissipation for alpha > 0)");
    vector1(gg, "contact_residual", g.contact_residual, "1", "last sweep's max reaction change / (p0 h)");
    dataset(gg, "contact_iterations", g.contact_iterations, g.contact_iterations.size(), 0, "1",
            "Gauss-Seidel sweeps of the step");
    H5Gclose(gg);

    if (!rec.snapshots.empty()) {
      const hid_t gs = check_id(H5Gcreate2(file, "snapshots", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), "snapshots");
      const hsize_t n_nodes = rec.snapshot_mesh.coordinates.size() / 2;
      dataset(gs, "coordinates", rec.snapshot_mesh.coordinates, n_nodes, 2, "m",
              "node coordinates of the unwrapped mesh (the column x = lambda repeats x = 0)");
      dataset(gs, "connectivity", rec.snapshot_mesh.connectivity, rec.snapshot_mesh.connectivity.size() / 4, 4,
              "1", "quadrilateral nodes, counter-clockwise");
      for (size_t k = 0; k < rec.snapshots.size(); ++k) {
        char id[32];
        std::snprintf(id, sizeof id, "%04zu", k);
        const hid_t one = check_id(H5Gcreate2(gs, id, H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), id);
        attribute_number(one, "t", rec.snapshots[k].t);
        dataset(one, "displacement", rec.snapshots[k].displacement, n_nodes, 2, "m", "nodal displacement");
        dataset(one, "velocity", rec.snapshots[k].velocity, n_nodes, 2, "m/s", "nodal velocity");
        H5Gclose(one);
      }
      H5Gclose(gs);
    }
    check(H5Fclose(file), "close");
  } catch (...) {
    H5Fclose(file);
    std::remove(temporary.c_str());
    throw;
  }
  // The sidecars go into place only after run.h5 did, so they never point at a missing file.
  try {
    stage_xdmf_sidecars(path, rec);
  } catch (...) {
    std::remove(temporary.c_str());
    throw;
  }
  if (std::rename(temporary.c_str(), path.c_str()) != 0) {
    std::remove(temporary.c_str());
    discard_xdmf_sidecars(path);
    throw std::runtime_error("cannot rename " + temporary + " to " + path);
  }
  publish_xdmf_sidecars(path, rec);
}

}  // namespace slidewave

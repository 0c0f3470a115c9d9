#include "io/run_attributes.hpp"

#include <ctime>

#include "git_version.hpp"
#include "io/hdf5_support.hpp"
#include "model/substrate.hpp"

namespace slidewave {
namespace {

std::string utc_now() {
  char buffer[32];
  const std::time_t now = std::time(nullptr);
  std::strftime(buffer, sizeof buffer, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&now));
  return buffer;
}

}  // namespace

void write_run_header(hid_t file, const std::string& path, const RunConfig& config, const Provenance& provenance) {
  using namespace h5;
  const DerivedConstants d = config.derived();
  write_int_attribute(file, "format_version", run_format_version(config), path);
  write_string_attribute(file, "creator", "slidewave", path);
  write_string_attribute(file, "slidewave_version", kVersion, path);
  write_string_attribute(file, "git_commit", kGitCommit, path);
  write_string_attribute(file, "call", provenance.call, path);
  write_string_attribute(file, "run_id", provenance.run_id, path);
  write_string_attribute(file, "created_utc", utc_now(), path);
  write_string_attribute(file, "config", config.to_json().dump(), path);
  const Handle setup = group_create(file, "setup", path, large_attribute_properties(H5P_GROUP_CREATE));
  write_string_attribute(setup, "config_input", provenance.config_input, path);
  const struct {
    const char* name;
    double value;
  } constants[] = {{"E", config.material.E},
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
                   {"t_onset_estimate", d.t_onset_estimate}};
  for (const auto& c : constants) write_double_attribute(setup, c.name, c.value, path);
  if (config.substrate.present()) {  // format 3 (docs/substrate.md)
    const RunConfig body = substrate_body_config(config);
    const DerivedConstants ds = body.derived();
    const struct {
      const char* name;
      double value;
    } substrate[] = {{"substrate_E", body.material.E},
                     {"substrate_nu", body.material.nu},
                     {"substrate_rho", body.material.rho},
                     {"substrate_H", ds.H},
                     {"substrate_c_s", ds.c_s},
                     {"substrate_c_l", ds.c_l},
                     {"substrate_return_time", 2 * ds.H / ds.c_l}};
    for (const auto& c : substrate) write_double_attribute(setup, c.name, c.value, path);
  }
}

void write_run_outcome(hid_t file, const std::string& path, const RunRecord& record) {
  using namespace h5;
  replace_int_attribute(file, "complete", record.complete ? 1 : 0, path);
  replace_string_attribute(file, "end_reason", record.end_reason, path);
  replace_int_attribute(file, "n_steps_done", record.n_steps_done, path);
  replace_double_attribute(file, "t_first_opening", record.t_first_opening, path);
  const Handle setup = group_open(file, "setup", path);
  replace_double_attribute(setup, "u_x_preshear", record.u_x_preshear, path);
  replace_double_attribute(setup, "opening_threshold", record.opening_threshold, path);
}

}  // namespace slidewave

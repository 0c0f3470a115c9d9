#include "config/run_config.hpp"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

#include "config/config_keys.hpp"
#include "config/strict_json.hpp"

namespace slidewave {
namespace {

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

std::string join(const std::vector<std::string>& items) {
  std::string out;
  for (const auto& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

/// Unknown groups, groups that are not objects and unknown keys, each a problem line.
void check_names(const nlohmann::json& input, std::vector<std::string>& problems) {
  const auto& groups = config_groups();
  for (const auto& [group, node] : input.items()) {
    if (std::find(groups.begin(), groups.end(), group) == groups.end()) {
      problems.push_back(excerpt(group) + ": unknown group; allowed " + join(groups));
      continue;
    }
    if (!node.is_object()) {
      problems.push_back(group + ": must be an object");
      continue;
    }
    std::vector<std::string> names;
    for (const auto& k : config_keys())
      if (k.group == group) names.push_back(k.name);
    for (const auto& [name, _] : node.items())
      if (std::find(names.begin(), names.end(), name) == names.end())
        problems.push_back(group + "." + excerpt(name) + ": unknown key; allowed " + join(names));
  }
}

std::string short_number(double x) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.4g", x);
  return buffer;
}

}  // namespace

ConfigError::ConfigError(const std::vector<std::string>& list)
    : std::runtime_error("invalid configuration:\n" + join_lines(list)), problems(list) {}

RunConfig parse_run_config(const nlohmann::json& input) {
  if (!input.is_object()) throw ConfigError({"configuration: the top level must be a JSON object"});
  std::vector<std::string> problems;
  check_names(input, problems);
  RunConfig c;
  for (const auto& key : config_keys()) {
    if (!input.contains(key.group) || !input.at(key.group).is_object()) continue;
    const auto& group = input.at(key.group);
    if (!group.contains(key.name)) continue;
    const std::string problem = key.problem(group.at(key.name));
    if (problem.empty())
      key.set(c, group.at(key.name));
    else
      problems.push_back(problem);
  }

  // Cross-key rules: the period must hold a whole number of elements, at least 3 (periodic ties).
  const double n_x = c.geometry.lambda_over_H * c.mesh.elements_per_H;
  if (std::fabs(n_x - std::round(n_x)) > 1e-9 * n_x || std::round(n_x) < 3 || n_x > std::numeric_limits<int>::max())
    problems.push_back("geometry.lambda_over_H: " + std::to_string(c.geometry.lambda_over_H) +
                       " times mesh.elements_per_H must be an integer >= 3");
  // The substrate: all four keys or none; its thickness a whole number of the layer's elements.
  const SubstrateConfig& s = c.substrate;
  const std::pair<const char*, bool> given[] = {
      {"E", s.E.has_value()}, {"nu", s.nu.has_value()}, {"rho", s.rho.has_value()}, {"H", s.H.has_value()}};
  int n_given = 0;
  for (const auto& g : given) n_given += g.second;
  if (n_given > 0 && n_given < 4) {
    for (const auto& g : given)
      if (!g.second)
        for (const auto& key : config_keys())
          if (key.group == "substrate" && key.name == g.first)
            problems.push_back(key.path() +
                               ": missing; the substrate needs E, nu, rho and H together (or none "
                               "of them: the rigid flat); allowed " +
                               key.allowed().substr(8));  // not "null or "
  } else if (n_given == 4 && problems.empty()) {
    const double n_y = *s.H * c.mesh.elements_per_H / c.geometry.H;
    if (std::fabs(n_y - std::round(n_y)) > 1e-9 * n_y || std::round(n_y) < 2 || std::round(n_y) > 65536)
      problems.push_back("substrate.H: " + short_number(*s.H) + " m is " + short_number(n_y) +
                         " elements of size h = geometry.H / mesh.elements_per_H = " +
                         short_number(c.geometry.H / c.mesh.elements_per_H) +
                         " m; allowed a whole number of elements in [2, 65536]");
  }
  // The single-mode seed: its wavelength at least four elements; `mode` or `start`
  // without an amplitude is a mistake.
  if (input.contains("mode_seed") && input.at("mode_seed").is_object()) {
    for (const char* name : {"mode", "start"})
      if (!c.mode_seed.present() && input.at("mode_seed").contains(name))
        problems.push_back(std::string("mode_seed.amplitude_over_H: missing; `mode_seed.") + name +
                           "` needs it; allowed 0 < amplitude_over_H <= 0.01");
    if (problems.empty() && c.mode_seed.present() && 4LL * c.mode_seed.mode > std::lround(n_x))
      problems.push_back("mode_seed.mode: " + std::to_string(c.mode_seed.mode) + " wavelengths in a period of " +
                         std::to_string(std::lround(n_x)) + " elements; allowed an integer in [1, " +
                         std::to_string(std::lround(n_x) / 4) + "] (four elements a wavelength)");
  }
  // The step count, once every value it depends on is valid (a count from a rejected value would mislead).
  if (problems.empty()) {
    const DerivedConstants d = c.derived();
    if (!(d.n_steps <= static_cast<double>(c.time.max_steps)))
      problems.push_back("time.max_steps: t_end = " + short_number(c.time.t_end) + " s at dt = " + short_number(d.dt) +
                         " s is " + short_number(d.n_steps) +
                         " steps, over time.max_steps = " + std::to_string(c.time.max_steps) +
                         "; shorten time.t_end, enlarge the time step or raise time.max_steps");
  }
  if (!problems.empty()) throw ConfigError(problems);
  return c;
}

std::string read_config_bytes(const std::string& path) {
  std::FILE* file = std::fopen(path.c_str(), "rb");
  if (!file) throw ConfigError({path + ": cannot open the configuration file: " + std::strerror(errno)});
  std::string bytes;
  char buffer[65536];
  size_t n;
  while ((n = std::fread(buffer, 1, sizeof buffer, file)) > 0) bytes.append(buffer, n);
  const int error = std::ferror(file) ? errno : 0;
  std::fclose(file);
  if (error) throw ConfigError({path + ": cannot read the configuration file: " + std::strerror(error)});
  return bytes;
}

RunConfig parse_run_config_text(const std::string& text, const std::string& origin, const nlohmann::json& overrides) {
  nlohmann::json j = parse_strict_json(text, origin);
  if (j.is_object()) j.merge_patch(overrides);
  return parse_run_config(j);
}

RunConfig load_run_config(const std::string& path) { return parse_run_config_text(read_config_bytes(path), path); }

DerivedConstants RunConfig::derived() const {
  DerivedConstants d{};
  const double E = material.E, nu = material.nu, rho = material.rho;
  d.G = E / (2 * (1 + nu));
  d.lame_lambda = E * nu / ((1 + nu) * (1 - 2 * nu));
  d.c_s = std::sqrt(d.G / rho);
  d.c_l = std::sqrt((d.lame_lambda + 2 * d.G) / rho);
  d.H = geometry.H;
  d.n_y = mesh.elements_per_H;
  d.n_x = static_cast<int>(std::lround(geometry.lambda_over_H * mesh.elements_per_H));
  d.h = d.H / d.n_y;
  d.lambda = d.n_x * d.h;
  d.p0 = -loading.Uy_over_H * (d.lame_lambda + 2 * d.G);
  d.V0 = loading.V0_over_cs * d.c_s;
  d.dt = time.dt ? *time.dt : time.dt_times_cs / d.c_s;
  // Uniform stick state: tau = G u_top / H, so T/N grows by (1 - ratio) f over du = (1-ratio) f p0 H / G.
  d.t_onset_estimate = (1 - loading.preshear_ratio) * friction.f * d.p0 * d.H / (d.G * d.V0);
  if (substrate.present()) {
    // Both bodies in series under the same uniaxial strain state: the top's Uy H compresses the layer by
    // H / M and the substrate by H_s / M_s per unit pressure (M the P-wave modulus), and the shear traction
    // strains both, so the top moves H / G + H_s / G_s per unit traction (docs/substrate.md).
    const double E_s = *substrate.E, nu_s = *substrate.nu, H_s = *substrate.H;
    const double M = d.lame_lambda + 2 * d.G, M_s = E_s * (1 - nu_s) / ((1 + nu_s) * (1 - 2 * nu_s));
    d.p0 = -loading.Uy_over_H * d.H / (d.H / M + H_s / M_s);
    const double shear_compliance = d.H / d.G + H_s / (E_s / (2 * (1 + nu_s)));
    d.t_onset_estimate = (1 - loading.preshear_ratio) * friction.f * d.p0 * shear_compliance / d.V0;
  }
  d.n_steps = std::ceil(time.t_end / d.dt - 1e-9);
  return d;
}

nlohmann::json RunConfig::to_json() const {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& key : config_keys()) {
    // No substrate (the rigid flat): the group is left out, so that such a run's resolved configuration is
    // what it was before the group existed.
    if (key.group == "substrate" && !substrate.present()) continue;
    if (key.group == "mode_seed" && !mode_seed.present()) continue;  // likewise: no mode seed
    j[key.group][key.name] = key.get(*this);
  }
  return j;
}

int substrate_rows(const RunConfig& c) {
  return static_cast<int>(std::lround(*c.substrate.H * c.mesh.elements_per_H / c.geometry.H));
}

}  // namespace slidewave

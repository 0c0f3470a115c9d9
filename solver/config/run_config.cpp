#include "config/run_config.hpp"

#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace slidewave {
namespace {

std::string join_lines(const std::vector<std::string>& lines) {
  std::string out;
  for (const auto& l : lines) out += l + "\n";
  return out;
}

/// Reads one JSON group, records every problem instead of stopping at the first.
class GroupReader {
 public:
  GroupReader(const nlohmann::json& root, const std::string& group, std::vector<std::string>& problems)
      : group_(group), problems_(problems) {
    if (!root.contains(group)) return;
    if (!root.at(group).is_object()) {
      problems_.push_back(group + ": must be an object");
      return;
    }
    node_ = &root.at(group);
  }

  /// Number in [lo, hi] (bounds inclusive unless the *_open flags say otherwise).
  void number(const std::string& key, double& value, double lo, double hi, bool lo_open, bool hi_open,
              const std::string& allowed) {
    seen_.push_back(key);
    if (!node_ || !node_->contains(key)) return;
    const auto& v = node_->at(key);
    if (!v.is_number()) {
      problems_.push_back(name(key) + ": " + v.dump() + " is not a number; allowed " + allowed);
      return;
    }
    const double x = v.get<double>();
    const bool ok = std::isfinite(x) && (lo_open ? x > lo : x >= lo) && (hi_open ? x < hi : x <= hi);
    if (!ok) {
      problems_.push_back(name(key) + ": " + v.dump() + " out of range; allowed " + allowed);
      return;
    }
    value = x;
  }

  void optional_number(const std::string& key, std::optional<double>& value, const std::string& allowed) {
    seen_.push_back(key);
    if (!node_ || !node_->contains(key) || node_->at(key).is_null()) return;
    const auto& v = node_->at(key);
    if (!v.is_number() || !(v.get<double>() > 0) || !std::isfinite(v.get<double>())) {
      problems_.push_back(name(key) + ": " + v.dump() + " invalid; allowed " + allowed);
      return;
    }
    value = v.get<double>();
  }

  template <typename Int>
  void integer(const std::string& key, Int& value, long long lo, long long hi, const std::string& allowed) {
    seen_.push_back(key);
    if (!node_ || !node_->contains(key)) return;
    const auto& v = node_->at(key);
    const bool integral = v.is_number_integer() ||
                          (v.is_number_float() && std::floor(v.get<double>()) == v.get<double>());
    if (!integral || v.get<double>() < lo || v.get<double>() > hi) {
      problems_.push_back(name(key) + ": " + v.dump() + " invalid; allowed " + allowed);
      return;
    }
    value = static_cast<Int>(v.get<long long>());
  }

  template <typename Enum>
  void choice(const std::string& key, Enum& value, const std::map<std::string, Enum>& options) {
    seen_.push_back(key);
    if (!node_ || !node_->contains(key)) return;
    const auto& v = node_->at(key);
    std::string allowed;
    for (const auto& [text, _] : options) allowed += (allowed.empty() ? "" : "|") + text;
    if (!v.is_string() || !options.count(v.get<std::string>())) {
      problems_.push_back(name(key) + ": " + v.dump() + " invalid; allowed " + allowed);
      return;
    }
    value = options.at(v.get<std::string>());
  }

  void number_list(const std::string& key, std::vector<double>& value, const std::string& allowed) {
    seen_.push_back(key);
    if (!node_ || !node_->contains(key)) return;
    const auto& v = node_->at(key);
    bool ok = v.is_array();
    if (ok)
      for (const auto& e : v) ok = ok && e.is_number() && e.get<double>() >= 0 && std::isfinite(e.get<double>());
    if (!ok) {
      problems_.push_back(name(key) + ": " + v.dump() + " invalid; allowed " + allowed);
      return;
    }
    value = v.get<std::vector<double>>();
  }

  /// Call after all keys of the group were read: any other key is an error.
  void reject_unknown() {
    if (!node_) return;
    std::string allowed;
    for (const auto& s : seen_) allowed += (allowed.empty() ? "" : ", ") + s;
    for (const auto& [key, _] : node_->items()) {
      bool known = false;
      for (const auto& s : seen_) known = known || s == key;
      if (!known) problems_.push_back(name(key) + ": unknown key; allowed " + allowed);
    }
  }

 private:
  std::string name(const std::string& key) const { return group_ + "." + key; }
  const nlohmann::json* node_ = nullptr;
  std::string group_;
  std::vector<std::string>& problems_;
  std::vector<std::string> seen_;
};

const std::map<std::string, Integration> kIntegration{
    {"full", Integration::full}, {"reduced", Integration::reduced}, {"reduced_pure", Integration::reduced_pure}};
const std::map<std::string, MassKind> kMass{{"consistent", MassKind::consistent}, {"lumped", MassKind::lumped}};
const std::map<std::string, ContactWeighting> kWeighting{{"alpha", ContactWeighting::alpha},
                                                         {"end", ContactWeighting::end}};
const std::map<std::string, Regularization> kRegularization{{"none", Regularization::none},
                                                            {"prakash_clifton", Regularization::prakash_clifton}};
const std::map<std::string, LinearSolverKind> kLinearSolver{{"circulant", LinearSolverKind::circulant},
                                                             {"cholmod", LinearSolverKind::cholmod}};
const std::map<std::string, ProgressMode> kProgress{
    {"auto", ProgressMode::automatic}, {"always", ProgressMode::always}, {"never", ProgressMode::never}};

template <typename Enum>
std::string name_of(const std::map<std::string, Enum>& options, Enum value) {
  for (const auto& [text, v] : options)
    if (v == value) return text;
  return "?";
}

}  // namespace

ConfigError::ConfigError(const std::vector<std::string>& list)
    : std::runtime_error("invalid configuration:\n" + join_lines(list)), problems(list) {}

RunConfig parse_run_config(const nlohmann::json& input) {
  if (!input.is_object()) throw ConfigError({"configuration: the top level must be a JSON object"});
  std::vector<std::string> problems;
  RunConfig c;
  constexpr double inf = std::numeric_limits<double>::infinity();
  const std::vector<std::string> groups{"material", "geometry", "mesh", "loading", "friction",
                                        "time", "contact", "perturbation", "numerics", "output"};
  for (const auto& [key, _] : input.items()) {
    bool known = false;
    for (const auto& g : groups) known = known || g == key;
    if (!known) problems.push_back(key + ": unknown group; allowed " + "material, geometry, mesh, loading, "
                                   "friction, time, contact, perturbation, numerics, output");
  }

  GroupReader material(input, "material", problems);
  material.number("E", c.material.E, 0, inf, true, true, "E > 0 (Pa)");
  material.number("nu", c.material.nu, 0, 0.5, false, true, "0 <= nu < 0.5");
  material.number("rho", c.material.rho, 0, inf, true, true, "rho > 0 (kg/m^3)");
  material.reject_unknown();

  GroupReader geometry(input, "geometry", problems);
  geometry.number("H", c.geometry.H, 0, inf, true, true, "H > 0 (m)");
  geometry.number("lambda_over_H", c.geometry.lambda_over_H, 0, inf, true, true, "lambda_over_H > 0");
  geometry.reject_unknown();

  GroupReader mesh(input, "mesh", problems);
  mesh.integer("elements_per_H", c.mesh.elements_per_H, 2, 4096, "integer in [2, 4096]");
  mesh.choice("integration", c.mesh.integration, kIntegration);
  mesh.choice("mass", c.mesh.mass, kMass);
  mesh.reject_unknown();

  GroupReader loading(input, "loading", problems);
  loading.number("Uy_over_H", c.loading.Uy_over_H, -0.1, 0, true, true, "-0.1 < Uy_over_H < 0");
  loading.number("preshear_ratio", c.loading.preshear_ratio, 0, 1, false, true, "0 <= preshear_ratio < 1");
  loading.number("V0_over_cs", c.loading.V0_over_cs, 0, 0.1, true, false, "0 < V0_over_cs <= 0.1");
  loading.reject_unknown();

  GroupReader friction(input, "friction", problems);
  friction.number("f", c.friction.f, 0, inf, false, true, "f >= 0");
  friction.choice("regularization", c.friction.regularization, kRegularization);
  friction.number("pc_length", c.friction.pc_length, 0, inf, true, true, "pc_length > 0 (m)");
  friction.number("pc_velocity", c.friction.pc_velocity, 0, inf, false, true, "pc_velocity >= 0 (m/s)");
  friction.reject_unknown();

  GroupReader time(input, "time", problems);
  time.number("dt_times_cs", c.time.dt_times_cs, 0, inf, true, true, "dt_times_cs > 0 (m)");
  time.optional_number("dt", c.time.dt, "null or dt > 0 (s)");
  time.number("t_end", c.time.t_end, 0, inf, true, true, "t_end > 0 (s)");
  time.number("hht_alpha", c.time.hht_alpha, 0, 1.0 / 3.0, false, false, "0 <= hht_alpha <= 1/3");
  time.choice("contact_weighting", c.time.contact_weighting, kWeighting);
  time.optional_number("stop_after_opening", c.time.stop_after_opening, "null or > 0 (s)");
  time.reject_unknown();

  GroupReader contact(input, "contact", problems);
  contact.number("tolerance", c.contact.tolerance, 0, 1e-2, true, false, "0 < tolerance <= 1e-2");
  contact.integer("max_iterations", c.contact.max_iterations, 1, 100000000, "integer >= 1");
  contact.reject_unknown();

  GroupReader perturbation(input, "perturbation", problems);
  perturbation.number("amplitude", c.perturbation.amplitude, 0, inf, false, true, "amplitude >= 0");
  perturbation.integer("seed", c.perturbation.seed, 0, std::numeric_limits<long long>::max(), "integer >= 0");
  perturbation.reject_unknown();

  GroupReader numerics(input, "numerics", problems);
  numerics.choice("linear_solver", c.numerics.linear_solver, kLinearSolver);
  numerics.reject_unknown();

  GroupReader output(input, "output", problems);
  output.integer("interface_stride", c.output.interface_stride, 1, 1000000, "integer >= 1");
  output.number_list("snapshot_times", c.output.snapshot_times, "list of times >= 0 (s)");
  output.choice("progress", c.output.progress, kProgress);
  output.number("checkpoint_interval", c.output.checkpoint_interval, 0, inf, false, true,
                 "checkpoint_interval >= 0 (s of wall time; 0: only at SIGINT/SIGTERM)");
  output.reject_unknown();

  // Cross-key rules: the period must hold a whole number of elements, at least 3 (periodic ties).
  const double n_x = c.geometry.lambda_over_H * c.mesh.elements_per_H;
  if (std::fabs(n_x - std::round(n_x)) > 1e-9 * n_x || std::round(n_x) < 3)
    problems.push_back("geometry.lambda_over_H: " + std::to_string(c.geometry.lambda_over_H) +
                       " times mesh.elements_per_H must be an integer >= 3");
  if (!problems.empty()) throw ConfigError(problems);
  return c;
}

RunConfig load_run_config(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw ConfigError({path + ": cannot open the configuration file"});
  nlohmann::json j;
  try {
    in >> j;
  } catch (const nlohmann::json::parse_error& e) {
    throw ConfigError({path + ": not valid JSON: " + e.what()});
  }
  return parse_run_config(j);
}

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
  return d;
}

nlohmann::json RunConfig::to_json() const {
  nlohmann::json j;
  j["material"] = {{"E", material.E}, {"nu", material.nu}, {"rho", material.rho}};
  j["geometry"] = {{"H", geometry.H}, {"lambda_over_H", geometry.lambda_over_H}};
  j["mesh"] = {{"elements_per_H", mesh.elements_per_H},
               {"integration", name_of(kIntegration, mesh.integration)},
               {"mass", name_of(kMass, mesh.mass)}};
  j["loading"] = {{"Uy_over_H", loading.Uy_over_H},
                  {"preshear_ratio", loading.preshear_ratio},
                  {"V0_over_cs", loading.V0_over_cs}};
  j["friction"] = {{"f", friction.f},
                   {"regularization", name_of(kRegularization, friction.regularization)},
                   {"pc_length", friction.pc_length},
                   {"pc_velocity", friction.pc_velocity}};
  j["time"] = {{"dt_times_cs", time.dt_times_cs},
               {"dt", time.dt ? nlohmann::json(*time.dt) : nlohmann::json(nullptr)},
               {"t_end", time.t_end},
               {"hht_alpha", time.hht_alpha},
               {"contact_weighting", name_of(kWeighting, time.contact_weighting)},
               {"stop_after_opening", time.stop_after_opening ? nlohmann::json(*time.stop_after_opening)
                                                              : nlohmann::json(nullptr)}};
  j["contact"] = {{"tolerance", contact.tolerance}, {"max_iterations", contact.max_iterations}};
  j["perturbation"] = {{"amplitude", perturbation.amplitude}, {"seed", perturbation.seed}};
  j["numerics"] = {{"linear_solver", name_of(kLinearSolver, numerics.linear_solver)}};
  j["output"] = {{"interface_stride", output.interface_stride},
                 {"snapshot_times", output.snapshot_times},
                 {"progress", name_of(kProgress, output.progress)},
                 {"checkpoint_interval", output.checkpoint_interval}};
  return j;
}

}  // namespace slidewave

#include "config/config_keys.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <type_traits>
#include <utility>

#include "config/run_config.hpp"
#include "config/strict_json.hpp"

namespace slidewave {
namespace {

using nlohmann::json;

Bound open(double value, std::string text = "") { return Bound{value, true, std::move(text)}; }
Bound closed(double value, std::string text = "") { return Bound{value, false, std::move(text)}; }
constexpr std::nullopt_t unbounded = std::nullopt;

// Row factories: `field` is a generic lambda [](auto& c) -> auto& { return c.group.key; }, so that one
// accessor serves reading (const RunConfig) and writing.
template <typename Field>
ConfigKey number(std::string group, std::string name, std::optional<Bound> lower, std::optional<Bound> upper,
                 std::string unit, std::string description, Field field) {
  ConfigKey k{group, name, KeyKind::number, lower, upper, {}, {}, unit, description, {}, {}};
  k.get = [field](const RunConfig& c) { return json(field(c)); };
  k.set = [field](RunConfig& c, const json& v) { field(c) = v.get<double>(); };
  return k;
}

template <typename Field>
ConfigKey optional_number(std::string group, std::string name, std::optional<Bound> lower, std::string unit,
                          std::string description, Field field, std::optional<Bound> upper = unbounded) {
  ConfigKey k{group, name, KeyKind::optional_number, lower, upper, {}, {}, unit, description, {}, {}};
  k.get = [field](const RunConfig& c) { return field(c) ? json(*field(c)) : json(nullptr); };
  k.set = [field](RunConfig& c, const json& v) {
    if (v.is_null())
      field(c).reset();
    else
      field(c) = v.get<double>();
  };
  return k;
}

template <typename Field>
ConfigKey integer(std::string group, std::string name, long long lower, std::optional<long long> upper,
                  std::string description, Field field) {
  ConfigKey k{group, name, KeyKind::integer, closed(static_cast<double>(lower)), unbounded, {}, {}, "", description,
              {},    {}};
  if (upper) k.upper = closed(static_cast<double>(*upper));
  k.get = [field](const RunConfig& c) { return json(field(c)); };
  k.set = [field](RunConfig& c, const json& v) {
    using Int = std::decay_t<decltype(field(c))>;
    field(c) = static_cast<Int>(v.is_number_integer() ? v.get<long long>() : static_cast<long long>(v.get<double>()));
  };
  return k;
}

/// The member type a field accessor addresses (the enum of a `choice`).
template <typename Field>
using MemberOf = std::decay_t<decltype(std::declval<Field>()(std::declval<RunConfig&>()))>;

template <typename Field>
ConfigKey choice(std::string group, std::string name, std::vector<std::pair<std::string, MemberOf<Field>>> options,
                 std::string description, Field field, std::vector<std::pair<std::string, std::string>> retired = {}) {
  ConfigKey k{group, name, KeyKind::choice, unbounded, unbounded, {}, std::move(retired), "", description, {}, {}};
  for (const auto& option : options) k.choices.push_back(option.first);
  k.get = [field, options](const RunConfig& c) {
    for (const auto& [text, value] : options)
      if (value == field(c)) return json(text);
    return json(nullptr);  // unreachable: every enumerator has a name
  };
  k.set = [field, options](RunConfig& c, const json& v) {
    for (const auto& [text, value] : options)
      if (text == v.get<std::string>()) field(c) = value;
  };
  return k;
}

template <typename Field>
ConfigKey number_list(std::string group, std::string name, std::optional<Bound> lower, std::string unit,
                      std::string description, Field field) {
  ConfigKey k{group, name, KeyKind::number_list, lower, unbounded, {}, {}, unit, description, {}, {}};
  k.get = [field](const RunConfig& c) { return json(field(c)); };
  k.set = [field](RunConfig& c, const json& v) { field(c) = v.get<std::vector<double>>(); };
  return k;
}

std::vector<ConfigKey> make_table() {
  constexpr double kMaxStepsLimit = 1e9;  // keeps every step counter far inside a 32-bit int
  constexpr long long kMaxSeed = (1LL << 53) - 1;
  // The key table as laid out by hand: one key per entry, its accessor on the entry's last line.
  // clang-format off
  return {
      number("material", "E", open(0), unbounded, "Pa", "Young's modulus",
             [](auto& c) -> auto& { return c.material.E; }),
      number("material", "nu", closed(0), open(0.5), "", "Poisson's ratio",
             [](auto& c) -> auto& { return c.material.nu; }),
      number("material", "rho", open(0), unbounded, "kg/m^3", "density",
             [](auto& c) -> auto& { return c.material.rho; }),

      number("geometry", "H", open(0), unbounded, "m", "layer height",
             [](auto& c) -> auto& { return c.geometry.H; }),
      number("geometry", "lambda_over_H", open(0), unbounded, "",
             "period / H; lambda_over_H * elements_per_H must be an integer >= 3",
             [](auto& c) -> auto& { return c.geometry.lambda_over_H; }),

      integer("mesh", "elements_per_H", 2, 4096, "n, the element size is h = H / n",
              [](auto& c) -> auto& { return c.mesh.elements_per_H; }),
      choice("mesh", "integration",
             {{"full", Integration::full}, {"reduced", Integration::reduced},
              {"reduced_pure", Integration::reduced_pure}},
             "`full` (2x2), `reduced` (1 point + ASQBI hourglass stiffness), `reduced_pure` (1 point)",
             [](auto& c) -> auto& { return c.mesh.integration; }),
      choice("mesh", "mass",
             {{"consistent", MassKind::consistent},
              {"lumped", MassKind::lumped},
              {"redistributed", MassKind::redistributed}},
             "`consistent` (the paper's); `redistributed`: consistent, the contact nodes' inertia moved onto the nodes "
             "above them (fem/mass_redistribution.hpp), which keeps long runs from creating energy at small "
             "c_s dt / h; `lumped` exists but chatters on this problem (not for studies)",
             [](auto& c) -> auto& { return c.mesh.mass; }),

      number("loading", "Uy_over_H", open(-0.1), open(0), "", "stage 1 top displacement / H (compression)",
             [](auto& c) -> auto& { return c.loading.Uy_over_H; }),
      number("loading", "preshear_ratio", closed(0), open(1), "", "stage 2 shears until T/N = preshear_ratio * f",
             [](auto& c) -> auto& { return c.loading.preshear_ratio; }),
      number("loading", "V0_over_cs", open(0), closed(0.1), "", "stage 3 top velocity / c_s",
             [](auto& c) -> auto& { return c.loading.V0_over_cs; }),

      number("friction", "f", closed(0), unbounded, "", "Coulomb coefficient",
             [](auto& c) -> auto& { return c.friction.f; }),
      choice("friction", "regularization",
             {{"none", Regularization::none}, {"prakash_clifton", Regularization::prakash_clifton}},
             "`none` or `prakash_clifton`: the friction bound f*s uses a normal stress s that relaxes to the "
             "contact pressure, ds/dt = -(abs(v)+pc_velocity)/pc_length (s - sigma), updated once per step "
             "(backward Euler, lagged); a node whose open/closed status cycles within one contact solve "
             "(grazing: no solution with a fixed bound) falls back to the Coulomb bound f r_y for that solve "
             "(solver/contact/prakash_clifton.hpp)",
             [](auto& c) -> auto& { return c.friction.regularization; }),
      number("friction", "pc_length", open(0), unbounded, "m", "Prakash–Clifton slip length L",
             [](auto& c) -> auto& { return c.friction.pc_length; }),
      number("friction", "pc_velocity", closed(0), unbounded, "m/s", "Prakash–Clifton reference velocity v*",
             [](auto& c) -> auto& { return c.friction.pc_velocity; }),

      number("time", "dt_times_cs", open(0), unbounded, "m", "dt = dt_times_cs / c_s; used when `time.dt` is null",
             [](auto& c) -> auto& { return c.time.dt_times_cs; }),
      optional_number("time", "dt", open(0), "s", "explicit time step, overrides `dt_times_cs`",
                      [](auto& c) -> auto& { return c.time.dt; }),
      number("time", "t_end", open(0), unbounded, "s",
             "simulated time of stage 3, a cap when `stop_after_opening` is set",
             [](auto& c) -> auto& { return c.time.t_end; }),
      integer("time", "max_steps", 1, static_cast<long long>(kMaxStepsLimit),
              "upper bound on the stage-3 step count ceil(t_end / dt): a configuration that asks for more is "
              "rejected before the run (exit 2) with the computed count. The default 2e7 is ~800 times the "
              "longest study run (20000 s at dt = 0.5 m / c_s = 0.77 s: 2.6e4 steps) and keeps the per-step "
              "global series (12 doubles a step) under 2 GB; the limit 1e9 keeps step counters inside a "
              "32-bit int",
              [](auto& c) -> auto& { return c.time.max_steps; }),
      number("time", "hht_alpha", closed(0), closed(1.0 / 3.0, "1/3"), "",
             "the paper's alpha (= -classic alpha_H); beta = (1+a)^2/4, gamma = 1/2+a",
             [](auto& c) -> auto& { return c.time.hht_alpha; }),
      choice("time", "contact_weighting", {{"alpha", ContactWeighting::alpha}, {"end", ContactWeighting::end}},
             "`alpha`: contact forces weighted like F_ext, (1-a) R(n+1) + a R(n); `end`: R(n+1) only",
             [](auto& c) -> auto& { return c.time.contact_weighting; }),
      optional_number("time", "stop_after_opening", open(0), "s",
                      "end the run this long after the interface first opens",
                      [](auto& c) -> auto& { return c.time.stop_after_opening; }),

      number("contact", "tolerance", open(0), closed(1e-2), "",
             "relative residual of the contact solve (scaled by p0 h)",
             [](auto& c) -> auto& { return c.contact.tolerance; }),
      integer("contact", "max_iterations", 1, 100000000,
              "Gauss–Seidel sweeps per pass; a pass that misses the tolerance, settles on a period-2 orbit or "
              "stalls (500 sweeps without halving its change) is followed by one under-relaxed pass (omega 0.5) "
              "of as many sweeps, after which the step is an error (solver/contact/contact_solver.hpp)",
              [](auto& c) -> auto& { return c.contact.max_iterations; }),
      choice("contact", "all_stick", {{"exact", AllStick::exact}},
             "how a step whose nodes all stuck before is solved: first the exact all-stick solution "
             "r = -W^-1 q (one product), kept when every node is closed and inside its friction bound, else "
             "Gauss–Seidel sweeps. The one way; the key stays so that configs naming it keep working",
             [](auto& c) -> auto& { return c.contact.all_stick; },
             {{"iterate", "Gauss–Seidel sweeps on every step are retired; the solver always tries the exact "
                          "all-stick solution first (use \"exact\" or leave the key out)"}}),

      number("perturbation", "amplitude", closed(0), unbounded, "",
             "random initial displacement of the free nodes, relative to the preshear top displacement",
             [](auto& c) -> auto& { return c.perturbation.amplitude; }),
      integer("perturbation", "seed", 0, kMaxSeed,
              "seed of the deterministic generator (std::mt19937_64); at most 2^53 - 1, the largest integer that "
              "every JSON reader holding numbers as doubles keeps exactly (a larger one would name two runs alike)",
              [](auto& c) -> auto& { return c.perturbation.seed; }),

      // The single-mode seed (model/mode_seed.hpp): absent unless amplitude_over_H is given.
      optional_number("mode_seed", "amplitude_over_H", open(0), "",
                      "amplitude / H of a single-mode initial displacement of the layer, added to the random "
                      "one: u_x = A cos(k x) exp(-k y), u_y = -A sin(k x) exp(-k y) at the free nodes (y above "
                      "the interface; not the contact nodes' u_y: no gap, no penetration), k = 2 pi mode / "
                      "lambda; null: none, and the group is left out of the resolved configuration",
                      [](auto& c) -> auto& { return c.mode_seed.amplitude_over_H; }, closed(1e-2)),
      integer("mode_seed", "mode", 1, 65536,
              "wavelengths of the single-mode seed in the period; at most lambda / (4 h) (four elements a "
              "wavelength); needs `mode_seed.amplitude_over_H`",
              [](auto& c) -> auto& { return c.mode_seed.mode; }),
      choice("mode_seed", "start", {{"rest", false}, {"sliding", true}},
             "`rest`: the layer starts at rest, its top at V0 (the paper's start); `sliding`: every node of the "
             "layer starts at V0, the steady sliding whose linear stability the seed probes. With f > 0 the "
             "interface slips from the first step, its traction jumping from preshear_ratio f p0 to f p0, which "
             "sends a uniform velocity jump (1 - preshear_ratio) f p0 / (rho c_s) into the layer: keep V0 well "
             "above it (the checks: V0 = 0.01 c_s, and the slip rate stays within 1.5 % of V0). Needs "
             "`mode_seed.amplitude_over_H`",
             [](auto& c) -> auto& { return c.mode_seed.sliding_start; }),

      choice("numerics", "linear_solver",
             {{"spectral", LinearSolverKind::spectral}, {"cholmod", LinearSolverKind::cholmod}},
             "`spectral` (FFT in x, exact for this uniform periodic mesh: on the rigid flat every step is "
             "taken per wavenumber on one mesh column's banded system, docs/stick-phase.md; with a substrate "
             "or `output.energy_decomposition = hht`, after the stick phase, one K_eff pass per step) or "
             "`cholmod` (general sparse Cholesky, two solves per step, every step: the oracle); both give the "
             "same discrete solution to round-off, which this chaotic problem amplifies after slip onset",
             [](auto& c) -> auto& { return c.numerics.linear_solver; },
             {{"circulant", "the two-solve FFT path is retired; `spectral` solves the same equations with one "
                            "K_eff pass per step (use \"spectral\" or leave the key out)"}}),
      integer("numerics", "threads", 1, 256,
              "threads of one run: the OpenMP team that shares out the FFT rows and wavenumbers of the "
              "`spectral` solves (results bitwise the same for any count), or the BLAS/OpenMP "
              "threads under CHOLMOD; `slidewave run --threads N` overrides it, and the resolved configuration "
              "in run.h5 records the count used. Needs a free core per thread: on a busy machine more threads are "
              "slower (set OMP_WAIT_POLICY=PASSIVE there)",
              [](auto& c) -> auto& { return c.numerics.threads; }),

      integer("output", "interface_stride", 1, 1000000, "write interface fields every this many steps",
              [](auto& c) -> auto& { return c.output.interface_stride; }),
      number_list("output", "snapshot_times", closed(0), "s", "times (stage 3 clock) of bulk snapshots",
                  [](auto& c) -> auto& { return c.output.snapshot_times; }),
      choice("output", "progress",
             {{"auto", ProgressMode::automatic}, {"always", ProgressMode::always}, {"never", ProgressMode::never}},
             "progress on stderr: `auto` (only on a TTY), `always`, `never`; a failing progress write (closed "
             "pipe) silences it and never stops the run",
             [](auto& c) -> auto& { return c.output.progress; }),
      number("output", "checkpoint_interval", closed(0), unbounded, "s",
             "wall time between checkpoints (RUN.checkpoint.h5, which `slidewave run --resume` continues); "
             "0: only at SIGINT/SIGTERM; does not change the results",
             [](auto& c) -> auto& { return c.output.checkpoint_interval; }),
      choice("output", "energy_decomposition", {{"none", false}, {"hht", true}},
             "`hht`: also book the algorithmic dissipation of HHT term by term (/global/dissipation_hht*, "
             "docs/energy-balance.md; a few dot products a step), which the balance residual must equal; "
             "`none`: not written",
             [](auto& c) -> auto& { return c.output.energy_decomposition; }),

      // The deformable substrate (docs/substrate.md): all four keys or none (none: the rigid flat, the paper).
      optional_number("substrate", "E", open(0), "Pa",
                      "substrate Young's modulus; null in every `substrate` key: the rigid flat of the paper. The "
                      "four keys go together (docs/substrate.md)",
                      [](auto& c) -> auto& { return c.substrate.E; }),
      optional_number("substrate", "nu", closed(0), "", "substrate Poisson's ratio",
                      [](auto& c) -> auto& { return c.substrate.nu; }, open(0.5)),
      optional_number("substrate", "rho", open(0), "kg/m^3", "substrate density",
                      [](auto& c) -> auto& { return c.substrate.rho; }),
      optional_number("substrate", "H", open(0), "m",
                      "substrate thickness H_s, a whole number in [2, 65536] of elements of the layer's size "
                      "h = geometry.H / mesh.elements_per_H; its bottom is held (u = 0)",
                      [](auto& c) -> auto& { return c.substrate.H; }),
  };
  // clang-format on
}

/// Shortest %g form that reads back as x: 0, 0.5, 0.01, 1e-05.
std::string format_number(double x) {
  char buffer[32];
  for (int digits = 1; digits <= 17; ++digits) {
    std::snprintf(buffer, sizeof buffer, "%.*g", digits, x);
    if (std::strtod(buffer, nullptr) == x) break;
  }
  return buffer;
}

std::string bound_text(const Bound& b, bool integral) {
  if (!b.text.empty()) return b.text;
  return integral ? std::to_string(static_cast<long long>(b.value)) : format_number(b.value);
}

bool within(const ConfigKey& k, double x) {
  if (!std::isfinite(x)) return false;
  if (k.lower && (k.lower->open ? !(x > k.lower->value) : !(x >= k.lower->value))) return false;
  if (k.upper && (k.upper->open ? !(x < k.upper->value) : !(x <= k.upper->value))) return false;
  return true;
}

/// "lo <= name < hi", "name > lo", ...
std::string interval_text(const ConfigKey& k) {
  std::string text;
  if (k.lower && k.upper)
    text = bound_text(*k.lower, false) + (k.lower->open ? " < " : " <= ") + k.name + (k.upper->open ? " < " : " <= ") +
           bound_text(*k.upper, false);
  else if (k.lower)
    text = k.name + (k.lower->open ? " > " : " >= ") + bound_text(*k.lower, false);
  else if (k.upper)
    text = k.name + (k.upper->open ? " < " : " <= ") + bound_text(*k.upper, false);
  else
    text = "any finite " + k.name;
  return text;
}

/// A whole number of any size (1e19 and 18446744073709551615 included: they are then out of range,
/// which within() reports, rather than "not an integer").
bool is_integral(const json& v) {
  if (v.is_number_integer()) return true;
  return v.is_number_float() && std::isfinite(v.get<double>()) && std::floor(v.get<double>()) == v.get<double>();
}

}  // namespace

json ConfigKey::default_value() const { return get(RunConfig{}); }

std::string ConfigKey::allowed() const {
  const std::string unit_text = unit.empty() ? "" : " (" + unit + ")";
  switch (kind) {
    case KeyKind::number:
      return interval_text(*this) + unit_text;
    case KeyKind::optional_number:
      return "null or " + interval_text(*this) + unit_text;
    case KeyKind::integer:
      return upper ? "integer in [" + bound_text(*lower, true) + ", " + bound_text(*upper, true) + "]"
                   : "integer >= " + bound_text(*lower, true);
    case KeyKind::choice: {
      std::string text;
      for (const auto& c : choices) text += (text.empty() ? "" : "|") + c;
      return text;
    }
    case KeyKind::number_list:
      return "list of numbers " + std::string(lower->open ? "> " : ">= ") + bound_text(*lower, false) + unit_text;
  }
  return "";
}

std::string ConfigKey::problem(const json& v) const {
  const std::string head = path() + ": " + excerpt(v.dump());
  const std::string tail = "; allowed " + allowed();
  switch (kind) {
    case KeyKind::optional_number:
      if (v.is_null()) return "";
      [[fallthrough]];
    case KeyKind::number:
      if (!v.is_number()) return head + " is not a number" + tail;
      return within(*this, v.get<double>()) ? "" : head + " out of range" + tail;
    case KeyKind::integer:
      if (!is_integral(v)) return head + " is not an integer" + tail;
      return within(*this, v.get<double>()) ? "" : head + " out of range" + tail;
    case KeyKind::choice:
      if (v.is_string()) {
        for (const auto& c : choices)
          if (c == v.get<std::string>()) return "";
        for (const auto& [value, instead] : retired)
          if (value == v.get<std::string>()) return head + " is retired: " + instead + tail;
      }
      return head + " invalid" + tail;
    case KeyKind::number_list: {
      bool ok = v.is_array();
      if (ok)
        for (const auto& e : v) ok = ok && e.is_number() && within(*this, e.get<double>());
      return ok ? "" : head + " invalid" + tail;
    }
  }
  return head + " invalid" + tail;
}

const std::vector<ConfigKey>& config_keys() {
  static const std::vector<ConfigKey> table = make_table();
  return table;
}

const std::vector<std::string>& config_groups() {
  static const std::vector<std::string> groups = [] {
    std::vector<std::string> out;
    for (const auto& k : config_keys())
      if (out.empty() || out.back() != k.group) out.push_back(k.group);
    return out;
  }();
  return groups;
}

}  // namespace slidewave

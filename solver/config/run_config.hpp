#pragma once
// Typed run configuration mirroring the JSON groups of docs/contracts.md (section 1).
// The member initializers are the keys' defaults (the paper's); bounds, units and descriptions of
// every key are in the key table (config/config_keys.hpp). Validation reports every violation at once.
#include <nlohmann/json.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace slidewave {

enum class Integration { full, reduced, reduced_pure };
enum class MassKind { consistent, lumped, redistributed };
enum class ContactWeighting { alpha, end };
enum class Regularization { none, prakash_clifton };
enum class ProgressMode { automatic, always, never };
enum class LinearSolverKind { spectral, cholmod };
enum class AllStick { exact };  ///< one value: the key contact.all_stick stays readable (config_keys.cpp)

struct MaterialConfig {
  double E = 1000.0, nu = 0.2, rho = 1000.0;
};
struct GeometryConfig {
  double H = 25.0, lambda_over_H = 2.0;
};
struct MeshConfig {
  int elements_per_H = 32;
  Integration integration = Integration::reduced;
  MassKind mass = MassKind::consistent;
};
struct LoadingConfig {
  double Uy_over_H = -0.001, preshear_ratio = 0.95, V0_over_cs = 1e-5;
};
struct FrictionConfig {
  double f = 1.5;
  Regularization regularization = Regularization::none;
  double pc_length = 0.5;    ///< Prakash–Clifton slip length L (m)
  double pc_velocity = 0.0;  ///< Prakash–Clifton reference velocity v* (m/s)
};
struct TimeConfig {
  double dt_times_cs = 0.5;  ///< dt = dt_times_cs / c_s, a length (m), used when dt is absent
  std::optional<double> dt;  ///< explicit step (s)
  double t_end = 1500.0;
  double hht_alpha = 0.1;  ///< the paper's alpha (classic HHT alpha_H = -hht_alpha)
  ContactWeighting contact_weighting = ContactWeighting::alpha;
  std::optional<double> stop_after_opening;
  long long max_steps = 20000000;  ///< a longer run is rejected before it starts (exit 2)
};
struct ContactConfig {
  double tolerance = 1e-10;
  int max_iterations = 2000;
  AllStick all_stick = AllStick::exact;
};
struct PerturbationConfig {
  double amplitude = 1e-5;
  long long seed = 1;
};
/// A single-mode initial displacement of the layer (model/mode_seed.hpp), on top of the random one: what
/// excites a chosen wavenumber in the checks against interface-wave theory (docs/substrate.md). Absent
/// (amplitude null): no such seed, and the group is left out of the resolved configuration.
struct ModeSeedConfig {
  std::optional<double> amplitude_over_H;  ///< displacement amplitude / geometry.H
  int mode = 1;                            ///< wavelengths in the period: k = 2 pi mode / lambda
  bool sliding_start = false;              ///< the whole layer starts at V0 (steady sliding), not at rest
  bool present() const { return amplitude_over_H.has_value(); }
};
struct NumericsConfig {
  /// spectral: FFT in x, one K_eff pass per step (the uniform periodic layer); cholmod: the general sparse
  /// path (two solves per step), kept as the tests' oracle
  LinearSolverKind linear_solver = LinearSolverKind::spectral;
  int threads = 1;  ///< threads of one run: spectral solves, or CHOLMOD (`run --threads` overrides it)
};
/// The deformable substrate below the interface (docs/substrate.md, model/substrate.hpp): all four keys
/// or none (parse_run_config checks that); none is the paper's rigid flat.
struct SubstrateConfig {
  std::optional<double> E, nu, rho;  ///< Young's modulus (Pa), Poisson's ratio, density (kg/m^3)
  std::optional<double> H;           ///< thickness H_s (m), a whole number of the layer's elements
  bool present() const { return E.has_value(); }
};
struct OutputConfig {
  int interface_stride = 4;
  std::vector<double> snapshot_times;
  ProgressMode progress = ProgressMode::automatic;
  double checkpoint_interval = 300.0;  ///< wall-time seconds between checkpoints (0: only at SIGINT/SIGTERM)
  bool energy_decomposition = false;   ///< also book the HHT algorithmic dissipation (/global/dissipation_hht*)
};

/// Constants that follow from the configuration, computed in one place (and written to run.h5).
struct DerivedConstants {
  double G, lame_lambda, c_s, c_l;
  double H, lambda, h;
  int n_x, n_y;  ///< elements along x (period) and y (height)
  double p0;     ///< preload pressure -Uy E(1-nu)/(H(1+nu)(1-2nu)) (Pa, compression positive); with a
                 ///< substrate, the pair's: -Uy / (H / M + H_s / M_s)
  double V0, dt;
  double t_onset_estimate;  ///< quasi-static time for T/N to reach f from preshear_ratio*f (s)
  /// Stage-3 steps the time loop runs at most, ceil(t_end / dt - 1e-9): a double, so that an absurd
  /// count (t_end = 1e12, rho = 1e-300) is compared with time.max_steps before any integer cast.
  double n_steps;
};

struct RunConfig {
  MaterialConfig material;
  GeometryConfig geometry;
  MeshConfig mesh;
  LoadingConfig loading;
  FrictionConfig friction;
  TimeConfig time;
  ContactConfig contact;
  PerturbationConfig perturbation;
  ModeSeedConfig mode_seed;
  NumericsConfig numerics;
  OutputConfig output;
  SubstrateConfig substrate;

  DerivedConstants derived() const;
  nlohmann::json to_json() const;  ///< the resolved configuration, every key explicit
};

/// Element rows of the substrate, H_s / h (precondition: config.substrate.present(), validated).
int substrate_rows(const RunConfig& config);

/// Thrown with every problem found, one per line ("key: value ... allowed ...").
class ConfigError : public std::runtime_error {
 public:
  explicit ConfigError(const std::vector<std::string>& problems);
  const std::vector<std::string> problems;
};

/// Parses and validates; throws ConfigError listing every invalid or unknown key, and a step count
/// ceil(t_end / dt) over time.max_steps.
RunConfig parse_run_config(const nlohmann::json& input);

/// The bytes of a configuration file, read once: a run parses exactly these and records them as
/// /setup/config_input, so editing or deleting the file during the run changes nothing.
/// Throws ConfigError naming the file and the operating system's reason when it cannot be read.
std::string read_config_bytes(const std::string& path);
/// Parses JSON text (`origin` names it in messages), merges `overrides` (JSON merge-patch: the CLI's
/// --threads) and validates the result like parse_run_config.
RunConfig parse_run_config_text(const std::string& text, const std::string& origin,
                                const nlohmann::json& overrides = nlohmann::json::object());
/// read_config_bytes + parse_run_config_text.
RunConfig load_run_config(const std::string& path);

}  // namespace slidewave

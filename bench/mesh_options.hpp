#pragma once
// The options every benchmark takes for the meshes it times: `--n N...` (elements per H) and
// `--lambda L...` (period / H), each followed by one or more values; and those of the case it times.
#include <cstdlib>
#include <string>
#include <vector>

#include "config/run_config.hpp"

namespace slidewave::bench {

/// True when argv[i] is `--n` or `--lambda`: its values are appended and i moves past them.
inline bool mesh_option(const std::string& option, int argc, char** argv, int& i, std::vector<int>& resolutions,
                        std::vector<double>& lambdas) {
  const auto has_value = [&] { return i + 1 < argc && argv[i + 1][0] != '-'; };
  if (option == "--n") {
    while (has_value()) resolutions.push_back(std::atoi(argv[++i]));
    return true;
  }
  if (option == "--lambda") {
    while (has_value()) lambdas.push_back(std::atof(argv[++i]));
    return true;
  }
  return false;
}

/// The case options of the benchmarks that time the paper's case: `--t-end T`, `--nu NU`, `--f F`.
struct CaseOptions {
  double t_end = 1000, nu = 0.2, f = 1.5;
  /// True when `option` is one of them (then set to `value`).
  bool take(const std::string& option, double value) {
    double* field = option == "--t-end" ? &t_end : option == "--nu" ? &nu : option == "--f" ? &f : nullptr;
    if (field) *field = value;
    return field != nullptr;
  }
};

/// The paper's configuration at one mesh (n elements per H, period lambda_over_H H) with the benchmark's nu,
/// f and t_end: the case every benchmark times.
inline RunConfig bench_config(int n, double lambda_over_H, double nu, double f, double t_end) {
  RunConfig config;
  config.mesh.elements_per_H = n;
  config.geometry.lambda_over_H = lambda_over_H;
  config.material.nu = nu;
  config.friction.f = f;
  config.time.t_end = t_end;
  return config;
}

}  // namespace slidewave::bench

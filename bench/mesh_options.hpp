#pragma once
// The options every benchmark takes for the meshes it times: `--n N...` (elements per H) and
// `--lambda L...` (period / H), each followed by one or more values.
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

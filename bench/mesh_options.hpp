#pragma once
// The options every benchmark takes for the meshes it times: `--n N...` (elements per H) and
// `--lambda L...` (period / H), each followed by one or more values.
#include <cstdlib>
#include <string>
#include <vector>

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

}  // namespace slidewave::bench

#pragma once
// Two values of numerics.linear_solver give the same discrete run to round-off: checked before the slip
// onset (the stick phase is not chaotic; after onset round-off differences grow), at H/8 up to 600 s.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"

namespace slidewave::testing {

inline void expect_same_run_before_slip_onset(const char* solver_a, const char* solver_b) {
  RunRecord runs[2];
  const char* kinds[2] = {solver_a, solver_b};
  for (int s = 0; s < 2; ++s)
    runs[s] = simulate(LayerModel(make_config({{"mesh", {{"elements_per_H", 8}}},
                                               {"time", {{"t_end", 600.0}}},
                                               {"numerics", {{"linear_solver", kinds[s]}}}})));
  const auto &a = runs[0], &b = runs[1];
  ASSERT_EQ(a.global.t.size(), b.global.t.size());
  EXPECT_NEAR(a.u_x_preshear, b.u_x_preshear, 1e-12 * std::fabs(b.u_x_preshear));
  const auto max_relative = [](const std::vector<double>& x, const std::vector<double>& y) {
    double scale = 0, diff = 0;
    for (size_t n = 0; n < x.size(); ++n) {
      scale = std::max(scale, std::fabs(y[n]));
      diff = std::max(diff, std::fabs(x[n] - y[n]));
    }
    return scale > 0 ? diff / scale : diff;
  };
  EXPECT_LE(max_relative(a.global.T, b.global.T), 1e-10);
  EXPECT_LE(max_relative(a.global.N, b.global.N), 1e-10);
  EXPECT_LE(max_relative(a.global.energy_elastic, b.global.energy_elastic), 1e-10);
  EXPECT_LE(max_relative(a.global.energy_kinetic, b.global.energy_kinetic), 1e-8);
  // Sticking nodes only move by the contact tolerance: compare slip with the preload displacement |Uy|.
  double max_slip_difference = 0;
  for (size_t n = 0; n < a.interface.slip.data.size(); ++n)
    max_slip_difference = std::max(max_slip_difference, std::fabs(a.interface.slip.data[n] - b.interface.slip.data[n]));
  EXPECT_LE(max_slip_difference, 1e-10 * 0.025);
  EXPECT_LE(max_relative(a.interface.normal_traction.data, b.interface.normal_traction.data), 1e-10);
  EXPECT_EQ(a.interface.state.data, b.interface.state.data);
}

}  // namespace slidewave::testing

// The retirement test's transient factor per wavenumber (model/stick_phase/wavenumber_stepper.hpp,
// docs/stick-phase.md "Retirement"): 3 max(6.3, 1.65 / Omega_min) with Omega_min = dt sqrt(lambda_min) of the
// lane's interior problem K_II x = lambda M_II x, against a dense generalized eigensolve of every lane; lanes
// certified above the floor by an inertia count get the floor without an inverse iteration, and the count
// (positive_definite_lanes) agrees with the eigenvalues.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "model/layer_model.hpp"
#include "model/stick_phase/wavenumber_blocks.hpp"
#include "model/stick_phase/wavenumber_stepper.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

/// Lane m's interior block (rows and columns [2, s)) of a banded matrix, dense.
Eigen::MatrixXd interior(const BandedLanes& A, int m) {
  const int n = A.rows - 2;
  Eigen::MatrixXd dense = Eigen::MatrixXd::Zero(n, n);
  for (int r = 0; r < n; ++r)
    for (int k = -A.p; k <= A.p; ++k)
      if (r + k >= 0 && r + k < n) dense(r, r + k) = A.get(r + 2, k, m);
  return dense;
}

double lowest_eigenvalue(const WavenumberBlocks& blocks, int m) {
  const Eigen::GeneralizedSelfAdjointEigenSolver<Eigen::MatrixXd> solver(interior(blocks.K, m), interior(blocks.M, m));
  return solver.eigenvalues().minCoeff();
}

TEST(WavenumberStepper, TransientFactorIsThatOfEachLanesSlowestFrequency) {
  for (const double dt_cs : {0.5, 0.125}) {  // few lanes below the floor, and half of them
    const LayerModel m(testing::make_config(
        {{"mesh", {{"elements_per_H", 16}}}, {"time", {{"dt_times_cs", dt_cs}, {"t_end", 100.0}}}}));
    const WavenumberBlocks blocks(m);
    const HHTCoefficients hht(m.config.time.hht_alpha, m.d.dt);
    const WavenumberStepper stepper(blocks, hht, true, 0x1p-54);
    int floored = 0;
    for (int lane = 0; lane < blocks.lanes; ++lane) {
      const double omega = m.d.dt * std::sqrt(lowest_eigenvalue(blocks, lane));
      const double expected = 3 * std::max(6.3, 1.65 / omega);
      // Inverse iteration (60 steps) approaches Omega_min from above (a Rayleigh quotient), so the factor from
      // below; lanes with close lowest eigenvalues are up to ~1e-4 short of it after 60 steps.
      const double factor = stepper.transient_factor(lane);
      EXPECT_LE(factor, expected * (1 + 1e-12)) << "dt c_s " << dt_cs << " lane " << lane;
      EXPECT_GE(factor, expected * (1 - 1e-3)) << "dt c_s " << dt_cs << " lane " << lane;
      if (expected == 3 * 6.3) {
        EXPECT_EQ(factor, expected) << "dt c_s " << dt_cs << " lane " << lane;
      }
      floored += expected == 3 * 6.3;
    }
    std::printf("dt c_s %g: %d of %d lanes at the floor\n", dt_cs, floored, blocks.lanes);
    EXPECT_GT(floored, 0) << "some lanes are at the floor";
    EXPECT_LT(floored, blocks.lanes) << "some lanes are below it";
  }
}

TEST(BandedLanes, PositiveDefiniteLanesCountsTheEigenvaluesBelowTheShift) {
  const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 8}}}}));
  const WavenumberBlocks blocks(m);
  const double sigma = lowest_eigenvalue(blocks, 3);  // lane 3's lowest: lanes below it have theirs lower
  for (const double shift : {0.999 * sigma, 1.001 * sigma}) {
    const std::vector<bool> definite = positive_definite_lanes(mass_stiffness_band(blocks, -shift, 1.0), 2);
    for (int lane = 0; lane < blocks.lanes; ++lane)
      EXPECT_EQ(definite[lane], lowest_eigenvalue(blocks, lane) > shift) << "lane " << lane << " shift " << shift;
  }
}

}  // namespace
}  // namespace slidewave

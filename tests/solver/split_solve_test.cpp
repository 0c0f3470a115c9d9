// One K_eff pass per step (numerics.linear_solver = "spectral"): BlockCirculantSolver's split solve
// (linalg/split_solver.hpp) against two full solves and CHOLMOD on the layer's K_eff, and the one-pass HHT
// step against the two-solve step (TwoSolveSplit over the FFT solver and over CHOLMOD).
// Oracles: K_eff^{-1} (b + C^T g) by CHOLMOD; the load g is scaled so that its response is a sizeable part
// of u (a wrong G_m, a lost 1/n_x or a wrong weight w changes u far beyond the tolerance).
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <random>

#include "linalg/block_circulant_solver.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "linalg/two_solve_split.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "same_run_support.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

using testing::random_vector;

double relative_difference(const Eigen::VectorXd& x, const Eigen::VectorXd& reference) {
  return (x - reference).lpNorm<Eigen::Infinity>() / reference.lpNorm<Eigen::Infinity>();
}

LayerModel layer(int n_x, int n_y, Integration integration, const char* mass) {
  return LayerModel(testing::make_config(
      {{"mesh", {{"elements_per_H", n_y}, {"integration", testing::integration_name(integration)}, {"mass", mass}}},
       {"geometry", {{"lambda_over_H", double(n_x) / n_y}}}}));
}

Eigen::SparseMatrix<double> K_eff_of(const LayerModel& m) {
  const HHTCoefficients hht(m.config.time.hht_alpha, m.d.dt);
  return effective_matrix(hht, m.M_ff(), m.K_ff());
}

TEST(SplitSolve, FreeAndLoadedHalvesMatchCholmod) {
  // n_x with a factor 3 (12, 48, 192) get FFTW plans that use the imaginary-minus-real array offset of the
  // planning arrays, which the split buffers must reproduce (they once did not: wrong u, heap corruption).
  for (int n_x : {3, 4, 5, 8, 12, 48, 192})
    for (int n_y : {2, 3})
      for (Integration integration : testing::kAllIntegrations)
        for (const char* mass : {"consistent", "lumped"}) {
          const LayerModel m = layer(n_x, n_y, integration, mass);
          ASSERT_EQ(m.mesh.n_x, n_x);
          const std::string where = "n_x = " + std::to_string(n_x) + " n_y = " + std::to_string(n_y) + " " +
                                    testing::integration_name(integration) + " " + mass;
          const Eigen::SparseMatrix<double> A = K_eff_of(m);
          BlockCirculantSolver split(A, n_x, n_y);
          const SparseCholesky cholmod(A);
          const int n = split.size(), n_c = split.n_contact();
          ASSERT_EQ(n_c, m.n_contact_dofs) << where;
          const Eigen::VectorXd b = random_vector(n, 5);
          const Eigen::VectorXd x_free = cholmod.solve(b);
          // g large enough that its response dominates u at the contact DOFs.
          const double scale = A.diagonal().maxCoeff() * x_free.lpNorm<Eigen::Infinity>() * 10;
          const Eigen::VectorXd g = scale * random_vector(n_c, 6);
          Eigen::VectorXd b_loaded = b;
          b_loaded.head(n_c) += g;
          const Eigen::VectorXd x_loaded = cholmod.solve(b_loaded);
          ASSERT_GT(relative_difference(x_free, x_loaded), 0.5) << where << ": the load must matter";

          Eigen::VectorXd u_contact(n_c), u(n);
          split.solve_free(b, u_contact);
          EXPECT_LE(relative_difference(u_contact, x_free.head(n_c)), 1e-12) << where;
          // A full solve in between (as for the Delassus operator) leaves the kept spectrum alone.
          EXPECT_LE(relative_difference(split.solve(b_loaded), x_loaded), 1e-12) << where;
          split.solve_loaded(g, u);
          EXPECT_LE(relative_difference(u, x_loaded), 1e-12) << where;
          // The kept spectrum is consumed: a second loaded half needs a new free half.
          EXPECT_THROW(split.solve_loaded(g, u), std::logic_error) << where;
          // Zero load: the free solve itself, all DOFs.
          split.solve_free(b, u_contact);
          split.solve_loaded(Eigen::VectorXd::Zero(n_c), u);
          EXPECT_LE(relative_difference(u, x_free), 1e-12) << where;
        }
}

/// The layer's system, the preload, and one step from the same state on a given path.
struct OneStep {
  const LayerModel& m;
  PartitionedSystem system;
  HHTCoefficients hht;
  PreloadState pre;
  explicit OneStep(const LayerModel& model)
      : m(model),
        system(model.partitioned()),
        hht(model.config.time.hht_alpha, model.d.dt),
        pre(solve_preload(model)) {}

  /// Two steps (so that the carried r(n) and K u(n) enter too) with contact forces r_1, r_2.
  /// load_factor scales r_1, r_2 (1: the step under test; 0.9 stands for a wrong weight w).
  /// fused: each correct() also does the next step's predictor (HHTStepper::correct's u_d_following).
  HHTState run(std::unique_ptr<SplitSolver> K_eff, bool alpha_weighted, Eigen::VectorXd* u_free_1,
               double load_factor = 1, bool fused = false) const {
    HHTStepper stepper(system, hht, alpha_weighted, std::move(K_eff));
    Eigen::VectorXd v = Eigen::VectorXd::Zero(m.n_free + m.n_top);
    for (int i = 0; i < m.mesh.n_x; ++i) v(m.n_free + 2 * i) = m.d.V0;
    HHTState s = stepper.initial_state(pre.u, v, pre.r, SparseCholesky(m.M_ff()));
    const int n_c = m.n_contact_dofs;
    const auto u_d = [&](int n) {
      return m.top_displacement(pre.u_x_top + 1e3 * m.d.V0 * (n * hht.dt), m.config.loading.Uy_over_H * m.d.H);
    };
    for (int n = 1; n <= 2; ++n) {
      stepper.predict(s, u_d(n));
      const Eigen::VectorXd u_free = stepper.solve_free();
      EXPECT_EQ(u_free.size(), n_c);
      if (n == 1) *u_free_1 = u_free;
      // Reactions of the preload with a node-to-node variation of their own size.
      const Eigen::VectorXd r = load_factor * (pre.r + pre.r.lpNorm<Eigen::Infinity>() * random_vector(n_c, 10 + n));
      const Eigen::VectorXd u_d_following = u_d(n + 1);
      stepper.correct(r, s, fused ? &u_d_following : nullptr);
    }
    return s;
  }
};

TEST(SplitSolve, OneStepEqualsTheTwoSolveStep) {
  const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 8}}}}));
  const OneStep step(m);
  for (bool alpha_weighted : {true, false}) {
    const std::string where = alpha_weighted ? "alpha weighting (w = 1 - a)" : "end weighting (w = 1)";
    Eigen::VectorXd free_two, free_one, free_cholmod;
    const auto circulant = [&] { return std::make_unique<BlockCirculantSolver>(K_eff_of(m), m.mesh.n_x, m.mesh.n_y); };
    const auto two_solves = [&](std::unique_ptr<LinearSolver> solver) {
      return std::make_unique<TwoSolveSplit>(std::move(solver), m.n_contact_dofs);
    };
    const HHTState two = step.run(two_solves(circulant()), alpha_weighted, &free_two);
    const HHTState one = step.run(circulant(), alpha_weighted, &free_one);
    const HHTState cholmod =
        step.run(two_solves(std::make_unique<SparseCholesky>(K_eff_of(m))), alpha_weighted, &free_cholmod);
    // The test can fail: contact forces off by the 10 % of a wrong weight w (0.9 for 1) move u far beyond it.
    Eigen::VectorXd unused;
    const HHTState off = step.run(circulant(), alpha_weighted, &unused, 0.9);
    EXPECT_GT(relative_difference(off.u, two.u), 1e-4) << where;
    for (const HHTState* reference : {&two, &cholmod}) {
      EXPECT_LE(relative_difference(free_one, free_two), 1e-12) << where;
      EXPECT_LE(relative_difference(one.u, reference->u), 1e-12) << where;
      EXPECT_LE(relative_difference(one.v.head(m.n_free), reference->v.head(m.n_free)), 1e-10) << where;
      EXPECT_LE(relative_difference(one.acc.head(m.n_free), reference->acc.head(m.n_free)), 1e-10) << where;
      EXPECT_LE(relative_difference(one.Ku, reference->Ku), 1e-10) << where;
      EXPECT_LE(relative_difference(one.Ma_f, reference->Ma_f), 1e-10) << where;
    }
  }
}

// The next step's predictor done inside the correction's loops (the time loop's way) gives the same bits
// as a predict() of its own, on both paths and for both contact weightings.
TEST(SplitSolve, PredictorFusedIntoTheCorrectionIsBitwiseTheSame) {
  const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 8}}}}));
  const OneStep step(m);
  for (bool one_pass : {false, true})
    for (bool alpha_weighted : {true, false}) {
      const auto solver = [&]() -> std::unique_ptr<SplitSolver> {
        auto circulant = std::make_unique<BlockCirculantSolver>(K_eff_of(m), m.mesh.n_x, m.mesh.n_y);
        if (one_pass) return circulant;
        return std::make_unique<TwoSolveSplit>(std::move(circulant), m.n_contact_dofs);
      };
      Eigen::VectorXd free_apart, free_fused;
      const HHTState apart = step.run(solver(), alpha_weighted, &free_apart, 1, false);
      const HHTState fused = step.run(solver(), alpha_weighted, &free_fused, 1, true);
      const std::string where =
          std::string(one_pass ? "one pass" : "two solves") + (alpha_weighted ? ", alpha" : ", end");
      EXPECT_EQ(fused.u, apart.u) << where;
      EXPECT_EQ(fused.v, apart.v) << where;
      EXPECT_EQ(fused.acc, apart.acc) << where;
      EXPECT_EQ(fused.Ku, apart.Ku) << where;
      EXPECT_EQ(fused.Mu_f, apart.Mu_f) << where;
      EXPECT_EQ(fused.Mv_f, apart.Mv_f) << where;
      EXPECT_EQ(fused.Ma_f, apart.Ma_f) << where;
      // And the comparison can fail: a step with other forces differs.
      Eigen::VectorXd unused;
      EXPECT_NE(step.run(solver(), alpha_weighted, &unused, 0.9, true).u, apart.u) << where;
    }
}

TEST(SplitSolve, StepperNeedsASplitSolverOnTheContactDofs) {
  const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 4}}}}));
  const PartitionedSystem system = m.partitioned();
  const HHTCoefficients hht(0.1, m.d.dt);
  EXPECT_THROW(HHTStepper(system, hht, true, nullptr), std::invalid_argument);
  PartitionedSystem wrong_contact = system;
  wrong_contact.n_contact = 2;
  EXPECT_THROW(
      HHTStepper(wrong_contact, hht, true, std::make_unique<BlockCirculantSolver>(K_eff_of(m), m.mesh.n_x, m.mesh.n_y)),
      std::invalid_argument);
  EXPECT_THROW(TwoSolveSplit(std::make_unique<SparseCholesky>(K_eff_of(m)), -1), std::invalid_argument);
}

}  // namespace
}  // namespace slidewave

// Nonsmooth Gauss–Seidel on the condensed problem (contact/contact_solver) against brute-force
// enumeration of the 4^n contact states on small random problems, and against the conditions.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cstdio>
#include <fstream>
#include <random>
#include <string>

#include "contact/contact_solver.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/delassus.hpp"
#include "contact/prakash_clifton.hpp"
#include "contact_oracle.hpp"
#include "linalg/block_circulant_solver.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "model/layer_model.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

/// Gauss–Seidel on a dense W under Coulomb's bound f r_y, and y = q + W r.
GaussSeidelReport solve_coulomb(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                const GaussSeidelSettings& settings, Eigen::VectorXd& r, Eigen::VectorXd& y,
                                std::vector<ContactState>& state) {
  const ContactSolver solver(W, settings, DelassusLayout::dense);
  CoulombBounds bounds(f);
  const GaussSeidelReport report = solver.solve(q, bounds, r, state);
  solver.local_variables(q, r, y);
  return report;
}

/// Random SPD W of 2n x 2n: A A^T / (2n) + 0.3 I, A uniform in [-1, 1] (coupled, including u_x-u_y
/// within a node). With `delassus_like`, the per-node blocks are diagonal as in the layer's W.
Eigen::MatrixXd random_spd(int n, std::mt19937_64& generator, bool delassus_like) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::MatrixXd A(2 * n, 2 * n);
  for (int i = 0; i < 2 * n; ++i)
    for (int j = 0; j < 2 * n; ++j) A(i, j) = uniform(generator);
  Eigen::MatrixXd W = A * A.transpose() / (2 * n) + 0.3 * Eigen::MatrixXd::Identity(2 * n, 2 * n);
  if (delassus_like) {
    for (int k = 0; k < n; ++k) W(2 * k, 2 * k + 1) = W(2 * k + 1, 2 * k) = 0;
    W += 0.5 * Eigen::MatrixXd::Identity(2 * n, 2 * n);  // keep it SPD after zeroing the blocks
  }
  return W;
}

struct Counts {
  int problems = 0, not_converged = 0, several_solutions = 0, max_iterations = 0;
  int n_open = 0, n_stick = 0, n_slip = 0;  ///< node states over the converged problems (coverage)
};

Counts run_random_problems(bool delassus_like, std::uint64_t seed, int n_trials) {
  std::mt19937_64 generator(seed);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Counts counts;
  const GaussSeidelSettings settings{1e-14, 100000, 1.0};
  for (int n = 1; n <= 3; ++n)
    for (double f : {0.0, 0.3, 1.0, 2.0})
      for (int trial = 0; trial < n_trials; ++trial) {
        const Eigen::MatrixXd W = random_spd(n, generator, delassus_like);
        Eigen::VectorXd q(2 * n);
        for (int i = 0; i < 2 * n; ++i) q(i) = uniform(generator);
        const std::string where = "n = " + std::to_string(n) + " f = " + std::to_string(f) + " trial " +
                                  std::to_string(trial) + (delassus_like ? " (diagonal blocks)" : " (coupled)");
        const auto solutions = testing::enumerate_solutions(W, q, f, 1e-12);
        EXPECT_FALSE(solutions.empty()) << where << ": enumeration found no solution";
        ++counts.problems;
        counts.several_solutions += solutions.size() > 1;

        Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * n), y;
        std::vector<ContactState> state;
        const auto report = solve_coulomb(W, q, f, settings, r, y, state);
        if (!report.converged) {
          ++counts.not_converged;
          continue;
        }
        counts.max_iterations = std::max(counts.max_iterations, report.iterations);
        EXPECT_LE((y - (q + W * r)).norm(), 1e-15 * (1 + y.norm())) << where;
        EXPECT_EQ(testing::signorini_coulomb_violations(W, q, f, r, 1e-10), "") << where;
        double nearest = 1e300;
        for (const auto& s : solutions) nearest = std::min(nearest, (s - r).cwiseAbs().maxCoeff());
        EXPECT_LE(nearest, 1e-8) << where;
        for (int k = 0; k < n; ++k) {  // reported states agree with (r, y)
          counts.n_open += state[k] == ContactState::open;
          counts.n_stick += state[k] == ContactState::stick;
          counts.n_slip += state[k] == ContactState::slip;
          switch (state[k]) {
            case ContactState::open:
              EXPECT_EQ(r.segment<2>(2 * k).norm(), 0.0) << where;
              break;
            case ContactState::stick:
              EXPECT_LE(y.segment<2>(2 * k).norm(), 1e-10) << where;
              break;
            case ContactState::slip:
              EXPECT_NEAR(std::fabs(r(2 * k)), f * r(2 * k + 1), 1e-10) << where;
              break;
          }
        }
      }
  return counts;
}

// Problems shaped like the layer's (diagonal per-node blocks): Gauss–Seidel converges on every one.
TEST(GaussSeidel, AgreesWithBruteForceOnDelassusLikeProblems) {
  const Counts c = run_random_problems(true, 2024, 150);
  EXPECT_EQ(c.not_converged, 0) << "of " << c.problems;
  EXPECT_GT(c.n_open, 100);
  EXPECT_GT(c.n_stick, 100);
  EXPECT_GT(c.n_slip, 100);
  ::testing::Test::RecordProperty("problems", c.problems);
  ::testing::Test::RecordProperty("several_solutions", c.several_solutions);
  ::testing::Test::RecordProperty("max_sweeps", c.max_iterations);
  ::testing::Test::RecordProperty("states_open_stick_slip", std::to_string(c.n_open) + " " + std::to_string(c.n_stick) +
                                                                " " + std::to_string(c.n_slip));
}

// Fully coupled random W (u_x-u_y coupling inside a node too). Projected Gauss–Seidel is not
// guaranteed to converge for large f there; on these 1800 problems it converged every time.
TEST(GaussSeidel, AgreesWithBruteForceOnCoupledProblems) {
  const Counts c = run_random_problems(false, 7, 150);
  EXPECT_EQ(c.not_converged, 0) << "of " << c.problems;
  EXPECT_GT(c.n_open, 100);
  EXPECT_GT(c.n_stick, 100);
  EXPECT_GT(c.n_slip, 100);
  ::testing::Test::RecordProperty("problems", c.problems);
  ::testing::Test::RecordProperty("not_converged", c.not_converged);
  ::testing::Test::RecordProperty("several_solutions", c.several_solutions);
}

TEST(GaussSeidel, WarmStartAtTheSolutionTakesOneSweep) {
  std::mt19937_64 generator(99);
  const Eigen::MatrixXd W = random_spd(3, generator, true);
  const Eigen::VectorXd q = (Eigen::VectorXd(6) << 0.3, -0.5, -0.2, -0.4, 0.1, 0.2).finished();
  const GaussSeidelSettings settings{1e-14, 10000, 1.0};
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6), y;
  std::vector<ContactState> state;
  ASSERT_TRUE(solve_coulomb(W, q, 0.5, settings, r, y, state).converged);
  const auto again = solve_coulomb(W, q, 0.5, settings, r, y, state);
  EXPECT_TRUE(again.converged);
  EXPECT_EQ(again.iterations, 1);
}

TEST(GaussSeidel, ReportsNonConvergenceAtTheIterationCap) {
  std::mt19937_64 generator(5);
  const Eigen::MatrixXd W = random_spd(3, generator, true);
  const Eigen::VectorXd q = (Eigen::VectorXd(6) << 0.3, -0.5, -0.2, -0.4, 0.1, -0.2).finished();
  const GaussSeidelSettings settings{1e-300, 3, 1.0};
  Eigen::VectorXd r = Eigen::VectorXd::Zero(6), y;
  std::vector<ContactState> state;
  const auto report = solve_coulomb(W, q, 1.0, settings, r, y, state);
  EXPECT_FALSE(report.converged);
  EXPECT_EQ(report.iterations, 2 * 3);  // the plain pass, then the under-relaxed one
  EXPECT_EQ(report.relaxation, kFallbackRelaxation);
}

// Coulomb, two nodes, f = 2, one solution (both slipping). Node 0's friction lifts node 1
// (W(3, 0) = 0.15 > 0), and exact local solves overshoot from both sides: node 1 slips under
// r_y1 = 0.51, node 0 then slips at r_x0 = 1.25 and opens node 1, which lowers r_x0 to 0.32, and
// so on; plain sweeps repeat with period 2 from the first sweep, the change per sweep stays 1.02
// (the old behaviour: not converged at any cap). The under-relaxed pass converges to the solution.
TEST(GaussSeidel, PeriodTwoCycleAtLargeFrictionIsResolvedByTheRelaxedPass) {
  Eigen::MatrixXd W(4, 4);
  W << 0.41, 0.00, 0.08, 0.15, 0.00, 0.62, 0.35, 0.14, 0.08, 0.35, 0.53, 0.00, 0.15, 0.14, 0.00, 0.33;
  const Eigen::VectorXd q = (Eigen::VectorXd(4) << -0.68, -0.10, 0.69, -0.24).finished();
  const double f = 2.0;
  const auto solutions = testing::enumerate_solutions(W, q, f, 1e-12);
  ASSERT_EQ(solutions.size(), 1u);

  // Plain sweeps written out: each node solved exactly with the other frozen, from r = 0.
  const auto plain_sweep = [&](Eigen::VectorXd r) {
    for (int k = 0; k < 2; ++k) {
      const Eigen::Matrix2d D = W.block<2, 2>(2 * k, 2 * k);
      const Eigen::Vector2d b = (q + W * r).segment<2>(2 * k) - D * r.segment<2>(2 * k);
      r.segment<2>(2 * k) = solve_local_coulomb(LocalOperator(D), b, f).r;
    }
    return r;
  };
  const Eigen::VectorXd r_1 = plain_sweep(Eigen::VectorXd::Zero(4)), r_2 = plain_sweep(r_1), r_3 = plain_sweep(r_2);
  EXPECT_GT((r_2 - r_1).cwiseAbs().maxCoeff(), 1.0);
  EXPECT_LE((r_3 - r_1).cwiseAbs().maxCoeff(), 1e-14);
  EXPECT_GT((r_1 - solutions[0]).cwiseAbs().maxCoeff(), 0.4);

  Eigen::VectorXd r = Eigen::VectorXd::Zero(4), y;
  std::vector<ContactState> state;
  const GaussSeidelSettings settings{1e-14, 2000, 1.0};
  const auto report = solve_coulomb(W, q, f, settings, r, y, state);
  ASSERT_TRUE(report.converged);
  EXPECT_EQ(report.relaxation, kFallbackRelaxation);
  // The orbit is detected after kCycleSweeps returns (not at the cap), then the relaxed pass converges.
  EXPECT_LE(report.iterations, kCycleWatchFrom + 2 + kCycleSweeps + 100);
  EXPECT_LE((r - solutions[0]).cwiseAbs().maxCoeff(), 1e-12);
  EXPECT_EQ(testing::signorini_coulomb_violations(W, q, f, r, 1e-12), "");
  EXPECT_EQ(state[0], ContactState::slip);
  EXPECT_EQ(state[1], ContactState::slip);
}

// Prakash–Clifton bounds, two nodes, f = 1: no solution exists with the given bounds, so exact local
// solves cycle (the old behaviour: not converged at any cap). Node 1 slips forward at its bound and
// presses node 0 shut (gap -0.0014); node 0 closes and slips backward at its bound 0.19, which loads
// node 1 (r_y1 0.32 -> 0.37), which opens node 0 (gap +0.011), which removes its force, and so on.
// After kMaxStatusChanges changes node 0 gets the Coulomb bound f r_y and the solve converges.
TEST(GaussSeidel, PrakashCliftonCycleAtGrazingReleasesTheBound) {
  Eigen::MatrixXd W(4, 4);
  W << 1.09, 0.00, -0.24, -0.32, 0.00, 1.19, 0.22, 0.27, -0.24, 0.22, 1.17, 0.00, -0.32, 0.27, 0.00, 1.27;
  const Eigen::VectorXd q = (Eigen::VectorXd(4) << -0.73, -0.06, 0.43, -0.41).finished();
  const std::vector<double> bounds{0.19, 0.13};
  const double f = 1.0;
  const Eigen::Matrix2d D0 = W.block<2, 2>(0, 0), D1 = W.block<2, 2>(2, 2);
  // No solution with the given bounds: node 0 open leaves it a negative gap; node 0 closed must slip
  // backward at r_x0 = +0.19 (sticking needs r_x0 = 0.75), and then its gap is positive even at r_y0 = 0.
  const auto node1_open0 = solve_local_coulomb(LocalOperator(D1), q.segment<2>(2), f, bounds[1]);
  const double gap0_open = q(1) + W.block<1, 2>(1, 2).dot(node1_open0.r);
  EXPECT_LT(gap0_open, 0.0);
  const Eigen::Vector2d r0_slip(bounds[0], 0.0);
  const auto node1_slip0 =
      solve_local_coulomb(LocalOperator(D1), q.segment<2>(2) + W.block<2, 2>(2, 0) * r0_slip, f, bounds[1]);
  const double gap0_slip = q(1) + W.block<1, 2>(1, 0).dot(r0_slip) + W.block<1, 2>(1, 2).dot(node1_slip0.r);
  EXPECT_GT(gap0_slip, 0.0);
  const double r_x0_stick = -(q(0) + W.block<1, 2>(0, 2).dot(node1_slip0.r)) / D0(0, 0);  // du_x0 = 0
  EXPECT_GT(r_x0_stick, bounds[0]);

  Eigen::VectorXd r = Eigen::VectorXd::Zero(4), y;
  std::vector<ContactState> state;
  const ContactSolver solver(W, {1e-14, 2000, 1.0}, DelassusLayout::dense);
  PrakashCliftonBounds given(f, bounds);
  const auto report = solver.solve(q, given, r, state);
  solver.local_variables(q, r, y);
  ASSERT_TRUE(report.converged);
  EXPECT_LE(report.iterations, 30);
  EXPECT_EQ(report.n_bounds_released, 1);
  // node 0: Coulomb, slipping backward at f r_y0 with a closed gap; node 1: slipping forward at its bound
  EXPECT_EQ(state[0], ContactState::slip);
  EXPECT_GT(r(1), 0.0);
  EXPECT_NEAR(r(0), f * r(1), 1e-14);
  EXPECT_LT(y(0), 0.0);
  EXPECT_NEAR(y(1), 0.0, 1e-13);
  EXPECT_EQ(state[1], ContactState::slip);
  EXPECT_DOUBLE_EQ(r(2), -bounds[1]);
  EXPECT_GT(y(2), 0.0);
  EXPECT_NEAR(y(3), 0.0, 1e-13);
}

// On the real Delassus operator of a small layer, uniform compression q = (0, -g) per node: every
// node closes and sticks with the same reaction (translation invariance).
TEST(GaussSeidel, UniformIndentationOfTheLayerDelassus) {
  const RunConfig config = testing::make_config({{"mesh", {{"elements_per_H", 4}}}});
  const LayerModel model(config);
  const Eigen::MatrixXd W = delassus_operator(SparseCholesky(model.K_ff()), model.n_contact_dofs);
  const int n = model.mesh.n_contact();
  Eigen::VectorXd q = Eigen::VectorXd::Zero(2 * n);
  for (int k = 0; k < n; ++k) q(2 * k + 1) = -0.025;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * n), y;
  std::vector<ContactState> state;
  const auto report = solve_coulomb(W, q, 1.5, {1e-13, 10000, model.d.p0 * model.d.h}, r, y, state);
  ASSERT_TRUE(report.converged);
  for (int k = 0; k < n; ++k) {
    EXPECT_EQ(state[k], ContactState::stick);
    EXPECT_NEAR(r(2 * k + 1), r(1), 1e-10 * r(1));
    EXPECT_NEAR(r(2 * k), 0.0, 1e-10 * r(1));
  }
  EXPECT_EQ(testing::signorini_coulomb_violations(W, q, 1.5, r, 1e-10 * r(1)), "");
}

// A plain pass that stalls (its change neither shrinks nor repeats) gives up to the under-relaxed fallback
// after kStallSweeps sweeps without halving its smallest change, not after max_iterations, and the fallback
// solves the problem: a step of the campaign's run nu 0.49, f 2, H/32 (redistributed mass) whose plain pass
// stalled, read from tests/solver/data/stalled_contact_h32.txt (W's generating columns, q, the warm start).
TEST(GaussSeidel, AStalledPlainPassGivesUpToTheFallback) {
  std::ifstream in(std::string(SLIDEWAVE_SOURCE_DIR) + "/tests/solver/data/stalled_contact_h32.txt");
  ASSERT_TRUE(in) << "fixture missing";
  std::string line;
  while (in.peek() == '#') std::getline(in, line);
  int rows = 0, plain_sweeps_captured = 0;
  double f = 0, tolerance = 0, force_scale = 0;
  in >> rows >> f >> tolerance >> force_scale >> plain_sweeps_captured;
  Eigen::VectorXd z0(rows), z1(rows), q(rows), r(rows);
  for (int i = 0; i < rows; ++i) in >> z0(i) >> z1(i) >> q(i) >> r(i);
  ASSERT_TRUE(in) << "fixture truncated";
  const Eigen::MatrixXd W = delassus_from_node_responses(z0, z1, rows / 2);
  const GaussSeidelSettings settings{tolerance, 2000, force_scale};
  const ContactSolver solver(W, settings, DelassusLayout::block_circulant);
  CoulombBounds bounds(f);
  std::vector<ContactState> state;
  const GaussSeidelReport report = solver.solve(q, bounds, r, state);
  EXPECT_TRUE(report.converged);
  EXPECT_EQ(report.relaxation, kFallbackRelaxation);  // the plain pass gave up
  // It gave up at the stall (sweeps of both passes: 503 plain when captured, then the fallback's), not
  // after max_iterations = 2000 plain sweeps.
  EXPECT_GE(report.iterations, kStallSweeps);
  EXPECT_LT(report.iterations, settings.max_iterations);
  EXPECT_EQ(testing::signorini_coulomb_violations(W, q, f, r, 1e-8 * force_scale), "");
  int n_slip = 0, n_open = 0;
  for (ContactState s : state) {
    n_slip += s == ContactState::slip;
    n_open += s == ContactState::open;
  }
  EXPECT_GT(n_slip, 0);  // a frictional problem, not a trivial one
  std::printf("stalled plain pass: %d sweeps in all (%d plain when captured), %d slipping, %d open of %d nodes\n",
              report.iterations, plain_sweeps_captured, n_slip, n_open, rows / 2);
}

// The sweeps' updates through W's two generating columns (delassus_periodic_columns) give the result of the
// updates through W itself bit for bit: a frictional problem with slip, stick and opening on a layer's
// periodic Delassus operator, plain and (many sweeps, Prakash–Clifton-like bounds) cycling solves.
// The dense W and its generating columns give the same solve: the same states and r to the tolerance (the
// residual's start product sums in its own order, so not bit for bit).
TEST(GaussSeidel, PeriodicColumnsGiveTheSameSolve) {
  const LayerModel model(
      testing::make_config({{"mesh", {{"elements_per_H", 4}}}, {"geometry", {{"lambda_over_H", 6.0}}}}));
  const Eigen::MatrixXd W = delassus_operator_periodic(SparseCholesky(model.K_ff()), model.mesh.n_contact());
  const int n = model.mesh.n_contact();
  std::mt19937_64 generator(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    Eigen::VectorXd q(2 * n);
    for (int k = 0; k < n; ++k) {
      q(2 * k) = 0.02 * uniform(generator);
      q(2 * k + 1) = -0.025 + 0.03 * uniform(generator);  // some nodes open
    }
    // Odd trials: a given bound per node, Prakash–Clifton's
    const auto bounds = [&]() -> std::unique_ptr<FrictionBounds> {
      if (trial % 2)
        return std::make_unique<PrakashCliftonBounds>(1.5, std::vector<double>(n, 0.5 * model.d.p0 * model.d.h));
      return std::make_unique<CoulombBounds>(1.5);
    };
    const GaussSeidelSettings settings{1e-12, 200, model.d.p0 * model.d.h};
    const ContactSolver dense(W, settings, DelassusLayout::dense),
        circulant(W, settings, DelassusLayout::block_circulant);
    Eigen::VectorXd r_dense = Eigen::VectorXd::Zero(2 * n), r_columns = r_dense, y_dense, y_columns;
    std::vector<ContactState> state_dense, state_columns;
    const auto a = dense.solve(q, *bounds(), r_dense, state_dense);
    const auto b = circulant.solve(q, *bounds(), r_columns, state_columns);
    dense.local_variables(q, r_dense, y_dense);
    circulant.local_variables(q, r_columns, y_columns);
    EXPECT_GT(a.iterations, 2) << trial;
    EXPECT_NEAR(a.iterations, b.iterations, 1) << trial;
    EXPECT_TRUE(a.converged && b.converged) << trial;
    const double scale = settings.force_scale;
    EXPECT_LT((r_dense - r_columns).lpNorm<Eigen::Infinity>(), 1e-9 * scale) << trial;
    EXPECT_LT((y_dense - y_columns).lpNorm<Eigen::Infinity>(), 1e-9 * q.lpNorm<Eigen::Infinity>()) << trial;
    EXPECT_EQ(state_dense, state_columns) << trial;
  }
}

// The time loop's W (of K_eff: an implicit step's response, local) on a mesh with more contact nodes than
// its blocks reach above round-off (kDelassusRoundOff): the sweeps leave those blocks out, and give the
// dense W's solve: the same states and sweep counts, r to the dense solve's own round-off.
TEST(GaussSeidel, BlocksBelowRoundOffLeftOutGiveTheSameSolve) {
  const LayerModel model(
      testing::make_config({{"mesh", {{"elements_per_H", 32}}}, {"geometry", {{"lambda_over_H", 6.0}}}}));
  const HHTCoefficients hht(model.config.time.hht_alpha, model.d.dt);
  const BlockCirculantSolver K_eff(effective_matrix(hht, model.M_ff(), model.K_ff()), model.mesh.n_x, model.mesh.n_y,
                                   1);
  const int n = model.mesh.n_contact();
  const Eigen::MatrixXd W = delassus_operator_periodic(K_eff, n);
  const int reach = delassus_periodic_reach(delassus_periodic_columns(W), n, kDelassusRoundOff);
  ASSERT_LT(2 * reach + 1, n) << "the test needs blocks below round-off (reach " << reach << " of " << n << ")";
  std::mt19937_64 generator(9);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  const double scale = model.d.p0 * model.d.h;
  for (int trial = 0; trial < 10; ++trial) {
    Eigen::VectorXd q(2 * n);
    for (int k = 0; k < n; ++k) {  // a pressed interface with some nodes open and some slipping
      q(2 * k) = 0.8 * W(0, 0) * scale * uniform(generator);
      q(2 * k + 1) = W(1, 1) * scale * (-1.0 + 1.2 * uniform(generator));
    }
    const GaussSeidelSettings settings{1e-12, 500, scale};
    const ContactSolver dense(W, settings, DelassusLayout::dense),
        circulant(W, settings, DelassusLayout::block_circulant);
    Eigen::VectorXd r_dense = Eigen::VectorXd::Zero(2 * n), r_columns = r_dense;
    std::vector<ContactState> state_dense, state_columns;
    CoulombBounds bounds_dense(1.5), bounds_columns(1.5);
    const auto a = dense.solve(q, bounds_dense, r_dense, state_dense);
    const auto b = circulant.solve(q, bounds_columns, r_columns, state_columns);
    EXPECT_TRUE(a.converged && b.converged) << trial;
    EXPECT_GT(a.iterations, 2) << trial;
    EXPECT_EQ(a.iterations, b.iterations) << trial;
    EXPECT_EQ(state_dense, state_columns) << trial;
    // The round-off of a sweep's sums over n = 192 nodes, n eps ~ 4e-14 of p0 h (measured: 2-3e-15);
    // a block of W wrongly left out moves r by far more.
    EXPECT_LT((r_dense - r_columns).lpNorm<Eigen::Infinity>(), 1e-13 * scale) << trial;
  }
}

}  // namespace
}  // namespace slidewave

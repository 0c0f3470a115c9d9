// The exact all-stick solution (contact/all_stick): on the layer's own Delassus operator it returns
// r = -W^{-1} q when that r sticks everywhere (checked against the reactions that made q and against
// Gauss–Seidel), and refuses, leaving r and the states untouched, when one node would open or slip.
// In a run it replaces the sweeps of the stick steps.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>

#include "contact/all_stick.hpp"
#include "contact/contact_solver.hpp"
#include "contact/coulomb_friction.hpp"
#include "contact/delassus.hpp"
#include "contact/prakash_clifton.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

constexpr double kF = 1.5;

/// The block-circulant W of the dynamic step of the paper's layer at H/8 (16 contact nodes).
Eigen::MatrixXd layer_delassus() {
  const RunConfig config = testing::make_config({{"mesh", {{"elements_per_H", 8}}}});
  const LayerModel model(config);
  const HHTCoefficients hht(config.time.hht_alpha, model.d.dt);
  const auto K_eff = model.factorize(effective_matrix(hht, model.M_ff(), model.K_ff()));
  return delassus_operator_periodic(*K_eff, model.n_contact_dofs / 2);
}

/// Reactions of n nodes, closed (r_y in [1, 2]) and inside the cone: |r_x| <= 0.9 f r_y.
Eigen::VectorXd sticking_reactions(int n, std::mt19937_64& generator) {
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  Eigen::VectorXd r(2 * n);
  for (int k = 0; k < n; ++k) {
    r(2 * k + 1) = 1.5 + 0.5 * uniform(generator);
    r(2 * k) = 0.9 * kF * r(2 * k + 1) * uniform(generator);
  }
  return r;
}

/// Gauss–Seidel from zero to 1e-13 (an independent method): its reactions and states.
struct Sweeps {
  Eigen::VectorXd r;
  std::vector<ContactState> state;
};
Sweeps gauss_seidel(const Eigen::MatrixXd& W, const Eigen::VectorXd& q) {
  Sweeps out{Eigen::VectorXd::Zero(q.size()), {}};
  CoulombBounds bounds(kF);
  const auto report = ContactSolver(W, {1e-13, 100000, 1.0}, DelassusLayout::dense).solve(q, bounds, out.r, out.state);
  EXPECT_TRUE(report.converged);
  return out;
}

TEST(AllStick, ReturnsTheReactionsOfAStickingInterface) {
  const Eigen::MatrixXd W = layer_delassus();
  const int n = static_cast<int>(W.rows() / 2);
  ASSERT_EQ(n, 16);
  AllStickSolution all_stick(W);
  std::mt19937_64 generator(7);
  for (int trial = 0; trial < 20; ++trial) {
    const Eigen::VectorXd r_made = sticking_reactions(n, generator);
    const Eigen::VectorXd q = -W * r_made;  // y = q + W r_made = 0: every node sticks
    Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * n);
    std::vector<ContactState> state(n, ContactState::open);
    ASSERT_TRUE(all_stick.solve(q, CoulombBounds(kF), r, state)) << "trial " << trial;
    EXPECT_LE((r - r_made).cwiseAbs().maxCoeff(), 1e-12 * r_made.cwiseAbs().maxCoeff()) << "trial " << trial;
    for (ContactState s : state) EXPECT_EQ(s, ContactState::stick);
    // Gauss–Seidel reaches the same reactions to its tolerance.
    EXPECT_LE((r - gauss_seidel(W, q).r).cwiseAbs().maxCoeff(), 1e-9) << "trial " << trial;
  }
}

TEST(AllStick, RefusesWhenOneNodeWouldSlipOrOpen) {
  const Eigen::MatrixXd W = layer_delassus();
  const int n = static_cast<int>(W.rows() / 2);
  AllStickSolution all_stick(W);
  std::mt19937_64 generator(11);
  const Eigen::VectorXd r_inside = sticking_reactions(n, generator);
  Eigen::VectorXd outside_cone = r_inside, pulling = r_inside;
  outside_cone(2 * 5) = 1.05 * kF * outside_cone(2 * 5 + 1);  // node 5 beyond f r_y: it slips
  pulling(2 * 9 + 1) = -0.1;                                  // node 9 pulled: it opens
  pulling(2 * 9) = 0;
  for (const Eigen::VectorXd& r_made : {outside_cone, pulling}) {
    const Eigen::VectorXd q = -W * r_made;
    Eigen::VectorXd r = Eigen::VectorXd::Constant(2 * n, 3.0);
    std::vector<ContactState> state(n, ContactState::slip);
    EXPECT_FALSE(all_stick.solve(q, CoulombBounds(kF), r, state));
    EXPECT_EQ(r, Eigen::VectorXd::Constant(2 * n, 3.0));
    for (ContactState s : state) EXPECT_EQ(s, ContactState::slip);
    // Not all-stick indeed: Gauss–Seidel finds a node that does not stick.
    const std::vector<ContactState> state_sweeps = gauss_seidel(W, q).state;
    EXPECT_NE(std::count(state_sweeps.begin(), state_sweeps.end(), ContactState::stick), n);
  }
}

TEST(AllStick, GivenBoundsReplaceFTimesPressure) {
  const Eigen::MatrixXd W = layer_delassus();
  const int n = static_cast<int>(W.rows() / 2);
  AllStickSolution all_stick(W);
  std::mt19937_64 generator(13);
  const Eigen::VectorXd r_made = sticking_reactions(n, generator);
  const Eigen::VectorXd q = -W * r_made;
  std::vector<double> bounds(n);
  for (int k = 0; k < n; ++k) bounds[k] = std::fabs(r_made(2 * k)) * 1.001 + 1e-9;
  Eigen::VectorXd r = Eigen::VectorXd::Zero(2 * n);
  std::vector<ContactState> state;
  EXPECT_TRUE(all_stick.solve(q, PrakashCliftonBounds(kF, bounds), r, state));
  bounds[3] = 0.5 * std::fabs(r_made(6));  // node 3's bound below its stick force
  r.setZero();
  EXPECT_FALSE(all_stick.solve(q, PrakashCliftonBounds(kF, bounds), r, state));
  EXPECT_EQ(r, Eigen::VectorXd::Zero(2 * n));
}

// A whole run (H/16, nu = 0.2, f = 1.5, through slip onset to 50 s after the first opening): every step
// before the first slip is solved exactly (0 sweeps), and the energy balance closes as it must: the
// residual is the HHT dissipation booked term by term, to round-off of the energy that flowed.
TEST(AllStick, RunSolvesStickStepsExactlyAndKeepsTheEnergyBalance) {
  const RunConfig config = testing::make_config({{"mesh", {{"elements_per_H", 16}}},
                                                 {"time", {{"t_end", 3000.0}, {"stop_after_opening", 50.0}}},
                                                 {"output", {{"energy_decomposition", "hht"}}}});
  const RunRecord run = simulate(LayerModel(config));
  ASSERT_TRUE(run.complete);
  ASSERT_GT(run.t_first_opening, 0);
  // First recorded row with a node that does not stick; every step before it took 0 sweeps.
  const auto& st = run.interface.state;
  int first_slip_row = st.n_rows();
  for (int row = 0; row < st.n_rows() && first_slip_row == st.n_rows(); ++row)
    for (int k = 0; k < st.n_cols; ++k)
      if (st.data[row * st.n_cols + k] != static_cast<std::int8_t>(ContactState::stick)) first_slip_row = row;
  ASSERT_GT(first_slip_row, 10) << "the run should stick for a while";
  ASSERT_LT(first_slip_row, st.n_rows()) << "the run should reach slip onset";
  const size_t stick_steps = static_cast<size_t>((first_slip_row - 1) * config.output.interface_stride);
  long long sweeps_total = 0;
  for (size_t i = 1; i < run.global.t.size(); ++i) {
    sweeps_total += run.global.contact_iterations[i];
    if (i <= stick_steps) {
      EXPECT_EQ(run.global.contact_iterations[i], 0) << "step " << i;
    }
  }
  EXPECT_GT(sweeps_total, 0) << "the slip steps need Gauss–Seidel";
  const GlobalSeries& g = run.global;
  double scale = 0, closure = 0;
  for (size_t i = 0; i < g.t.size(); ++i)
    scale = std::max({scale, std::fabs(g.work_external[i]), std::fabs(g.energy_elastic[i] - g.energy_elastic[0]),
                      g.energy_kinetic[i], g.dissipation_friction[i]});
  for (size_t i = 0; i < g.t.size(); ++i)
    closure = std::max(closure, std::fabs(g.energy_balance_residual[i] + g.dissipation_hht[i]) / scale);
  EXPECT_LT(closure, 1e-9);
  RecordProperty("energy_closure", testing::sci(closure));
}

}  // namespace
}  // namespace slidewave

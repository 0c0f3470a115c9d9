// The stick stage (model/uniform_stick.hpp) against plain stepping of the whole layer: without the seed,
// the layer stepped by the HHT step and the exact all-stick contact solve stays x-uniform, and after N
// steps its state and running sums equal the column's, broadcast (and n_x times, for the sums), to
// round-off; the column finds the first slip at the step the layer does; a run's rows before the handover
// are the uniform layer's, and the seed comes n_lead steps before the first slip.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <cmath>

#include "contact/all_stick.hpp"
#include "contact/delassus.hpp"
#include "contact/friction_law.hpp"
#include "model/energy_ledger.hpp"
#include "model/layer_model.hpp"
#include "model/recorder.hpp"
#include "model/simulation.hpp"
#include "model/uniform_stick.hpp"
#include "test_support.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {
namespace {

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

/// The whole layer, unperturbed, stepped while every node sticks (all-stick solution r = -W^-1 q).
struct PlainStepping {
  explicit PlainStepping(const LayerModel& model)
      : m(model),
        hht(m.config.time.hht_alpha, m.d.dt),
        system{m.K, m.K_ff, m.M_ff, m.M_ff_rows, m.K_fd, m.n_free, m.n_top, m.n_contact_dofs},
        pre(solve_preload(m)),
        stepper(system, hht, m.config.time.contact_weighting == ContactWeighting::alpha,
                m.factorize_split(effective_matrix(hht, system))),
        all_stick(stepper.contact_weight() * delassus_operator_periodic(stepper.K_eff(), m.mesh.n_contact())),
        friction(make_friction_law(m.config.friction)),
        ledger(m, top_velocity()) {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(m.n_free + m.n_top);
    v.tail(m.n_top) = top_velocity();
    loop.dynamics = stepper.initial_state(pre.u, v, pre.r, *m.factorize(m.M_ff));
    loop.contact = pre.state;
    loop.friction = friction->initial_state(pre.r);
    loop.energy = ledger.start(loop.dynamics);
  }
  Eigen::VectorXd top_velocity() const {
    Eigen::VectorXd v = Eigen::VectorXd::Zero(m.n_top);
    for (int i = 0; i < m.mesh.n_x; ++i) v(2 * i) = m.d.V0;
    return v;
  }
  /// One step; false if the all-stick solution fails (the first slip).
  bool step() {
    HHTState& s = loop.dynamics;
    const int n_c = m.n_contact_dofs;
    stepper.predict(s, m.top_displacement(pre.u_x_top + m.d.V0 * ((loop.step + 1) * hht.dt),
                                          m.config.loading.Uy_over_H * m.d.H));
    Eigen::VectorXd q = stepper.solve_free();
    for (int k = 0; k < n_c; k += 2) q(k) -= s.u(k);
    std::vector<double> bounds;
    friction->bounds(loop.friction, bounds);
    Eigen::VectorXd r = s.r;
    if (!all_stick.solve(q, m.config.friction.f, bounds, r, loop.contact)) return false;
    stepper.correct(r, s);
    ++loop.step;
    const Eigen::VectorXd du = s.u.head(n_c) - stepper.u_previous().head(n_c);
    ledger.book_step(s, stepper.u_previous(), stepper.r_previous(), du, loop.energy);
    friction->update(du, s.r, hht.dt, loop.friction);
    return true;
  }
  const LayerModel& m;
  HHTCoefficients hht;
  PartitionedSystem system;
  PreloadState pre;
  HHTStepper stepper;
  AllStickSolution all_stick;
  std::unique_ptr<FrictionLaw> friction;
  EnergyLedger ledger;
  LoopState loop;
};

TEST(UniformStick, ColumnIsThePlainSteppedLayerToRoundOff) {
  for (const char* weighting : {"alpha", "end"}) {
    const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 8}}},
                                            {"time", {{"contact_weighting", weighting}}},
                                            {"output", {{"energy_decomposition", "hht"}}}}));
    PlainStepping plain(m);
    UniformStick stick(m, plain.pre);
    Recorder recorder(m, plain.ledger, plain.pre);
    LoopState layer = plain.loop;
    stick.start(layer, recorder, 0);
    const int n_steps = 300;
    for (int n = 0; n < n_steps; ++n) {
      ASSERT_TRUE(plain.step()) << "the layer sticks for 300 steps";
      ASSERT_TRUE(stick.step(layer, recorder));
    }
    stick.expand_into(layer);
    const HHTState &a = layer.dynamics, &b = plain.loop.dynamics;
    // Round-off of the two paths (a linear, stable recurrence: it does not grow). A column of the wrong
    // row sums, or a lost factor n_x, is off by O(1).
    EXPECT_LT(relative_difference(a.u, b.u), 1e-12) << weighting;
    EXPECT_LT(relative_difference(a.v, b.v), 1e-9) << weighting;
    EXPECT_LT(relative_difference(a.r, b.r), 1e-10) << weighting;
    EXPECT_LT(relative_difference(a.Ku, b.Ku), 1e-10) << weighting;
    const EnergySums &e = layer.energy, &f = plain.loop.energy;
    EXPECT_NEAR(e.energy_start, f.energy_start, 1e-12 * f.energy_start) << weighting;
    EXPECT_NEAR(e.work_external, f.work_external, 1e-9 * std::fabs(f.work_external)) << weighting;
    EXPECT_NEAR(e.hht.total(), f.hht.total(), 1e-9 * std::fabs(f.work_external)) << weighting;
    EXPECT_GT(std::fabs(f.work_external), 0);
    // The rows recorded from the column: T/N of the last step equals the plain layer's.
    const std::vector<double>& T = recorder.rows().global.T;
    double T_plain = 0;
    for (int k = 0; k < m.mesh.n_contact(); ++k) T_plain -= b.r(2 * k);
    EXPECT_NEAR(T.back(), T_plain, 1e-10 * T_plain) << weighting;
    EXPECT_EQ(T.size(), static_cast<std::size_t>(n_steps + 1));
  }
}

TEST(UniformStick, ColumnSlipsAtTheStepTheLayerSlipsAndHandsOverFourTransitsBefore) {
  const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 8}}}}));
  PlainStepping plain(m);
  std::int64_t n_slip = 0;
  while (plain.step()) ASSERT_LT(++n_slip, 5000) << "the layer must slip";
  UniformStick stick(m, plain.pre);
  const std::int64_t n_lead = std::lround(4 * m.d.H / (m.d.c_s * m.d.dt));
  EXPECT_EQ(stick.handover_step(100000, nullptr), n_slip - n_lead);
  EXPECT_EQ(stick.handover_step(n_slip - n_lead - 10, nullptr), n_slip - n_lead - 10) << "ends with the run";
}

TEST(UniformStick, FrictionlessInterfaceHasNoStickStage) {
  const LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 4}}}, {"friction", {{"f", 0.0}}}}));
  UniformStick stick(m, solve_preload(m));
  EXPECT_EQ(stick.handover_step(1000, nullptr), 0);
}

// A run: the rows before the handover are those of the uniform layer (every node the same), the seed
// shows after it; the energy balance closes through the stage, the seed and the slip (alpha = 0).
TEST(UniformStick, RunRowsAreUniformUntilTheHandoverAndTheBalanceCloses) {
  const RunConfig config = testing::make_config({{"mesh", {{"elements_per_H", 8}}},
                                                 {"time", {{"t_end", 1300.0}, {"hht_alpha", 0.0}}},
                                                 {"output", {{"interface_stride", 1}}}});
  const LayerModel m(config);
  UniformStick probe(m, solve_preload(m));
  const std::int64_t n_handover = probe.handover_step(100000, nullptr);
  ASSERT_GT(n_handover, 100);
  const RunRecord run = simulate(m);
  const auto& traction = run.interface.tangential_traction;
  const auto spread = [&](int row) {
    const auto first = traction.data.begin() + static_cast<std::ptrdiff_t>(row) * traction.n_cols;
    const auto [lo, hi] = std::minmax_element(first, first + traction.n_cols);
    return *hi - *lo;
  };
  EXPECT_EQ(spread(static_cast<int>(n_handover)), 0) << "uniform up to the handover";
  EXPECT_GT(spread(static_cast<int>(n_handover) + 1), 0) << "the seed breaks the symmetry";
  double scale = 0, worst = 0;
  for (std::size_t i = 0; i < run.global.t.size(); ++i) {
    scale = std::max(scale, std::fabs(run.global.work_external[i]));
    worst = std::max(worst, std::fabs(run.global.energy_balance_residual[i]));
  }
  EXPECT_LT(worst, 1e-10 * scale);
  RecordProperty("energy_balance_relative", testing::sci(worst / scale));
}

}  // namespace
}  // namespace slidewave

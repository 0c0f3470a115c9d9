// The stick phase in wavenumbers (model/stick_phase/stick_phase.hpp, docs/stick-phase.md) against plain
// stepping: simulate() itself from the seeded state at t = 0 (the project's setup), captured through a run
// observer. The same discrete solution to round-off: state, reactions at every node and step, energies and
// the ledger's sums; the all-stick solution leaves its friction bound on the same step; retiring
// wavenumbers happens and changes nothing beyond round-off.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <atomic>
#include <cmath>
#include <map>

#include "contact/friction_law.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state_arrays.hpp"
#include "model/simulation.hpp"
#include "model/stick_phase/plain_slip_step.hpp"
#include "model/stick_phase/stick_phase.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

/// Runs simulate() until its first step solved by Gauss–Seidel (the first slip), keeping the state at
/// the steps asked for and every row.
class PlainRun : public RunObserver {
 public:
  PlainRun(const LayerModel& model, std::vector<std::int64_t> keep) : keep_(std::move(keep)) {
    record_ = simulate(model, {}, &stop_, nullptr, this);
  }
  void after_step(RunRecord& record, const Capture& capture) override {
    const std::int64_t step = static_cast<std::int64_t>(record.global.t.size()) - 1;
    if (step == 0 || std::find(keep_.begin(), keep_.end(), step) != keep_.end()) states_[step] = capture();
    if (step > 0 && record.global.contact_iterations.back() > 0) {
      first_slip_ = step;
      stop_ = true;
    }
  }
  void at_end(RunRecord&, const Capture&) override {}
  const StateArrays& state(std::int64_t step) const { return states_.at(step); }
  const RunRecord& record() const { return record_; }
  std::int64_t first_slip() const { return first_slip_; }

 private:
  std::vector<std::int64_t> keep_;
  std::map<std::int64_t, StateArrays> states_;
  std::atomic<bool> stop_{false};
  RunRecord record_;
  std::int64_t first_slip_ = -1;
};

double relative_difference(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).lpNorm<Eigen::Infinity>() / b.lpNorm<Eigen::Infinity>();
}

/// Largest differences: u, dt v, beta dt^2 a against max |u| (the state in one unit, whose round-off
/// plain stepping itself makes), v and a against their own max (for the record), reactions against the
/// largest reaction (every node at the interface rows, T and N every step), energies and sums against
/// the elastic energy.
struct Agreement {
  double u = 0, v = 0, acc = 0, v_own = 0, acc_own = 0, r = 0, reactions_every_step = 0, energies = 0, sums = 0;
};

/// Steps the stick phase from the plain run's t = 0 to `step` and compares with the plain run there.
Agreement compare_at(const LayerModel& m, const PlainRun& plain, StickPhase& stick, std::int64_t step) {
  const auto law = make_friction_law(m.config.friction);
  const LoopState start = captured_loop_state(m, plain.state(0));
  stick.start(start);
  Agreement a;
  const RunRecord& rows = plain.record();
  const double force_scale = std::fabs(rows.global.N[0]);
  while (stick.step_count() < step) {
    EXPECT_TRUE(stick.step(*law->bounds(start.friction))) << "step " << stick.step_count() + 1;
    const std::size_t n = static_cast<std::size_t>(stick.step_count());
    double T = 0, N = 0;
    for (Eigen::Index k = 0; k < stick.reactions().size() / 2; ++k) {
      T -= stick.reactions()(2 * k);
      N += stick.reactions()(2 * k + 1);
    }
    a.reactions_every_step = std::max({a.reactions_every_step, std::fabs(T - rows.global.T[n]) / force_scale,
                                       std::fabs(N - rows.global.N[n]) / force_scale});
    const double energy_scale = rows.global.energy_elastic[n];
    a.energies = std::max({a.energies, std::fabs(stick.kinetic() - rows.global.energy_kinetic[n]) / energy_scale,
                           std::fabs(stick.elastic() - rows.global.energy_elastic[n]) / energy_scale});
    const EnergySums& e = stick.sums();
    const double work_scale = energy_scale;  // the sums start at 0: measured against the energies
    a.sums = std::max({a.sums, std::fabs(e.work_external - rows.global.work_external[n]) / work_scale,
                       std::fabs(e.dissipation_friction - rows.global.dissipation_friction[n]) / work_scale,
                       std::fabs(e.work_contact_normal - rows.global.work_contact_normal[n]) / work_scale});
    if (!rows.global.dissipation_hht.empty())  // each HHT term of the ledger
      a.sums = std::max({a.sums, std::fabs(e.hht.gamma - rows.global.dissipation_hht_gamma[n]) / work_scale,
                         std::fabs(e.hht.beta - rows.global.dissipation_hht_beta[n]) / work_scale,
                         std::fabs(e.hht.shift - rows.global.dissipation_hht_shift[n]) / work_scale});
    // Node by node on the rows of the interface (every interface_stride steps).
    if (n % m.config.output.interface_stride == 0) {
      const std::size_t row = n / m.config.output.interface_stride, n_c = m.mesh.n_contact();
      for (std::size_t k = 0; k < n_c; ++k) {
        const double r_x = -rows.interface.tangential_traction.data[row * n_c + k] * m.d.h;
        const double r_y = rows.interface.normal_traction.data[row * n_c + k] * m.d.h;
        a.reactions_every_step =
            std::max({a.reactions_every_step, std::fabs(stick.reactions()(2 * k) - r_x) / force_scale * n_c,
                      std::fabs(stick.reactions()(2 * k + 1) - r_y) / force_scale * n_c});
      }
    }
  }
  LoopState now = start;
  stick.reconstruct(now);
  const LoopState reference = captured_loop_state(m, plain.state(step));
  const double dt = m.d.dt, beta = HHTCoefficients(m.config.time.hht_alpha, dt).beta;
  const double u_scale = reference.dynamics.u.lpNorm<Eigen::Infinity>();
  const auto difference = [](const Eigen::VectorXd& x, const Eigen::VectorXd& y) {
    return (x - y).lpNorm<Eigen::Infinity>();
  };
  a.u = difference(now.dynamics.u, reference.dynamics.u) / u_scale;
  a.v = dt * difference(now.dynamics.v, reference.dynamics.v) / u_scale;
  a.acc = beta * dt * dt * difference(now.dynamics.acc, reference.dynamics.acc) / u_scale;
  a.v_own = relative_difference(now.dynamics.v, reference.dynamics.v);
  a.acc_own = relative_difference(now.dynamics.acc, reference.dynamics.acc);
  a.r = relative_difference(now.dynamics.r, reference.dynamics.r);
  return a;
}

void report(const char* name, const Agreement& a) {
  char line[300];
  std::snprintf(line, sizeof line,
                "u %.1e dt v %.1e beta dt^2 a %.1e (v %.1e a %.1e of their own) r %.1e r(every step) %.1e energies "
                "%.1e sums %.1e",
                a.u, a.v, a.acc, a.v_own, a.acc_own, a.r, a.reactions_every_step, a.energies, a.sums);
  ::testing::Test::RecordProperty(name, line);
  std::printf("%s: %s\n", name, line);
}

void expect_round_off(const Agreement& a, const std::string& what) {
  EXPECT_LT(a.u, 1e-13) << what;  // measured: <= 1e-14 (H/8 to H/32, both weightings)
  EXPECT_LT(a.v, 1e-13) << what;
  EXPECT_LT(a.acc, 1e-13) << what;
  EXPECT_LT(a.r, 1e-12) << what;
  EXPECT_LT(a.reactions_every_step, 1e-11) << what;  // per node: measured <= 1.6e-12
  EXPECT_LT(a.energies, 1e-12) << what;
  EXPECT_LT(a.sums, 1e-12) << what;
}

/// The model stepped plainly: the oracle.
LayerModel plain_stepping(const RunConfig& config) {
  LayerModel m(config);
  m.steps_in_wavenumbers = false;
  return m;
}

RunConfig config(int n, const char* weighting) {
  return testing::make_config({{"mesh", {{"elements_per_H", n}}},
                               {"time", {{"contact_weighting", weighting}, {"t_end", 1500.0}}},
                               {"output", {{"energy_decomposition", "hht"}}}});
}

TEST(StickPhase, IsPlainSteppingToRoundOffAndSlipsOnTheSameStep) {
  for (const int n : {8, 16})
    for (const char* weighting : {"alpha", "end"}) {
      const std::string what = "H/" + std::to_string(n) + " " + weighting;
      const LayerModel m = plain_stepping(config(n, weighting));
      const std::int64_t checked = 300;
      PlainRun plain(m, {checked});
      ASSERT_GT(plain.first_slip(), checked) << what;
      const WavenumberBlocks blocks(m);
      StickPhase stick(m, blocks, plain.record().u_x_preshear, 0.0);  // no retirement
      const Agreement a = compare_at(m, plain, stick, checked);
      report((what + " no retirement").c_str(), a);
      expect_round_off(a, what);
      // On to the first slip: the all-stick reactions leave the bound on the step plain stepping slips.
      const auto law = make_friction_law(m.config.friction);
      const LoopState start = captured_loop_state(m, plain.state(0));
      stick.start(start);
      while (stick.step(*law->bounds(start.friction))) ASSERT_LT(stick.step_count(), plain.first_slip()) << what;
      EXPECT_EQ(stick.step_count() + 1, plain.first_slip()) << what;
    }
}

TEST(StickPhase, RetiresWavenumbersWithoutChangingTheAgreement) {
  for (const char* weighting : {"alpha", "end"}) {
    const LayerModel m =
        plain_stepping(config(32, weighting));  // at H/32 the highest wavenumbers retire after ~600 steps
    const std::int64_t checked = 900;
    PlainRun plain(m, {checked});
    ASSERT_GT(plain.first_slip(), checked);
    const WavenumberBlocks blocks(m);
    StickPhase stick(m, blocks, plain.record().u_x_preshear);
    const Agreement a = compare_at(m, plain, stick, checked);
    report((std::string("H/32 retiring ") + weighting).c_str(), a);
    expect_round_off(a, weighting);
    EXPECT_LT(stick.n_active(), m.mesh.n_x / 2 + 1) << "some wavenumbers retired";
    // ... and left the step's arrays, whose narrowed rows the agreement above was reconstructed from.
    EXPECT_LT(stick.array_width(), m.mesh.n_x / 2 + 1) << "the arrays narrowed";
    EXPECT_GE(stick.array_width(), stick.n_active());
    std::printf("active wavenumbers after %lld steps: %d of %d, arrays %d wide\n", static_cast<long long>(checked),
                stick.n_active(), m.mesh.n_x / 2 + 1, stick.array_width());
  }
}

}  // namespace
}  // namespace slidewave

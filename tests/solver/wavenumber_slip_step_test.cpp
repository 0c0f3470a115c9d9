// The slip step in wavenumbers (model/stick_phase/wavenumber_slip_step.hpp, a prototype) against plain
// stepping: from the state a plain run of simulate() reaches a few steps after its first slip, N slip steps
// both ways with the same contact solve. The plain reference (model/stick_phase/plain_slip_step.hpp) is first
// checked to be simulate()'s loop bit for bit.
#include <gtest/gtest.h>

#include <Eigen/Dense>
#include <algorithm>
#include <atomic>
#include <cstdio>

#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "model/stick_phase/plain_slip_step.hpp"
#include "model/stick_phase/wavenumber_slip_step.hpp"
#include "test_support.hpp"

namespace slidewave {
namespace {

/// Captures the state `after` steps past the first slip and `after + more` steps past it, then stops the run.
class AfterFirstSlip : public RunObserver {
 public:
  AfterFirstSlip(std::int64_t after, std::int64_t more) : after_(after), more_(more) {}
  void after_step(RunRecord& record, const Capture& capture) override {
    const auto& sweeps = record.global.contact_iterations;
    const std::int64_t step = static_cast<std::int64_t>(sweeps.size()) - 1;
    if (first_slip < 0 && step > 0 && sweeps.back() > 0) first_slip = step;
    if (first_slip < 0) return;
    if (step == first_slip + after_) start = capture();
    if (step == first_slip + after_ + more_) {
      end = capture();
      stop = true;
    }
  }
  void at_end(RunRecord&, const Capture&) override {}
  std::atomic<bool> stop{false};
  std::int64_t first_slip = -1;
  StateArrays start, end;

 private:
  std::int64_t after_, more_;
};

double max_abs(const Eigen::VectorXd& x) { return x.lpNorm<Eigen::Infinity>(); }

TEST(WavenumberSlipStep, StepsThePlainSlipStepToRoundOff) {
  constexpr std::int64_t kAfter = 3, kSteps = 40;
  LayerModel m(testing::make_config({{"mesh", {{"elements_per_H", 16}}}, {"time", {{"t_end", 1000.0}}}}));
  m.steps_in_wavenumbers = false;
  AfterFirstSlip observer(kAfter, kSteps);
  const RunRecord record = simulate(m, {}, &observer.stop, nullptr, &observer);
  ASSERT_GT(observer.first_slip, 100) << "the paper case sticks for a while";
  ASSERT_FALSE(observer.end.reals.empty()) << "the run reached first slip + " << kAfter + kSteps;
  const LoopState start = captured_loop_state(m, observer.start);

  // The reference is simulate()'s loop, bit for bit.
  PlainSlipStep plain(m, record.u_x_preshear);
  plain.start(start);
  for (std::int64_t k = 0; k < kSteps; ++k) plain.step();
  const LoopState loop_end = captured_loop_state(m, observer.end);
  EXPECT_TRUE(plain.state().dynamics.u == loop_end.dynamics.u);
  EXPECT_TRUE(plain.state().dynamics.r == loop_end.dynamics.r);
  EXPECT_TRUE(plain.state().contact == loop_end.contact);

  plain.start(start);
  const WavenumberBlocks blocks(m);
  WavenumberSlipStep modes(m, blocks, record.u_x_preshear, plain.settings(), plain.friction());
  modes.start(start);
  LoopState rebuilt = start;
  // The round-off model of the bound. Each way of stepping computes u(n+1) by backward-stable solves, so a
  // step adds a few ulps of the displacement scale to their difference, and the HHT map does not amplify it
  // (spectral radius <= 1): after k steps at most 10 k eps max|u|. The velocity's round-off is that of a
  // difference of displacements (not of v: V0 dt is ~1e-5 of u): dt v gains dt^2 (gamma a(n+1) + (1-gamma) a(n))
  // with dt^2 a = (u(n+1) - u~) / beta, so its bound is that of u over beta. The reactions are r = -W^-1 q: a
  // displacement difference dq moves them by at most ||W^-1||_inf |dq|.
  const double eps = 0x1p-52, dt = m.d.dt, beta = HHTCoefficients(m.config.time.hht_alpha, dt).beta;
  const double W_inverse_norm = plain.delassus().inverse().cwiseAbs().rowwise().sum().maxCoeff();
  int slipping_steps = 0;
  double worst_u = 0, worst_v = 0, worst_r = 0;  // difference / its bound
  for (std::int64_t k = 1; k <= kSteps; ++k) {
    const GaussSeidelReport a = plain.step(), b = modes.step();
    ASSERT_TRUE(a.converged && b.converged);
    modes.reconstruct(rebuilt);
    const HHTState &x = plain.state().dynamics, &y = rebuilt.dynamics;
    const double u_bound = 10 * k * eps * max_abs(x.u), v_bound = u_bound / beta, r_bound = W_inverse_norm * u_bound;
    const double du = max_abs(x.u - y.u), dv = dt * max_abs(x.v - y.v), dr = max_abs(x.r - y.r);
    const bool slipping =
        std::count(plain.state().contact.begin(), plain.state().contact.end(), ContactState::slip) > 0;
    slipping_steps += slipping;
    std::printf(
        "[slip step %2lld] sweeps %2d / %2d%s: against max|u|: u %.1e, dt v %.1e; against max|r|: r %.1e; "
        "against the bounds: %.2f %.2f %.2f\n",
        static_cast<long long>(k), a.iterations, b.iterations, slipping ? "" : " (all stick)", du / max_abs(x.u),
        dv / max_abs(x.u), dr / max_abs(x.r), du / u_bound, dv / v_bound, dr / r_bound);
    EXPECT_TRUE(plain.state().contact == rebuilt.contact) << "step " << k;
    worst_u = std::max(worst_u, du / u_bound);
    worst_v = std::max(worst_v, dv / v_bound);
    worst_r = std::max(worst_r, dr / r_bound);
  }
  EXPECT_GT(slipping_steps, 0) << "the steps compared slip";
  std::printf("[slip steps in wavenumbers vs plain, %lld steps] worst against the bounds: u %.2f, dt v %.2f, r %.2f\n",
              static_cast<long long>(kSteps), worst_u, worst_v, worst_r);
  EXPECT_LT(worst_u, 1.0);
  EXPECT_LT(worst_v, 1.0);
  EXPECT_LT(worst_r, 1.0);
}

// The lanes' W (from their responses to a unit load on contact node 0) is the plain step's w C K_eff^-1 C^T
// (from its K_eff factorization) to round-off, and block-circulant and symmetric as the contact solver needs.
TEST(WavenumberSlipStep, ItsDelassusOperatorIsThePlainOne) {
  for (const char* weighting : {"alpha", "end"}) {
    const LayerModel m(
        testing::make_config({{"mesh", {{"elements_per_H", 8}}}, {"time", {{"contact_weighting", weighting}}}}));
    const PlainSlipStep plain(m, 0.0);
    const WavenumberBlocks blocks(m);
    const WavenumberSlipStep modes(m, blocks, 0.0, plain.settings(), plain.friction());
    const Eigen::MatrixXd &W = modes.delassus(), &W_plain = plain.delassus();
    const double scale = W_plain.cwiseAbs().maxCoeff();
    const double difference = (W - W_plain).cwiseAbs().maxCoeff() / scale;
    std::printf("[W from the lanes vs from K_eff, %s weighting] %.2e of its largest entry\n", weighting, difference);
    EXPECT_LT(difference, 1e-13);
    EXPECT_TRUE(W == W.transpose());
    const int n = m.mesh.n_contact();
    for (int i = 0; i < n; ++i)  // block-circulant: block (i, k) depends on i - k only
      EXPECT_TRUE(W.block(2 * i, 0, 2, 2) == W.block(2 * ((i + 1) % n), 2, 2, 2)) << i;
  }
}

}  // namespace
}  // namespace slidewave

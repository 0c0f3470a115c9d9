// Cost of a slip step: simulate()'s plain step (model/stick_phase/plain_slip_step.hpp: the HHT step on the
// block-circulant split solver, two full FFTs per step) against the prototype that keeps the state in
// wavenumbers (model/stick_phase/wavenumber_slip_step.hpp: band solves per lane, only the two contact rows
// transformed), from the same state a few steps after the first slip, with the same contact solve. A timed
// program (not a test). Times are CPU seconds of the thread per step, split into free solve, contact solve and
// correction, best of --repeats runs of --steps steps (best by the total). Usage: slidewave_bench_slip
// [--n 64 128] [--lambda 2] [--steps 200] [--after 5] [--repeats 3] [--nu 0.2] [--f 1.5] [--t-end 1000]
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "mesh_options.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "model/stick_phase/plain_slip_step.hpp"
#include "model/stick_phase/wavenumber_slip_step.hpp"
#include "thread_cpu_time.hpp"

namespace {

using slidewave::bench::cpu_seconds;

/// Keeps the state `after` steps past the first slip and stops the run there.
class AfterFirstSlip : public slidewave::RunObserver {
 public:
  explicit AfterFirstSlip(std::int64_t after) : after_(after) {}
  void after_step(slidewave::RunRecord& record, const Capture& capture) override {
    const auto& sweeps = record.global.contact_iterations;
    const std::int64_t step = static_cast<std::int64_t>(sweeps.size()) - 1;
    if (first_slip < 0 && step > 0 && sweeps.back() > 0) first_slip = step;
    if (first_slip >= 0 && step == first_slip + after_) {
      start = capture();
      stop = true;
    }
  }
  void at_end(slidewave::RunRecord&, const Capture&) override {}
  std::atomic<bool> stop{false};
  std::int64_t first_slip = -1;
  slidewave::StateArrays start;

 private:
  std::int64_t after_;
};

/// Milliseconds per step of the three parts, and the contact sweeps.
struct Cost {
  double free = 0, contact = 0, correction = 0;
  long sweeps = 0;
  double total() const { return free + contact + correction; }
};

/// The best (by total) of `repeats` runs of `steps` steps of `stepper` from `start`.
template <class Stepper>
Cost time_steps(Stepper& stepper, const slidewave::LoopState& start, int steps, int repeats) {
  Cost best;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    stepper.start(start);
    Cost run;
    for (int k = 0; k < steps; ++k) {
      const double t0 = cpu_seconds();
      stepper.solve_free();
      const double t1 = cpu_seconds();
      run.sweeps += stepper.solve_contact().iterations;
      const double t2 = cpu_seconds();
      stepper.correct();
      const double t3 = cpu_seconds();
      run.free += t1 - t0;
      run.contact += t2 - t1;
      run.correction += t3 - t2;
    }
    for (double* part : {&run.free, &run.contact, &run.correction}) *part *= 1e3 / steps;
    if (repeat == 0 || run.total() < best.total()) best = run;
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> resolutions;
  std::vector<double> lambdas;
  slidewave::bench::CaseOptions case_options;
  int steps = 200, after = 5, repeats = 3;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (slidewave::bench::mesh_option(option, argc, argv, i, resolutions, lambdas)) continue;
    if (i + 1 >= argc) {
      std::fprintf(stderr,
                   "usage: slidewave_bench_slip [--n N...] [--lambda L...] [--steps N] [--after K] [--repeats R] "
                   "[--nu NU] [--f F] [--t-end T]\n");
      return 2;
    }
    const double value = std::atof(argv[++i]);
    if (case_options.take(option, value)) continue;
    if (option == "--steps" && value >= 1)
      steps = static_cast<int>(value);
    else if (option == "--after" && value >= 0)
      after = static_cast<int>(value);
    else if (option == "--repeats" && value >= 1)
      repeats = static_cast<int>(value);
    else {
      std::fprintf(stderr, "bad option %s %s (--steps, --repeats >= 1, --after >= 0)\n", option.c_str(), argv[i]);
      return 2;
    }
  }
  if (resolutions.empty()) resolutions = {64, 128};
  if (lambdas.empty()) lambdas = {2};
  std::printf(
      "| case | first slip | plain ms/step: total | free | contact | correction | wavenumbers: total | free | "
      "contact | correction | speed-up | sweeps/step plain, wavenumbers | after the steps: |du_c|, |dr| / max |");
  std::printf("\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---|\n");
  for (const double lambda_over_H : lambdas)
    for (const int n : resolutions) {
      slidewave::RunConfig config =
          slidewave::bench::bench_config(n, lambda_over_H, case_options.nu, case_options.f, case_options.t_end);
      config.output.progress = slidewave::ProgressMode::never;
      const slidewave::LayerModel model(config);  // the stick phase in wavenumbers gets there fast
      AfterFirstSlip observer(after);
      const slidewave::RunRecord record = slidewave::simulate(model, {}, &observer.stop, nullptr, &observer);
      if (observer.start.reals.empty()) {
        std::printf("| H/%d, lambda %gH | no slip before t_end |\n", n, lambda_over_H);
        continue;
      }
      const slidewave::LoopState start = slidewave::captured_loop_state(model, observer.start);
      slidewave::PlainSlipStep plain(model, record.u_x_preshear);
      const slidewave::WavenumberBlocks blocks(model);
      slidewave::WavenumberSlipStep modes(model, blocks, record.u_x_preshear, plain.settings(), plain.friction());
      const Cost a = time_steps(plain, start, steps, repeats);
      const Cost b = time_steps(modes, start, steps, repeats);
      const Eigen::VectorXd& u_plain = plain.state().dynamics.u;
      const double du = (u_plain.head(model.n_contact_dofs) - modes.contact_displacement()).lpNorm<Eigen::Infinity>() /
                        u_plain.head(model.n_contact_dofs).lpNorm<Eigen::Infinity>();
      const double dr = (plain.state().dynamics.r - modes.reactions()).lpNorm<Eigen::Infinity>() /
                        plain.state().dynamics.r.lpNorm<Eigen::Infinity>();
      std::printf(
          "| H/%d, lambda %gH, %d steps from first slip + %d | %lld | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | %.4f | "
          "%.4f | %.2fx | %.1f, %.1f | %.1e, %.1e |\n",
          n, lambda_over_H, steps, after, static_cast<long long>(observer.first_slip), a.total(), a.free, a.contact,
          a.correction, b.total(), b.free, b.contact, b.correction, a.total() / b.total(),
          static_cast<double>(a.sweeps) / steps, static_cast<double>(b.sweeps) / steps, du, dr);
      std::fflush(stdout);
    }
  return 0;
}

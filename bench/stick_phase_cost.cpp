// Cost of a stick step: plain stepping (simulate(), the HHT step with the exact all-stick contact solve,
// run until its first slip) against the stick phase in wavenumbers (model/stick_phase/stick_phase.hpp,
// docs/stick-phase.md) from the same seeded state at t = 0, with and without retirement; the number of
// active wavenumbers over the stick phase; the step of the first slip of both. A timed program (not a
// test). Times are CPU seconds of the thread (plain: simulate()'s steps 1 .. first slip - 1, rows recorded;
// wavenumbers: step() with the kinetic and elastic energy of every step). Usage: slidewave_bench_stick [--n 64 128]
// [--lambda 2] [--t-end 1000] [--nu 0.2] [--f 1.5]
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>
#include <vector>

#include "contact/friction_law.hpp"
#include "mesh_options.hpp"
#include "model/layer_model.hpp"
#include "model/loop_state_arrays.hpp"
#include "model/simulation.hpp"
#include "model/stick_phase/plain_slip_step.hpp"
#include "model/stick_phase/stick_phase.hpp"
#include "thread_cpu_time.hpp"

namespace {

using slidewave::bench::cpu_seconds;

/// Keeps the state at t = 0 and stops the run at its first slip.
class UntilFirstSlip : public slidewave::RunObserver {
 public:
  void after_step(slidewave::RunRecord& record, const Capture& capture) override {
    const std::int64_t step = static_cast<std::int64_t>(record.global.t.size()) - 1;
    if (step == 0) {
      start = capture();
      cpu_start = cpu_seconds();
    }
    if (step > 0 && record.global.contact_iterations.back() > 0 && first_slip < 0) {
      first_slip = step;
      stop = true;
    }
    if (first_slip < 0) cpu_stick = cpu_seconds() - cpu_start;  // steps 1 .. first_slip - 1 (all stick)
  }
  void at_end(slidewave::RunRecord&, const Capture&) override {}
  slidewave::StateArrays start;
  std::atomic<bool> stop{false};
  std::int64_t first_slip = -1;
  double cpu_start = 0, cpu_stick = 0;
};

struct StickRun {
  std::int64_t first_slip = -1;
  std::vector<double> step_seconds;
  std::vector<int> active;
  std::vector<Eigen::VectorXd> reactions;  ///< of every step
};

/// The stick phase from `start` until its all-stick reactions leave a bound; kinetic and elastic energy
/// of every step as the recorder would ask for them.
StickRun run_stick(const slidewave::LayerModel& m, double u_x_top, const slidewave::LoopState& start,
                   double tolerance) {
  const slidewave::WavenumberBlocks blocks(m);
  slidewave::StickPhase stick(m, blocks, u_x_top, tolerance);
  const auto law = slidewave::make_friction_law(m.config.friction);
  const auto bounds = law->bounds(start.friction);
  stick.start(start);
  StickRun run;
  double sink = 0;
  for (;;) {
    const double t0 = cpu_seconds();
    const bool stuck = stick.step(*bounds);
    if (stuck) sink += stick.kinetic() + stick.elastic();
    run.step_seconds.push_back(cpu_seconds() - t0);
    run.active.push_back(stick.n_active());
    if (!stuck) break;
    run.reactions.push_back(stick.reactions());
  }
  run.first_slip = stick.step_count() + 1;
  if (sink == 12345.678) std::printf(" ");  // keeps the energies computed
  return run;
}

double mean_ms(const std::vector<double>& s, std::size_t from, std::size_t to) {
  to = std::min(to, s.size());
  if (from >= to) return 0;
  double sum = 0;
  for (std::size_t k = from; k < to; ++k) sum += s[k];
  return 1e3 * sum / static_cast<double>(to - from);
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> resolutions;
  std::vector<double> lambdas;
  slidewave::bench::CaseOptions case_options;
  for (int i = 1; i < argc; ++i) {
    const std::string option = argv[i];
    if (slidewave::bench::mesh_option(option, argc, argv, i, resolutions, lambdas)) continue;
    if (i + 1 >= argc) {
      std::fprintf(stderr, "usage: slidewave_bench_stick [--n N...] [--lambda L...] [--t-end T] [--nu NU] [--f F]\n");
      return 2;
    }
    if (!case_options.take(option, std::atof(argv[++i]))) {
      std::fprintf(stderr, "unknown option %s\n", option.c_str());
      return 2;
    }
  }
  if (resolutions.empty()) resolutions = {64, 128};
  if (lambdas.empty()) lambdas = {2};
  std::printf(
      "| case | plain ms/step | wavenumbers ms/step: all steps | first 50 | last 200 | no retirement | "
      "speed-up (all steps) | first slip plain / wavenumbers | active wavenumbers at steps 1, 50, 100, 200, 400, 800, "
      "last | reactions: retiring - not, max / max r |\n");
  std::printf("|---|---:|---:|---:|---:|---:|---:|---|---|---:|\n");
  for (const double lambda_over_H : lambdas)
    for (const int n : resolutions) {
      slidewave::RunConfig config =
          slidewave::bench::bench_config(n, lambda_over_H, case_options.nu, case_options.f, case_options.t_end);
      config.output.progress = slidewave::ProgressMode::never;
      slidewave::LayerModel model(config);
      model.steps_in_wavenumbers = false;  // plain stepping, as before the stick phase was wired
      UntilFirstSlip plain;
      const slidewave::RunRecord record = slidewave::simulate(model, {}, &plain.stop, nullptr, &plain);
      const double plain_ms = 1e3 * plain.cpu_stick / static_cast<double>(plain.first_slip - 1);
      const slidewave::LoopState start = slidewave::captured_loop_state(model, plain.start);
      const StickRun retiring = run_stick(model, record.u_x_preshear, start, slidewave::StickPhase::kRetireTolerance);
      const StickRun full = run_stick(model, record.u_x_preshear, start, 0.0);
      const std::size_t steps = retiring.step_seconds.size();
      const double all = mean_ms(retiring.step_seconds, 0, steps);
      // What retiring changed: the reactions of every step, against the largest reaction.
      double retire_change = 0, r_max = 0;
      for (std::size_t k = 0; k < std::min(retiring.reactions.size(), full.reactions.size()); ++k) {
        retire_change = std::max(retire_change, (retiring.reactions[k] - full.reactions[k]).lpNorm<Eigen::Infinity>());
        r_max = std::max(r_max, full.reactions[k].lpNorm<Eigen::Infinity>());
      }
      std::string active;
      for (std::size_t k : {std::size_t{0}, std::size_t{49}, std::size_t{99}, std::size_t{199}, std::size_t{399},
                            std::size_t{799}, steps - 1})
        if (k < steps) active += std::to_string(retiring.active[k]) + " ";
      std::printf(
          "| H/%d, lambda %gH (%d wavenumbers) | %.4f | %.4f | %.4f | %.4f | %.4f | %.1fx | %lld / %lld | %s| %.1e |\n",
          n, lambda_over_H, model.mesh.n_x / 2 + 1, plain_ms, all, mean_ms(retiring.step_seconds, 0, 50),
          mean_ms(retiring.step_seconds, steps > 200 ? steps - 200 : 0, steps),
          mean_ms(full.step_seconds, 0, full.step_seconds.size()), plain_ms / all,
          static_cast<long long>(plain.first_slip), static_cast<long long>(retiring.first_slip), active.c_str(),
          retire_change / r_max);
      std::fflush(stdout);
    }
  return 0;
}

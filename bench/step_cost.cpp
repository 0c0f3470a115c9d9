// Per-step cost of slidewave runs: the stick phase (stick_ms, per step taken in wavenumbers while every
// node sticks, model/stick_phase/), then per step after it: predictor, free solve, contact, correction,
// diagnostics and output (with --stream), steps/s, the ratio of one step to one K_eff solve with the
// run's solver (step/slv, the machine-independent figure), and the peak resident memory of the process
// so far (getrusage; run one case per process for the peak of that case alone).
// On the spectral path the "free solve" is the forward half (FFT, sweeps, contact rows) and the
// "correction" the loaded half plus the Newmark update.
// A timed program (not a test). Usage: slidewave_bench_step [--n 32 64 128] [--lambda 2 4 6] [--t-end 1300]
//                                      [--nu 0.2] [--f 1.5] [--solver spectral|cholmod]
//                                      [--threads N] [--stream FOLDER [--checkpoint-interval S]]
//                                      [--substrate E_RATIO]
// --substrate adds a deformable substrate of the layer's size (H_s = H, its nu and rho, E_s = E_RATIO E;
// docs/substrate.md).
// --threads sets numerics.threads (the thread team of one spectral solve; CHOLMOD's BLAS is left as the
// process starts). sweeps/step is the mean count of Gauss–Seidel sweeps per step (0 on a step solved by the
// exact all-stick solution, contact/all_stick.hpp).
// --stream writes the run as `slidewave run` does (RUN.partial.h5 streamed, checkpoints every S s of
// wall time, RUN.h5 put in place; io/run_session.hpp) into FOLDER/bench_H<n>.h5, so that ms/step
// includes the output; without it nothing is written (the rows stay in memory).
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "fem/stencil_product.hpp"
#include "io/run_session.hpp"
#include "mesh_options.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"
#include "time/hht_stepper.hpp"

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/// Median-free simple estimate: average wall time of repeated solves with the K_eff factor.
double one_solve_seconds(const slidewave::LayerModel& model) {
  const slidewave::HHTCoefficients hht(model.config.time.hht_alpha, model.d.dt);
  const slidewave::PartitionedSystem system = model.partitioned();
  const auto factor = model.factorize(slidewave::effective_matrix(hht, system));
  Eigen::VectorXd b = Eigen::VectorXd::Ones(model.n_free), x(model.n_free);
  const int repeats = 200;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i) {
    factor->solve_into(b, x);
    b = x + Eigen::VectorXd::Ones(model.n_free);
  }
  return seconds_since(start) / repeats;
}

/// Average wall time of the product K u (all DOFs) that the correction does once per step: the matrix-free
/// stencil product the stepper uses on the periodic layer (fem/stencil_product.hpp).
double stiffness_product_seconds(const slidewave::LayerModel& model) {
  const slidewave::StencilProduct stencil(model.K(), model.mesh.n_x);
  Eigen::VectorXd u = Eigen::VectorXd::Ones(model.K().cols()), Ku(model.K().rows());
  const int repeats = 200;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < repeats; ++i) {
    stencil.apply(u, Ku);
    u(i % u.size()) += Ku(0) * 1e-300;  // keeps the product from being hoisted
  }
  return seconds_since(start) / repeats;
}

/// Peak resident set size of this process so far (MB).
double peak_rss_mb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss / 1024.0;  // kB on Linux
}

/// Forwards to the run session and adds up the wall time spent in it: the cost of the output (rows
/// drained to RUN.partial.h5, checkpoints, the final close and rename), measured apart from the step.
class TimedObserver : public slidewave::RunObserver {
 public:
  explicit TimedObserver(slidewave::RunObserver& inner) : inner_(inner) {}
  void setup_done() override {
    const auto start = std::chrono::steady_clock::now();
    inner_.setup_done();  // the session creates its files here
    seconds += seconds_since(start);
  }
  void after_step(slidewave::RunRecord& record, const Capture& capture) override {
    const auto start = std::chrono::steady_clock::now();
    inner_.after_step(record, capture);
    seconds += seconds_since(start);
  }
  void at_end(slidewave::RunRecord& record, const Capture& capture) override {
    const auto start = std::chrono::steady_clock::now();
    inner_.at_end(record, capture);
    seconds += seconds_since(start);
  }
  double seconds = 0;

 private:
  slidewave::RunObserver& inner_;
};

}  // namespace

int main(int argc, char** argv) {
  std::vector<int> resolutions;
  std::vector<double> lambdas;
  double t_end = 1300, nu = 0.2, f = 1.5;
  auto solver = slidewave::LinearSolverKind::spectral;
  std::string solver_name = "spectral";
  std::string stream_folder;
  double checkpoint_interval = 300;
  int threads = 1;
  double substrate_ratio = 0;  // 0: the rigid flat
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (slidewave::bench::mesh_option(a, argc, argv, i, resolutions, lambdas)) continue;
    if (a == "--t-end" && i + 1 < argc) {
      t_end = std::atof(argv[++i]);
    } else if (a == "--nu" && i + 1 < argc) {
      nu = std::atof(argv[++i]);
    } else if (a == "--f" && i + 1 < argc) {
      f = std::atof(argv[++i]);
    } else if (a == "--stream" && i + 1 < argc) {
      stream_folder = argv[++i];
    } else if (a == "--substrate" && i + 1 < argc && std::atof(argv[i + 1]) > 0) {
      substrate_ratio = std::atof(argv[++i]);
    } else if (a == "--threads" && i + 1 < argc && std::atoi(argv[i + 1]) >= 1) {
      threads = std::atoi(argv[++i]);
    } else if (a == "--checkpoint-interval" && i + 1 < argc) {
      checkpoint_interval = std::atof(argv[++i]);
    } else if (a == "--solver" && i + 1 < argc &&
               (solver_name = argv[++i], solver_name == "spectral" || solver_name == "cholmod")) {
      solver = solver_name == "cholmod" ? slidewave::LinearSolverKind::cholmod : slidewave::LinearSolverKind::spectral;
    } else {
      std::fprintf(stderr,
                   "usage: %s [--n N...] [--lambda L...] [--t-end T] [--nu NU] [--f F] [--solver spectral|cholmod] "
                   "[--threads N] [--stream FOLDER [--checkpoint-interval S]] [--substrate E_RATIO]\n",
                   argv[0]);
      return 2;
    }
  }
  if (resolutions.empty()) resolutions = {32, 64, 128};
  if (lambdas.empty()) lambdas = {2};

  std::printf("# nu=%g f=%g, t_end=%g s (stage 3), linear solver %s, %d thread%s, output %s\n", nu, f, t_end,
              solver_name.c_str(), threads, threads == 1 ? "" : "s",
              stream_folder.empty()
                  ? "none (in memory)"
                  : ("streamed, checkpoints every " + std::to_string(checkpoint_interval) + " s").c_str());
  std::printf("%6s %5s %8s %9s | %9s %9s %9s %9s %9s %9s %9s | %9s %9s %9s %8s %8s %7s %8s %8s %8s\n", "H/h", "lam/H",
              "n_dofs", "steps", "stick_ms", "predict", "free_slv", "contact", "correct", "diagnost", "output",
              "ms/step", "steps/s", "1solve_ms", "Ku_ms", "step/slv", "sweeps", "setup_s", "total_s", "peak_MB");
  for (double lambda_over_H : lambdas)
    for (int n : resolutions) {
      slidewave::RunConfig config = slidewave::bench::bench_config(n, lambda_over_H, nu, f, t_end);
      config.numerics.linear_solver = solver;
      config.numerics.threads = threads;
      if (substrate_ratio > 0)
        config.substrate =
            slidewave::SubstrateConfig{substrate_ratio * config.material.E, nu, config.material.rho, config.geometry.H};
      const slidewave::LayerModel model(config);
      config.output.checkpoint_interval = checkpoint_interval;
      slidewave::StepProfile profile;
      const auto start = std::chrono::steady_clock::now();
      std::unique_ptr<slidewave::RunSession> session;
      if (!stream_folder.empty())
        session = std::make_unique<slidewave::RunSession>(stream_folder + "/bench_H" + std::to_string(n) + ".h5",
                                                          config, slidewave::Provenance{"slidewave_bench_step", ""},
                                                          false, std::cerr);
      std::unique_ptr<TimedObserver> timed;
      if (session) timed = std::make_unique<TimedObserver>(*session);
      slidewave::simulate(model, {}, nullptr, &profile, timed.get());
      const double output_seconds = timed ? timed->seconds : 0;
      const double total = seconds_since(start);
      const double solve = one_solve_seconds(model);
      // Stick-phase steps (model/stick_phase/) per stick step, the others per step after it.
      // (At least one: a run that ends inside the stick phase has no step after it.)
      const std::int64_t plain_steps = std::max<std::int64_t>(1, profile.steps - profile.stick_phase_steps);
      const double per_step = (total - profile.setup - profile.stick_phase) / plain_steps;
      const auto ms = [&](double s) { return 1e3 * s / plain_steps; };
      const double stick_ms = profile.stick_phase_steps ? 1e3 * profile.stick_phase / profile.stick_phase_steps : 0;
      std::printf(
          "%6d %5g %8d %9lld | %9.3f %9.3f %9.3f %9.3f %9.3f %9.3f %9.4f | %9.3f %9.0f %9.3f %8.3f %8.2f %7.2f %8.2f "
          "%8.2f "
          "%8.1f\n",
          n, lambda_over_H, model.mesh.n_dofs(), static_cast<long long>(profile.steps), stick_ms, ms(profile.predictor),
          ms(profile.free_solve), ms(profile.contact), ms(profile.correction), ms(profile.diagnostics),
          ms(output_seconds), 1e3 * per_step, 1 / per_step, 1e3 * solve, 1e3 * stiffness_product_seconds(model),
          per_step / solve, static_cast<double>(profile.contact_sweeps) / profile.steps, profile.setup, total,
          peak_rss_mb());
      std::fflush(stdout);
    }
  return 0;
}

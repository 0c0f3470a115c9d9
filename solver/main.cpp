// slidewave: one run of the periodic elastic layer sliding on a rigid flat under Coulomb friction
// (Yastrebov 2016). Sample runs (CI executes the first two):
//   slidewave check study/examples/paper_nu0.2_f1.5.json
//   slidewave run study/examples/paper_nu0.2_f1.5.json -o run.h5
//   slidewave --version
// Exit codes: 0 success, 1 run failed (output flushed and marked incomplete), 2 invalid input (or a
// checkpoint of another run with --resume), 3 interrupted (RUN.partial.h5 and RUN.checkpoint.h5 kept),
// 4 I/O error (the message names the file and the reason).
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "config/run_config.hpp"
#include "git_version.hpp"
#include "io/progress.hpp"
#include "io/hdf5_support.hpp"
#include "io/run_session.hpp"
#include "model/layer_model.hpp"
#include "model/simulation.hpp"

// Thread counts of the BLAS and OpenMP under CHOLMOD, set when those libraries are linked (weak symbols:
// absent libraries are fine). One thread by default: a study runs one process per core, and fixed
// thread counts keep the results bit-identical from run to run.
extern "C" void openblas_set_num_threads(int) __attribute__((weak));
extern "C" void omp_set_num_threads(int) __attribute__((weak));

namespace {

std::atomic<bool> g_stop{false};
void on_signal(int) { g_stop = true; }

std::string read_file(const std::string& path) {
  std::ifstream in(path);
  std::stringstream buffer;
  buffer << in.rdbuf();
  return buffer.str();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace slidewave;
  h5::skip_library_cleanup_at_exit();  // before any HDF5 call: see io/hdf5_support.hpp

  // 1. Parse options.
  CLI::App app{"slidewave: elastodynamic sliding of a periodic layer on a rigid flat under Coulomb friction"};
  app.set_version_flag("--version", std::string("slidewave ") + kVersion + " (git " + kGitCommit + ")");
  app.require_subcommand(1);
  std::string config_path, output_path;
  auto* run = app.add_subcommand("run", "compute one run and write RUN.h5");
  run->add_option("config", config_path, "run configuration (JSON)")->required();
  run->add_option("-o,--output", output_path, "output HDF5 file")->required();
  int threads = 1;
  run->add_option("--threads", threads, "threads of the BLAS/OpenMP under CHOLMOD")->check(CLI::Range(1, 256));
  bool resume = false;
  run->add_flag("--resume", resume,
                "continue from RUN.checkpoint.h5 when it was written for this configuration and build "
                "(without one: start from the beginning)");
  auto* check = app.add_subcommand("check", "validate a configuration and print it resolved");
  check->add_option("config", config_path, "run configuration (JSON)")->required();
  CLI11_PARSE(app, argc, argv);

  // 2. Read and validate the configuration (every problem at once, exit 2, nothing written).
  RunConfig config;
  try {
    config = load_run_config(config_path);
  } catch (const ConfigError& e) {
    std::cerr << "slidewave: " << config_path << ": " << e.what();
    return 2;
  }
  if (check->parsed()) {
    std::cout << config.to_json().dump(2) << "\n";
    return 0;
  }

  // 3. Build the model and run the three stages.
  if (openblas_set_num_threads) openblas_set_num_threads(threads);
  if (omp_set_num_threads) omp_set_num_threads(threads);
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  std::string call;
  for (int i = 0; i < argc; ++i) call += (i ? " " : "") + std::string(argv[i]);
  std::unique_ptr<RunSession> session;
  try {
    // The output is streamed to RUN.partial.h5 and put in place at the end (io/run_session.hpp).
    session = std::make_unique<RunSession>(output_path, config, Provenance{call, read_file(config_path)}, resume,
                                           std::cerr);
    const LayerModel model(config);
    const ProgressPrinter printer(config.output.progress, model.mesh.n_contact());
    const auto progress = [&](double t, double t_end, double rate, double tn, int n_slip) {
      printer.report(t, t_end, rate, tn, n_slip, model.d.dt);
    };
    const RunRecord record = simulate(model, progress, &g_stop, nullptr, session.get());
    printer.finish();

    // 4. Say how the run ended.
    if (record.end_reason == "interrupted") {
      std::cerr << "slidewave: run interrupted at step " << record.n_steps_done << ", t = "
                << record.n_steps_done * model.d.dt << " s; " << output_path << " not written; "
                << session->partial_path() << " holds what was computed (complete = 0) and "
                << session->checkpoint_path() << " continues it with --resume\n";
      return 3;
    }
    if (!record.complete) {
      std::cerr << "slidewave: run ended early (" << record.end_reason << ") at step " << record.n_steps_done
                << ", t = " << record.n_steps_done * model.d.dt << " s; " << output_path
                << " holds what was computed and is marked complete = 0\n";
      return 1;
    }
  } catch (const ResumeRefused& e) {
    std::cerr << "slidewave: " << e.what() << "\n";
    return 2;
  } catch (const IoError& e) {
    const std::string kept = session ? session->abandon() : "";
    std::cerr << "slidewave: error: " << e.what() << (kept.empty() ? "" : "; " + kept) << "\n";
    return 4;
  } catch (const std::exception& e) {
    const std::string kept = session ? session->abandon() : "";
    std::cerr << "slidewave: error: " << e.what() << (kept.empty() ? "" : "; " + kept) << "\n";
    return 1;
  }
  return 0;
}

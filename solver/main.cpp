// slidewave: one run of the periodic elastic layer sliding on a rigid flat under Coulomb friction
// (Yastrebov 2016). Sample runs:
//   slidewave check study/examples/paper_nu0.2_f1.5_H32.json     (validate, print the resolved config)
//   slidewave run study/examples/paper_nu0.2_f1.5_H32.json -o run.h5
//   slidewave keys [--json]                                      (the key table, docs/contracts.md section 1)
//   slidewave --version
// Exit codes of `run` (docs/contracts.md):
//   0 complete (end_reason t_end or stop_after_opening): RUN.h5 written, complete = 1;
//   1 contact failure (contact_not_converged): RUN.h5 written with complete = 0;
//   2 bad input (config key or value, CLI usage, step count over time.max_steps, unusable output
//     path, a mesh whose memory estimate exceeds the available memory): nothing written;
//   3 interrupted (SIGINT/SIGTERM): RUN.h5 neither created nor touched, what was computed is in
//     RUN.partial.h5 (complete = 0, end_reason interrupted), RUN.checkpoint.h5 continues it (--resume);
//     during the setup, before any file is created: at once, nothing written;
//   2 also: --resume with a checkpoint of another configuration or build (nothing changed), and an
//     output another run is writing (it holds RUN.h5.lock; nothing changed);
//   4 I/O or internal error (unwritable file, HDF5 failure, ...): the message names the cause.
#include <CLI/CLI.hpp>
#include <atomic>
#include <csignal>
#include <iostream>
#include <memory>

#include "config/config_keys.hpp"
#include "config/run_config.hpp"
#include "config/step_advice.hpp"
#include "git_version.hpp"
#include "io/available_memory.hpp"
#include "io/hdf5_support.hpp"
#include "io/huge_page_heap.hpp"
#include "io/output_lock.hpp"
#include "io/output_path.hpp"
#include "io/progress.hpp"
#include "io/run_session.hpp"
#include "io/run_signals.hpp"
#include "model/layer_model.hpp"
#include "model/memory_estimate.hpp"
#include "model/simulation.hpp"

// The thread count of OpenMP (the spectral solves' team), set when it is linked (a weak symbol: absent is fine).
// One thread by default: a study runs one process per core. (CHOLMOD's BLAS gets its count where CHOLMOD is
// loaded, linalg/cholmod_library.hpp.)
extern "C" void omp_set_num_threads(int) __attribute__((weak));

namespace {

enum ExitCode { kComplete = 0, kContactFailure = 1, kBadInput = 2, kInterrupted = 3, kInternalError = 4 };

}  // namespace

int main(int argc, char** argv) {
  using namespace slidewave;
  h5::skip_library_cleanup_at_exit();  // before any HDF5 call: see io/hdf5_support.hpp

  // 1. Parse options (a usage error is bad input: exit 2; --help and --version exit 0).
  CLI::App app{"slidewave: elastodynamic sliding of a periodic layer on a rigid flat under Coulomb friction"};
  app.set_version_flag("--version", std::string("slidewave ") + kVersion + " (git " + kGitCommit + ")");
  app.require_subcommand(1);
  std::string config_path, output_path;
  auto* run = app.add_subcommand("run", "compute one run and write RUN.h5");
  run->add_option("config", config_path, "run configuration (JSON)")->required();
  run->add_option("-o,--output", output_path, "output HDF5 file")->required();
  int threads = 0;
  run->add_option("--threads", threads, "overrides numerics.threads (threads of this run's linear solves)");
  bool resume = false;
  run->add_flag("--resume", resume,
                "continue from RUN.checkpoint.h5 when it was written for this configuration and build "
                "(without one: start from the beginning)");
  auto* check = app.add_subcommand("check", "validate a configuration and print it resolved");
  check->add_option("config", config_path, "run configuration (JSON)")->required();
  auto* keys = app.add_subcommand("keys", "print the configuration keys (default: Markdown, docs/contracts.md)");
  bool keys_json = false, keys_markdown = false;
  auto* json_flag = keys->add_flag("--json", keys_json, "as JSON, one object per key");
  keys->add_flag("--markdown", keys_markdown, "as the Markdown section of docs/contracts.md")->excludes(json_flag);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    return app.exit(e) == 0 ? kComplete : kBadInput;
  }
  if (keys->parsed()) {
    std::cout << (keys_json ? config_keys_json().dump(2) + "\n" : config_keys_markdown());
    return kComplete;
  }

  // 2. Read the configuration bytes once and validate exactly those (every problem at once, exit 2,
  //    nothing written); the same bytes are recorded as /setup/config_input.
  RunConfig config;
  std::string config_input;
  try {
    config_input = read_config_bytes(config_path);
    nlohmann::json overrides = nlohmann::json::object();
    if (run->count("--threads")) overrides["numerics"]["threads"] = threads;
    config = parse_run_config_text(config_input, config_path, overrides);
  } catch (const ConfigError& e) {
    std::cerr << "slidewave: " << config_path << ": " << e.what();
    return kBadInput;
  }
  const MemoryEstimate memory = estimate_memory(config);
  const std::optional<std::string> advice = small_step_advice(config);
  if (check->parsed()) {
    std::cout << config.to_json().dump(2) << "\n";
    if (advice) std::cerr << "slidewave: " << config_path << ": " << *advice << "\n";
    std::cerr << "slidewave: memory estimate " << memory.describe() << "\n";
    return kComplete;
  }

  // 3. Check the output before any work: a run must not end in "cannot write", nor write or remove its
  //    input (every file it writes, removes or locks is compared with it).
  try {
    check_output_path(output_path, {config_path});
  } catch (const OutputPathError& e) {
    std::cerr << "slidewave: " << e.what() << "\n";
    return kBadInput;
  }

  // 4. Refuse a mesh that cannot fit in memory (exit 2, nothing written) before its setup would grow
  //    into it for minutes and end in std::bad_alloc or the OOM killer. From here on, stderr on a closed
  //    pipe must fail as EPIPE (and be silenced), not kill the run with SIGPIPE.
  std::signal(SIGPIPE, SIG_IGN);
  if (advice) std::cerr << "slidewave: " << config_path << ": " << *advice << "\n";
  const AvailableMemory available = available_memory();
  std::cerr << "slidewave: memory estimate " << memory.describe() << "; available " << bytes_text(available.bytes)
            << " (" << available.source << ")\n";
  if (memory.total() > available.bytes) {
    std::cerr << "slidewave: " << config_path << ": the run needs about " << bytes_text(memory.total())
              << ", more than the " << bytes_text(available.bytes) << " available (" << available.source
              << "); use a coarser mesh (mesh.elements_per_H) or a shorter period (geometry.lambda_over_H)\n";
    return kBadInput;
  }

  back_heap_with_huge_pages(memory.total());

  // 5. Claim the output before any file is created or truncated: a second run into it is refused. What
  //    a killed earlier run left under its own temporary names (its run id is in the lock file) goes.
  std::string call;
  for (int i = 0; i < argc; ++i) call += (i ? " " : "") + std::string(argv[i]);
  const Provenance provenance{call, config_input};
  std::unique_ptr<OutputLock> lock;
  try {
    lock = std::make_unique<OutputLock>(output_path, provenance.run_id, call);
    remove_temporaries_of(output_path, lock->previous_run_id());
  } catch (const OutputLocked& e) {
    std::cerr << "slidewave: " << e.what() << "\n";
    return kBadInput;
  } catch (const IoError& e) {
    std::cerr << "slidewave: error: " << e.what() << "\n";
    return kInternalError;
  }

  // 6. Build the model and run the three stages.
  if (omp_set_num_threads) omp_set_num_threads(config.numerics.threads);
  const std::atomic<bool>* stop = install_stop_handlers(kInterrupted, lock_path_for(output_path));
  std::unique_ptr<RunSession> session;
  try {
    // The output is streamed to RUN.partial.h5, created once the setup is done, and put in place at the
    // end (io/run_session.hpp); with --resume a checkpoint of this configuration and build is continued.
    session = std::make_unique<RunSession>(output_path, config, provenance, resume, std::cerr);
    SignalledRun observer(*session);
    const LayerModel model(config);
    const ProgressPrinter printer(config.output.progress, model.mesh.n_contact());
    const auto progress = [&](double t, double t_end, double rate, double tn, int n_slip) {
      printer.report(t, t_end, rate, tn, n_slip, model.d.dt);
    };
    const RunRecord record = simulate(model, progress, stop, nullptr, &observer);
    printer.finish();

    // 7. Say where the outcome went.
    if (record.complete) return kComplete;
    const bool interrupted = record.end_reason == "interrupted";
    std::cerr << "slidewave: run ended early (" << record.end_reason << ") at step " << record.n_steps_done
              << ", t = " << record.n_steps_done * model.d.dt << " s; "
              << (interrupted ? session->partial_path() : output_path)
              << " holds what was computed and is marked complete = 0"
              << (interrupted ? "; " + output_path + " was not touched; " + session->checkpoint_path() +
                                    " continues the run with --resume"
                              : std::string())
              << "\n";
    return interrupted ? kInterrupted : kContactFailure;
  } catch (const ResumeRefused& e) {
    std::cerr << "slidewave: " << e.what() << "\n";
    return kBadInput;
  } catch (const std::exception& e) {
    const std::string kept = session ? session->abandon() : "";
    std::cerr << "slidewave: error: " << e.what() << (kept.empty() ? "" : "; " + kept) << "\n";
    return kInternalError;
  }
}

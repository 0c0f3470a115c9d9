#include "io/run_signals.hpp"

#include <unistd.h>

#include <cstdlib>
#include <stdexcept>
#include <string>

namespace slidewave {
namespace {

std::atomic<bool> g_stop{false};
volatile std::sig_atomic_t g_files_open = 0;
volatile std::sig_atomic_t g_setup_exit_code = 3;
std::string g_lock_path;  // set before the handlers are installed, never changed after

void on_signal(int) {
  if (!g_files_open) {
    // Only async-signal-safe calls here: unlink(2) (the lock is still held), write(2) and _exit(2).
    if (!g_lock_path.empty()) ::unlink(g_lock_path.c_str());
    constexpr char message[] = "slidewave: interrupted during the setup; no file was written\n";
    [[maybe_unused]] const auto written = ::write(STDERR_FILENO, message, sizeof message - 1);
    ::_exit(g_setup_exit_code);
  }
  g_stop = true;
}

}  // namespace

const std::atomic<bool>* install_stop_handlers(int setup_exit_code, const std::string& lock_path) {
  g_setup_exit_code = setup_exit_code;
  g_lock_path = lock_path;
  std::signal(SIGINT, on_signal);
  std::signal(SIGTERM, on_signal);
  return &g_stop;
}

SignalledRun::SignalledRun(RunObserver& inner) : inner_(inner) {
  const char* at_step = std::getenv("SLIDEWAVE_TEST_SIGNAL_AT_STEP");
  if (!at_step) return;
  char* end = nullptr;
  signal_at_step_ = std::strtoll(at_step, &end, 10);
  if (*at_step == '\0' || *end != '\0' || signal_at_step_ < 0)
    throw std::invalid_argument(std::string("SLIDEWAVE_TEST_SIGNAL_AT_STEP: '") + at_step + "' is not a step number");
  const char* name = std::getenv("SLIDEWAVE_TEST_SIGNAL");
  const std::string which = name ? name : "TERM";
  if (which == "TERM")
    signal_ = SIGTERM;
  else if (which == "KILL")
    signal_ = SIGKILL;
  else
    throw std::invalid_argument("SLIDEWAVE_TEST_SIGNAL: '" + which + "' is not TERM or KILL");
}

void SignalledRun::setup_done() {
  g_files_open = 1;  // first: a signal while the files are being created must not leave them half-made
  inner_.setup_done();
  if (const StateArrays* start = inner_.start_state()) step_ = start->integers.at("counters").at(0);
}

void SignalledRun::after_step(RunRecord& record, const Capture& capture) {
  inner_.after_step(record, capture);
  if (++step_ == signal_at_step_) std::raise(signal_);
}

}  // namespace slidewave

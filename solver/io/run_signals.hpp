#pragma once
// SIGINT and SIGTERM during `slidewave run`, and the test hook that raises them at a chosen step.
//
// Until the run creates its files (RunObserver::setup_done), a signal ends the process at once, exit 3,
// with a line on stderr: nothing has been written yet, and the setup runs in library code that polls
// no flag (Eigen's dense LDLT of the Delassus operator, CHOLMOD, FFTW planning: minutes on a large
// mesh). From then on a signal sets the flag the time loop polls every step, and the run ends with a
// checkpoint (exit 3).
//
// Test hook (for tests only, docs/contracts.md section 2): with SLIDEWAVE_TEST_SIGNAL_AT_STEP=N in the
// environment, the run raises SLIDEWAVE_TEST_SIGNAL (TERM, the default, or KILL) on itself right after
// the rows of step N are recorded (N = 0: the rows of t = 0), so that kill-and-resume tests stop a run
// at a known step on any machine.
#include <atomic>
#include <csignal>
#include <string>

#include "model/run_observer.hpp"

namespace slidewave {

/// Installs the SIGINT and SIGTERM handlers; returns the stop flag for simulate(). A signal during the
/// setup removes `lock_path` (the run's lock file, io/output_lock.hpp, still held) and ends the process
/// with `setup_exit_code`.
const std::atomic<bool>* install_stop_handlers(int setup_exit_code, const std::string& lock_path);

/// Forwards everything to `inner`. At setup_done() signals turn from "exit now" into "stop at the next
/// step", before `inner` creates the files; after_step() carries out the test hook.
class SignalledRun : public RunObserver {
 public:
  /// Reads the hook's environment variables; throws std::invalid_argument for malformed values.
  explicit SignalledRun(RunObserver& inner);
  void setup_done() override;
  void after_step(RunRecord& record, const Capture& capture) override;
  void at_end(RunRecord& record, const Capture& capture) override { inner_.at_end(record, capture); }
  const StateArrays* start_state() const override { return inner_.start_state(); }

 private:
  RunObserver& inner_;
  long long signal_at_step_ = -1;  ///< -1: no test hook
  int signal_ = SIGTERM;
  long long step_ = -1;  ///< the step whose rows after_step() sees next minus one
};

}  // namespace slidewave

#pragma once
// One-line progress report on stderr: simulated time, steps/s, ETA, T/N and slipping nodes.
// On a terminal the line is rewritten in place; otherwise (when forced with progress = always) one
// line per report, so logs stay readable. Progress never stops a run: the first failed write (a
// closed pipe, a full disk) silences the printer; main() ignores SIGPIPE so that such a write fails
// with EPIPE instead of killing the process.
#include "config/run_config.hpp"

namespace slidewave {

class ProgressPrinter {
 public:
  ProgressPrinter(ProgressMode mode, int n_contact_nodes);
  bool enabled() const { return enabled_; }
  void report(double t, double t_end, double steps_per_second, double T_over_N, int n_slipping, double dt) const;
  void finish() const;

 private:
  void silence() const;
  mutable bool enabled_;
  bool terminal_;
  int n_contact_nodes_;
};

}  // namespace slidewave

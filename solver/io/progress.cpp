#include "io/progress.hpp"

#include <unistd.h>

#include <cstdio>

namespace slidewave {

ProgressPrinter::ProgressPrinter(ProgressMode mode, int n_contact_nodes)
    : terminal_(::isatty(STDERR_FILENO)), n_contact_nodes_(n_contact_nodes) {
  enabled_ = mode == ProgressMode::always || (mode == ProgressMode::automatic && terminal_);
}

void ProgressPrinter::report(double t, double t_end, double steps_per_second, double T_over_N, int n_slipping,
                             double dt) const {
  if (!enabled_) return;
  const double eta = steps_per_second > 0 ? (t_end - t) / dt / steps_per_second : 0;
  const int written = std::fprintf(
      stderr, "%st = %9.1f / %.1f s  %7.0f steps/s  ETA %6.0f s  T/N = %+.4f  slipping %d/%d%s", terminal_ ? "\r" : "",
      t, t_end, steps_per_second, eta, T_over_N, n_slipping, n_contact_nodes_, terminal_ ? "" : "\n");
  if (written < 0 || std::fflush(stderr) != 0) silence();
}

void ProgressPrinter::finish() const {
  if (enabled_ && terminal_ && std::fprintf(stderr, "\n") < 0) silence();
}

void ProgressPrinter::silence() const {
  enabled_ = false;  // e.g. EPIPE from `| head`: the run matters, its progress line does not
  std::clearerr(stderr);
}

}  // namespace slidewave

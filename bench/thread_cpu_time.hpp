#pragma once
// The clock of the benchmarks that time steps: CPU seconds of the calling thread. The machine is shared, so
// wall time per step measures the load as much as the step; every path a benchmark compares is timed this way.
#include <ctime>

namespace slidewave::bench {

inline double cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

}  // namespace slidewave::bench

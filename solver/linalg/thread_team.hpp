#pragma once
// A fixed team of OpenMP threads for one solve of BlockCirculantSolver, and the split of an index range
// over it. The split decides only which thread computes an item, never how: every item (an FFT row, a
// wavenumber) goes through the same instructions for any team size, so results are bitwise the same.
#include <omp.h>

#include <algorithm>

namespace slidewave {

/// Runs body(t, T) on a team of `threads` threads (t = 0..T-1; T may be smaller than asked, e.g. when
/// nested inside another parallel region), or body(0, 1) on the calling thread when threads <= 1.
/// body must not throw.
template <class Body>
void run_team(int threads, const Body& body) {
  if (threads <= 1) {
    body(0, 1);
    return;
  }
#pragma omp parallel num_threads(threads)
  body(omp_get_thread_num(), omp_get_num_threads());
}

/// Waits for the whole team (nothing to wait for on the calling thread alone).
inline void team_barrier() {
#pragma omp barrier
}

/// Part t of T of [0, n): contiguous, in order, boundaries at multiples of `granule` (a cache line of
/// doubles for per-wavenumber arrays, so that two threads never write the same line).
struct Share {
  int begin, end;
};
inline Share share(int n, int t, int T, int granule = 1) {
  const long long chunks = (n + granule - 1) / granule;
  const auto bound = [&](int k) { return static_cast<int>(std::min<long long>(n, chunks * k / T * granule)); };
  return {bound(t), bound(t + 1)};
}

}  // namespace slidewave

#pragma once
// CHOLMOD, loaded on first use. Only `numerics.linear_solver = "cholmod"` and the tests' oracle factorize with it;
// linked into every process, CHOLMOD and what it pulls in (OpenBLAS, LAPACK, gfortran, METIS: 12 libraries)
// cost each `slidewave run` ~3 ms of start-up and an OpenBLAS thread spinning on the other core. So the library
// is opened with dlopen the first time a SparseCholesky is made, and its functions are called through this table
// (the declarations of cholmod.h, the same functions Eigen's CholmodSupport calls).
#include <cholmod.h>

namespace slidewave {

struct CholmodLibrary {
  decltype(&cholmod_start) start;
  decltype(&cholmod_finish) finish;
  decltype(&cholmod_analyze) analyze;
  decltype(&cholmod_factorize_p) factorize_p;
  decltype(&cholmod_solve) solve;
  decltype(&cholmod_free_factor) free_factor;
  decltype(&cholmod_free_dense) free_dense;

  /// Sets the thread count of the BLAS under CHOLMOD (OpenBLAS; any other BLAS is left as it is). OpenBLAS starts
  /// its worker threads when it is loaded, one per core, and idle each spins on sched_yield for ~0.1 s of CPU: with
  /// one thread they are stopped at once (OpenBLAS restarts them if a later call asks for more).
  void set_blas_threads(int n) const;

  void (*openblas_set_num_threads)(int) = nullptr;  ///< null: not OpenBLAS
  int (*blas_thread_shutdown)() = nullptr;
};

/// The table, loaded once (thread-safe), its BLAS at one thread. Throws std::runtime_error naming the library and
/// dlerror() if CHOLMOD (libcholmod.so.<CHOLMOD_MAIN_VERSION>, Debian's libcholmod3) cannot be opened or lacks a
/// function.
const CholmodLibrary& cholmod_library();

}  // namespace slidewave

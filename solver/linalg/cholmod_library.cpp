#include "linalg/cholmod_library.hpp"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace slidewave {

namespace {

#define SLIDEWAVE_STRINGIFY_(x) #x
#define SLIDEWAVE_STRINGIFY(x) SLIDEWAVE_STRINGIFY_(x)
/// The soname of the CHOLMOD whose header this is built against (Debian 12: libcholmod.so.3).
constexpr const char* kSoname = "libcholmod.so." SLIDEWAVE_STRINGIFY(CHOLMOD_MAIN_VERSION);

template <typename F>
void look_up(void* handle, const char* name, F& f) {
  f = reinterpret_cast<F>(dlsym(handle, name));
  if (!f) throw std::runtime_error(std::string("CHOLMOD: ") + kSoname + " has no " + name);
}

CholmodLibrary load() {
  // RTLD_LOCAL: its symbols (and its BLAS's) stay out of the process's global scope.
  void* handle = dlopen(kSoname, RTLD_NOW | RTLD_LOCAL);
  if (!handle) {
    const char* why = dlerror();
    throw std::runtime_error(std::string("CHOLMOD (numerics.linear_solver = \"cholmod\") cannot be loaded: ") +
                             (why ? why : kSoname) + " (Debian package libcholmod3)");
  }
  CholmodLibrary lib{};
  lib.openblas_set_num_threads = reinterpret_cast<void (*)(int)>(dlsym(handle, "openblas_set_num_threads"));
  lib.blas_thread_shutdown = reinterpret_cast<int (*)()>(dlsym(handle, "blas_thread_shutdown_"));
  lib.set_blas_threads(1);
  look_up(handle, "cholmod_start", lib.start);
  look_up(handle, "cholmod_finish", lib.finish);
  look_up(handle, "cholmod_analyze", lib.analyze);
  look_up(handle, "cholmod_factorize_p", lib.factorize_p);
  look_up(handle, "cholmod_solve", lib.solve);
  look_up(handle, "cholmod_free_factor", lib.free_factor);
  look_up(handle, "cholmod_free_dense", lib.free_dense);
  return lib;  // the handle stays open for the process's life
}

}  // namespace

void CholmodLibrary::set_blas_threads(int n) const {
  if (openblas_set_num_threads) openblas_set_num_threads(n);
  if (n == 1 && blas_thread_shutdown) blas_thread_shutdown();
}

const CholmodLibrary& cholmod_library() {
  static const CholmodLibrary lib = load();  // a throw leaves it unset: the next call tries again
  return lib;
}

}  // namespace slidewave

#include "linalg/fftw_planner.hpp"

namespace slidewave {

std::mutex& fftw_planner_mutex() {
  static std::mutex m;
  return m;
}

}  // namespace slidewave

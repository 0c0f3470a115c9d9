#pragma once
// The FFTW planner is not thread-safe (FFTW manual, sec. 5.2); execution of distinct plans is. Every plan
// of the program is made and destroyed under this one mutex.
#include <mutex>

namespace slidewave {

std::mutex& fftw_planner_mutex();

}  // namespace slidewave

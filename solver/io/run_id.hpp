#pragma once
// The identity of one run, and the names of the temporary files it writes. Every temporary is
// "<final name>.tmp.<run id>": unique to the run, so a run removes only files it created itself (never
// a user's "run.h5.tmp.keepme"), and the next run of the same output finds what a killed run left
// from the run id recorded in the lock file (io/output_lock.hpp).
#include <string>

namespace slidewave {

/// 16 lowercase hex digits from the operating system's random source.
std::string new_run_id();

/// True for a string new_run_id() can return.
bool is_run_id(const std::string& text);

/// "<target>.tmp.<run_id>".
std::string temporary_path_for(const std::string& target, const std::string& run_id);

}  // namespace slidewave

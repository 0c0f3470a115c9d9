#pragma once
// How much memory a new run may use: the smallest of what the machine has available
// (/proc/meminfo MemAvailable), what this process's cgroup still allows (v2 memory.max - memory.current,
// v1 memory.limit_in_bytes - memory.usage_in_bytes) and its address-space limit (RLIMIT_AS, ulimit -v,
// less what the process already maps).
#include <string>

namespace slidewave {

struct AvailableMemory {
  double bytes;        ///< infinity when nothing could be read
  std::string source;  ///< which bound it is, e.g. "MemAvailable in /proc/meminfo"
};

AvailableMemory available_memory();

}  // namespace slidewave

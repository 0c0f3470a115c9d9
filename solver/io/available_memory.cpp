#include "io/available_memory.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>

namespace slidewave {
namespace {

/// The number after `key` in a "key: value kB" file (/proc/meminfo, /proc/self/status), in bytes; < 0 if absent.
double kib_field(const std::string& path, const std::string& key) {
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (line.rfind(key, 0) == 0) {
      std::istringstream fields(line.substr(key.size()));
      double kib = -1;
      fields >> kib;
      return kib * 1024;
    }
  return -1;
}

/// A file holding one number of bytes ("max" or a missing file: < 0).
double bytes_in(const std::string& path) {
  std::ifstream in(path);
  double value = -1;
  if (!(in >> value)) return -1;
  return value;
}

}  // namespace

AvailableMemory available_memory() {
  AvailableMemory a{std::numeric_limits<double>::infinity(), "no limit found"};
  const auto consider = [&a](double bytes, const std::string& source) {
    if (bytes >= 0 && bytes < a.bytes) a = {bytes, source};
  };
  consider(kib_field("/proc/meminfo", "MemAvailable:"), "MemAvailable in /proc/meminfo");
  const double v2_max = bytes_in("/sys/fs/cgroup/memory.max"), v2_now = bytes_in("/sys/fs/cgroup/memory.current");
  if (v2_max >= 0 && v2_now >= 0) consider(v2_max - v2_now, "the cgroup's memory.max less memory.current");
  const double v1_max = bytes_in("/sys/fs/cgroup/memory/memory.limit_in_bytes"),
               v1_now = bytes_in("/sys/fs/cgroup/memory/memory.usage_in_bytes");
  if (v1_max >= 0 && v1_now >= 0) consider(v1_max - v1_now, "the cgroup's memory.limit_in_bytes less usage");
  struct rlimit limit {};
  if (::getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
    consider(static_cast<double>(limit.rlim_cur) - std::max(0.0, kib_field("/proc/self/status", "VmSize:")),
             "the address-space limit (ulimit -v) less what the process maps");
  return a;
}

}  // namespace slidewave

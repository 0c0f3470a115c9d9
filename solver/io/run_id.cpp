#include "io/run_id.hpp"

#include <cstdio>
#include <random>

namespace slidewave {

std::string new_run_id() {
  std::random_device source;  // getrandom(2) on Linux
  const unsigned long long high = source(), low = source();
  char text[17];
  std::snprintf(text, sizeof text, "%08llx%08llx", high & 0xffffffffull, low & 0xffffffffull);
  return text;
}

bool is_run_id(const std::string& text) {
  if (text.size() != 16) return false;
  for (const char c : text)
    if (!((c >= '0' && c <= '9') || (c >= 'a' && c <= 'f'))) return false;
  return true;
}

std::string temporary_path_for(const std::string& target, const std::string& run_id) {
  return target + ".tmp." + run_id;
}

}  // namespace slidewave

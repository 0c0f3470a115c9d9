// The heap on transparent huge pages (io/huge_page_heap.hpp): after the call, a block far above glibc's mmap
// threshold comes from the heap, in a mapping advised for huge pages.
#include "io/huge_page_heap.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace {

/// The header line ("start-end perms ... path") and the VmFlags line of the mapping in /proc/self/smaps that
/// holds `address`; empty strings when no mapping does.
std::pair<std::string, std::string> mapping_of(const void* address) {
  std::ifstream smaps("/proc/self/smaps");
  const auto a = reinterpret_cast<std::uintptr_t>(address);
  std::string line, header;
  bool inside = false;
  while (std::getline(smaps, line)) {
    std::istringstream fields(line);
    std::uintptr_t start = 0, end = 0;
    char dash = 0;
    if (fields >> std::hex >> start >> dash >> end && dash == '-') {  // a mapping's header
      inside = start <= a && a < end;
      if (inside) header = line;
    } else if (inside && line.rfind("VmFlags:", 0) == 0) {
      return {header, line};
    }
  }
  return {};
}

}  // namespace

TEST(HugePageHeap, ALargeBlockComesFromTheHeapAdvisedForHugePages) {
#ifdef __SANITIZE_ADDRESS__
  GTEST_SKIP() << "AddressSanitizer's allocator has its own mappings and ignores mallopt";
#endif
  if (!std::ifstream("/sys/kernel/mm/transparent_hugepage/enabled"))
    GTEST_SKIP() << "this kernel has no transparent huge pages";
  slidewave::back_heap_with_huge_pages(std::size_t{64} << 20);
  void* block = std::malloc(std::size_t{16} << 20);  // glibc maps blocks of 128 KiB and more (up to 32 MiB) apart
  ASSERT_NE(block, nullptr);
  // Its middle: its first bytes may share a page with the heap's part before the advice.
  const auto [header, flags] = mapping_of(static_cast<const char*>(block) + (std::size_t{8} << 20));
  std::free(block);
  EXPECT_NE(header.find("[heap]"), std::string::npos) << header;
  EXPECT_NE(flags.find(" hg"), std::string::npos) << header << "\n" << flags;
}

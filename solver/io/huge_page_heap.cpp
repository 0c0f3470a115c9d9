#include "io/huge_page_heap.hpp"

#include <malloc.h>
#include <sys/mman.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>

namespace slidewave {

namespace {
// M_TOP_PAD is an int; larger runs grow the heap beyond the advised part in ordinary pages.
constexpr std::size_t kMaxReserve = std::size_t{1} << 30;
}  // namespace

void back_heap_with_huge_pages(std::size_t reserve) {
  // Every block from the heap (glibc would mmap blocks from 128 KiB up, each of them faulted page by page),
  // the heap grown by `reserve` at its next growth, and nothing given back before the end.
  mallopt(M_MMAP_THRESHOLD, 512 * 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, 1024 * 1024 * 1024);
  mallopt(M_TOP_PAD, static_cast<int>(std::min<std::size_t>(reserve, kMaxReserve)));
  // A block larger than the heap's free top (keepcost) makes it grow by the block and the pad; freed, it stays.
  const auto old_break = reinterpret_cast<std::uintptr_t>(sbrk(0));
  void* block = std::malloc(mallinfo2().keepcost + 1024 * 1024);
  if (!block) return;
  const auto start = reinterpret_cast<std::uintptr_t>(block);
  const auto end = reinterpret_cast<std::uintptr_t>(sbrk(0));
  std::free(block);
  // Advised only when the heap grew (else the block has an mmap of its own): the block begins in the heap's
  // free top, and from there to the new break the heap is free.
  const auto page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
  const std::uintptr_t begin = (start + page - 1) & ~(page - 1);
  if (end > old_break && begin < end) madvise(reinterpret_cast<void*>(begin), end - begin, MADV_HUGEPAGE);
}

}  // namespace slidewave

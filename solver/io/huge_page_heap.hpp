#pragma once
#include <cstddef>

namespace slidewave {

/// Backs this process's heap with transparent huge pages where the kernel offers them (THP "madvise" mode,
/// Debian's default), before the run allocates: the heap is grown once by `reserve` bytes and that range is
/// advised MADV_HUGEPAGE, and blocks of any size are taken from it (no mmap per large block). An H/64 run
/// otherwise first-touches ~15 MB in ~3700 page faults of 4 KiB, a noticeable part of its wall time on a
/// virtual machine (docs/performance.md). Memory that is never touched is never backed; peak memory grows by
/// at most the huge pages' rounding. Where the kernel has no THP, or the advice fails, nothing changes but the
/// page size. Call early in main, once.
void back_heap_with_huge_pages(std::size_t reserve);

}  // namespace slidewave

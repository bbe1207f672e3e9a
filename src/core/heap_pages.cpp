#include "core/heap_pages.hpp"

#include <malloc.h>
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>

namespace collide::core {

void preferHugePagesForHeap(std::size_t bytes) {
  constexpr std::uintptr_t kHugePage = std::uintptr_t{2} << 20;  // x86-64 and arm64 PMD size
  if (bytes < 2 * kHugePage || bytes > (std::size_t{1} << 30)) return;
  // Blocks up to `bytes` from the heap, and the heap kept once grown: the reservation below
  // stays part of it after free().
  const int limit = static_cast<int>(bytes + kHugePage);
  if (mallopt(M_MMAP_THRESHOLD, limit) == 0 || mallopt(M_TRIM_THRESHOLD, 2 * limit) == 0) return;
  // Grow the heap by `bytes` (nothing is touched, so nothing becomes resident), mark the 2 MiB
  // aligned part of it, and give it back to malloc for the allocations to come.
  void* block = std::malloc(bytes);
  if (block == nullptr) return;
  const auto start = reinterpret_cast<std::uintptr_t>(block);
  const std::uintptr_t first = (start + kHugePage - 1) & ~(kHugePage - 1);
  const std::uintptr_t last = (start + bytes) & ~(kHugePage - 1);
  if (last > first) {
    static_cast<void>(madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE));
  }
  std::free(block);
}

}  // namespace collide::core

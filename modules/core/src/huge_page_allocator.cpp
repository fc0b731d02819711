#include "c2f/core/huge_page_allocator.hpp"

#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace c2f::detail {

void* allocate_huge(std::size_t bytes) {
  const std::size_t rounded = (bytes + kHugePageBytes - 1) / kHugePageBytes * kHugePageBytes;
  void* block = std::aligned_alloc(kHugePageBytes, rounded);
  if (block == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // A request: refused (no THP in this kernel, or disabled), the block has small pages.
  (void)madvise(block, rounded, MADV_HUGEPAGE);
#endif
  return block;
}

void free_huge(void* block) noexcept {
  std::free(block);
}

}  // namespace c2f::detail

#include "c2f/core/huge_page_allocator.hpp"

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace c2f::detail {

namespace {
constexpr std::size_t kHugePage = std::size_t{2} << 20;
}  // namespace

void* allocate_huge(std::size_t bytes) {
  const std::size_t rounded = (bytes + kHugePage - 1) / kHugePage * kHugePage;
  void* block = std::aligned_alloc(kHugePage, rounded);
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

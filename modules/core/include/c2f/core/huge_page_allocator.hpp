#pragma once
// An allocator that asks the kernel for transparent huge pages for large blocks: a
// std::vector<T, HugePageAllocator<T>> of at least kHugePageMinBytes is aligned to 2 MiB and
// advised MADV_HUGEPAGE, so that first touching it costs a page fault per 2 MiB instead of per
// 4 KiB. On a grid of millions of variables the solver's arrays (unaries, edge incidences, move
// problems, max-flow graphs) are hundreds of megabytes written once each, and the faults of
// 4 KiB pages took most of a run's time on some machines (docs/performance.md, "Huge pages for
// the large arrays"). Smaller blocks take std::allocator's path; where the system has no such
// advice a large block is only aligned. The advice is a request: where the kernel gives no huge
// page the block is as any other.

#include <cstddef>
#include <memory>
#include <new>
#include <vector>

namespace c2f {

/// A transparent huge page: 2 MiB.
inline constexpr std::size_t kHugePageBytes = std::size_t{2} << 20;
/// Blocks from this size on are aligned to kHugePageBytes and advised for huge pages.
inline constexpr std::size_t kHugePageMinBytes = 2 * kHugePageBytes;

namespace detail {
/// A block of `bytes` (>= kHugePageMinBytes) aligned to 2 MiB, its whole 2 MiB pages advised
/// MADV_HUGEPAGE where the system has it. Throws std::bad_alloc when there is no memory.
[[nodiscard]] void* allocate_huge(std::size_t bytes);
/// Frees a block of allocate_huge.
void free_huge(void* block) noexcept;
}  // namespace detail

/// std::allocator's contract (stateless, every instance equal); blocks of at least
/// kHugePageMinBytes come from allocate_huge.
template <typename T>
class HugePageAllocator {
 public:
  using value_type = T;

  HugePageAllocator() noexcept = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) noexcept {}  // NOLINT: converts as std::allocator

  [[nodiscard]] T* allocate(std::size_t n) {
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw std::bad_array_new_length();
    if (n * sizeof(T) < kHugePageMinBytes) return std::allocator<T>().allocate(n);
    return static_cast<T*>(detail::allocate_huge(n * sizeof(T)));
  }
  void deallocate(T* block, std::size_t n) noexcept {
    if (n * sizeof(T) < kHugePageMinBytes) {
      std::allocator<T>().deallocate(block, n);
    } else {
      detail::free_huge(block);
    }
  }

  template <typename U>
  friend bool operator==(const HugePageAllocator&, const HugePageAllocator<U>&) noexcept {
    return true;
  }
};

/// A vector whose large blocks are on huge pages (HugePageAllocator): the solver's arrays that
/// grow with the problem.
template <typename T>
using LargeVector = std::vector<T, HugePageAllocator<T>>;

}  // namespace c2f

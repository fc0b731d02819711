#pragma once
// An allocator that default-initialises where std::allocator value-initialises: a
// std::vector<float, DefaultInitAllocator<float>>(n) allocates n floats and leaves them
// unwritten. The first write is then the one that touches the memory (and takes its page
// faults), on whichever thread makes it, instead of a serial pass of zeros before it. The
// contract is the caller's: every element is written before it is read. Large blocks are on
// huge pages (HugePageAllocator).

#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

#include "c2f/core/huge_page_allocator.hpp"

namespace c2f {

template <typename T>
class DefaultInitAllocator : public HugePageAllocator<T> {
 public:
  using HugePageAllocator<T>::HugePageAllocator;

  /// Default-initialisation: nothing is written for a trivial U.
  template <typename U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible_v<U>) {
    ::new (static_cast<void*>(p)) U;
  }
  template <typename U, typename... Args>
  void construct(U* p, Args&&... args) {
    ::new (static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

/// A vector allocated unwritten: every element is written after allocation by whoever computes
/// it (so each page is first touched on that thread, not by a serial fill of zeros).
template <typename T>
using DefaultInitVector = std::vector<T, DefaultInitAllocator<T>>;

/// Float values that a producer writes in full (on as many threads as it likes) after
/// allocating: the storage of cost volumes and of PairwiseEnergy's float unaries.
using FloatValues = DefaultInitVector<float>;

}  // namespace c2f

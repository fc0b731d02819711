#pragma once
// Internal to the graph-cut solvers: a pass over the variables or edges of a move, split into
// bands of consecutive indices that depend on the count only, run on several threads. Each band
// writes only its own outputs, so results are the same for every thread count. Installed only
// because the solver templates include it.

#include <algorithm>
#include <cstddef>
#include <functional>
#include <vector>

namespace c2f::detail {

/// The indices of one band: [0, count) is cut into bands of this many (the last shorter),
/// unless a pass asks for another size.
inline constexpr std::size_t kBandSize = 8192;

/// The number of bands of `band` indices in [0, count).
[[nodiscard]] constexpr std::size_t band_count(std::size_t count,
                                               std::size_t band = kBandSize) noexcept {
  return (count + band - 1) / band;
}

/// Calls task(b, first, last) for every band b = [first, last) of `band` indices of [0, count),
/// each once, on up to `threads` threads (0: the machine's cores); a single band or one thread
/// runs in order on the calling thread (parallel_for_chunks). Rethrows the exception of the
/// lowest band that threw after all have ended.
void for_each_band(std::size_t count,
                   const std::function<void(std::size_t, std::size_t, std::size_t)>& task,
                   int threads, std::size_t band = kBandSize);

/// Runs list(first, last, out) for every band [first, last) of `band` indices of [0, count) by
/// for_each_band, each band into a list of its own (`lists`, kept between calls for their
/// memory), then appends the lists to `joined` in band order (copied on the threads when they
/// hold kBandSize entries or more): the same result for every thread count. A `joined` whose
/// allocator default-initialises (DefaultInitVector) grows without a serial pass of zeros
/// before the copies.
template <class T, class ListAllocator, class Allocator, class List>
void append_by_bands(std::size_t count, std::vector<std::vector<T, ListAllocator>>& lists,
                     std::vector<T, Allocator>& joined, const List& list, int threads,
                     std::size_t band = kBandSize) {
  const std::size_t bands = band_count(count, band);
  if (lists.size() < bands) lists.resize(bands);
  for_each_band(
      count,
      [&](std::size_t b, std::size_t first, std::size_t last) {
        lists[b].clear();
        list(first, last, lists[b]);
      },
      threads, band);
  // Each band's list copied to its place on the threads when there is much to copy.
  std::size_t added = 0;
  for (std::size_t b = 0; b < bands; ++b) added += lists[b].size();
  if (added < kBandSize) {
    for (std::size_t b = 0; b < bands; ++b)
      joined.insert(joined.end(), lists[b].begin(), lists[b].end());
    return;
  }
  std::vector<std::size_t> place(bands);
  std::size_t end = joined.size();
  for (std::size_t b = 0; b < bands; ++b) {
    place[b] = end;
    end += lists[b].size();
  }
  joined.resize(end);
  for_each_band(
      bands,
      [&](std::size_t, std::size_t first, std::size_t last) {
        for (std::size_t b = first; b < last; ++b)
          std::copy(lists[b].begin(), lists[b].end(), joined.begin() + place[b]);
      },
      threads, 1);
}

}  // namespace c2f::detail

#include "c2f/adapters/graphcut/detail/bands.hpp"

#include <algorithm>

#include "c2f/support/parallel_for.hpp"

namespace c2f::detail {

void for_each_band(std::size_t count,
                   const std::function<void(std::size_t, std::size_t, std::size_t)>& task,
                   int threads) {
  const std::size_t bands = band_count(count);
  const auto band = [&](std::size_t b) {
    task(b, b * kBandSize, std::min(count, (b + 1) * kBandSize));
  };
  if (bands <= 1 || resolved_threads(threads) == 1) {
    for (std::size_t b = 0; b < bands; ++b) band(b);
    return;
  }
  parallel_for(bands, band, threads);
}

}  // namespace c2f::detail

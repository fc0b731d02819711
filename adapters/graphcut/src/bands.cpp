#include "c2f/adapters/graphcut/detail/bands.hpp"

#include "c2f/support/parallel_for.hpp"

namespace c2f::detail {

void for_each_band(std::size_t count,
                   const std::function<void(std::size_t, std::size_t, std::size_t)>& task,
                   int threads, std::size_t band) {
  parallel_for_chunks(count, band, task, threads);
}

}  // namespace c2f::detail

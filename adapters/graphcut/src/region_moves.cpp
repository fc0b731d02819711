#include "c2f/adapters/graphcut/detail/region_moves.hpp"

#include "c2f/support/parallel_for.hpp"

namespace c2f::detail {

void for_each_region(std::size_t count, const std::function<void(std::size_t)>& task, int threads) {
  parallel_for(count, task, threads);
}

}  // namespace c2f::detail

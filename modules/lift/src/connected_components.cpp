#include "c2f/lift/connected_components.hpp"

#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

namespace c2f {

DensePartition connected_components(const DensePartition& partition, GridShape shape) {
  require_grid_size(partition.num_variables(), shape, "connected_components", "partition");
  std::vector<std::size_t> parent(shape.size());
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](std::size_t x) {
    while (parent[x] != x) x = parent[x] = parent[parent[x]];
    return x;
  };
  auto unite = [&](std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent[std::max(a, b)] = std::min(a, b);
  };
  const std::size_t w = shape.width;
  for (std::size_t v = 0; v < shape.size(); ++v) {
    if (v % w + 1 < w && partition.group_of(v) == partition.group_of(v + 1)) unite(v, v + 1);
    if (v + w < shape.size() && partition.group_of(v) == partition.group_of(v + w)) unite(v, v + w);
  }
  std::vector<std::int64_t> roots(shape.size());
  for (std::size_t v = 0; v < roots.size(); ++v) roots[v] = static_cast<std::int64_t>(find(v));
  return DensePartition::from_ids(roots);
}

}  // namespace c2f

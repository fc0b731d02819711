#include "c2f/lift/connected_components.hpp"

#include "disjoint_sets.hpp"

namespace c2f {

DensePartition connected_components(const DensePartition& partition, GridShape shape) {
  require_grid_size(partition.num_variables(), shape, "connected_components", "partition");
  detail::DisjointSets sets(shape.size());
  const std::size_t w = shape.width;
  for (std::size_t v = 0; v < shape.size(); ++v) {
    if (v % w + 1 < w && partition.group_of(v) == partition.group_of(v + 1)) sets.unite(v, v + 1);
    if (v + w < shape.size() && partition.group_of(v) == partition.group_of(v + w))
      sets.unite(v, v + w);
  }
  return sets.partition();
}

}  // namespace c2f

#include "c2f/lift/connected_components.hpp"

#include <stdexcept>
#include <string>

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

DensePartition connected_components_along_edges(const DensePartition& partition,
                                                const LiftingView& view) {
  if (partition.num_variables() != view.num_variables) {
    throw std::invalid_argument("connected_components_along_edges: the partition has " +
                                std::to_string(partition.num_variables()) +
                                " variables, the energy " + std::to_string(view.num_variables));
  }
  detail::DisjointSets sets(view.num_variables);
  for (const ColourFactor& factor : view.factors)
    if (partition.group_of(factor.u) == partition.group_of(factor.v))
      sets.unite(factor.u, factor.v);
  return sets.partition();
}

}  // namespace c2f

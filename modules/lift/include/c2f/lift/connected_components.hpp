#pragma once
// Splitting the groups of a partition into spatially connected pieces.

#include "c2f/core/grid.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/lifting_view.hpp"

namespace c2f {

/// The partition whose groups are the 4-connected components (on the width x height grid) of
/// the groups of `partition`. It refines `partition`; and if Q refines P, then
/// connected_components(Q) refines connected_components(P), so schedules stay nested. Reduced
/// energies of connected groups keep only the edges along group boundaries, which makes each
/// solver move on a coarse level much cheaper than on scattered groups. Throws
/// std::invalid_argument when the partition does not cover the grid.
DensePartition connected_components(const DensePartition& partition, GridShape shape);

/// The same on the graph of the view's factors, for an energy that is no pixel grid: two
/// variables of one group are in one component when a path of factors within the group joins
/// them. Nested partitions stay nested, as above. O(N + F). Throws std::invalid_argument when
/// the partition does not have the view's variable count.
DensePartition connected_components_along_edges(const DensePartition& partition,
                                                const LiftingView& view);

}  // namespace c2f

#pragma once
// Splitting the groups of a partition into spatially connected pieces.

#include "c2f/core/grid.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

/// The partition whose groups are the 4-connected components (on the width x height grid) of
/// the groups of `partition`. It refines `partition`; and if Q refines P, then
/// connected_components(Q) refines connected_components(P), so schedules stay nested. Reduced
/// energies of connected groups keep only the edges along group boundaries, which makes each
/// solver move on a coarse level much cheaper than on scattered groups. Throws
/// std::invalid_argument when the partition does not cover the grid.
DensePartition connected_components(const DensePartition& partition, GridShape shape);

}  // namespace c2f

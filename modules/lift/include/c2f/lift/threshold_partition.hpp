#pragma once
// Threshold partitions: pixels with similar unary cost vectors share a group.

#include "c2f/core/grid.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/lifting_view.hpp"

namespace c2f {

/// Groups are the connected components (single linkage) of the graph that links two pixels
/// when they lie within Chebyshev distance `radius` on the width x height grid and the L1
/// distance of their unary cost vectors is at most `tau`. Consequences, by construction: a
/// smaller tau gives a refinement of a larger one (same radius); chains of similar neighbours
/// can join pixels whose own unaries differ by more than tau. (The reference implementation
/// compared each pixel with an upper-left window only and let later matches overwrite earlier
/// ones, which is neither symmetric nor nested; this is not that.) O(N * radius^2 * L).
/// Throws std::invalid_argument for a size mismatch, tau < 0 or NaN, or radius < 1.
DensePartition threshold_partition(const PairwiseEnergy& energy, GridShape shape, double tau,
                                   int radius = 1);
/// The same on the unaries of any energy kind (its LiftingView).
DensePartition threshold_partition(const LiftingView& view, GridShape shape, double tau,
                                   int radius = 1);

}  // namespace c2f

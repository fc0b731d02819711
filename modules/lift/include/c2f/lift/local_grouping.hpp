#pragma once
// What the authors' released stereo code actually computed under the name "colour passing",
// kept for runs that reproduce it. Its pairwise factors were
// connected to their first endpoint only, so no information ever travels between pixels: the
// grouping is a local feature hash.

#include "c2f/core/grid.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

/// The reference's partition for paper-named CP(labels, iterations) on a width x height grid
/// energy (pixel v = y * width + x):
///  - iterations == 1 (the reference's initial colouring): pixels share a group when their
///    ordered tuples of the `labels` lowest-cost labels are equal and they own the same number
///    of grid edges (interior: right and down; last column or last row: one; the bottom-right
///    corner: none);
///  - iterations >= 2 (one or more reference rounds; more rounds add nothing): additionally the
///    unordered pair of the classes of the pixel's own right and down edges must be equal,
///    where an edge's class is its (term, weight).
/// An edge is a pixel's right edge when it joins v and v + 1 in one row, its down edge when it
/// joins v and v + width; other edges are ignored. Throws std::invalid_argument when the energy
/// does not have width * height variables, labels is not in [1, num_labels] or iterations < 1.
DensePartition local_grouping(const PairwiseEnergy& energy, GridShape shape, int labels,
                              int iterations);

}  // namespace c2f

#pragma once
// Exact reduction of an energy by a partition (the paper's reduced graphical model).

#include <concepts>

#include "c2f/core/energy.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

/// The reduced energy over the groups of `partition`: for every labeling y of the groups,
/// reduce(e, p).evaluate(y) == e.evaluate(expand(y, p)) up to the rounding of double sums
/// (Theorem 1). Construction:
///  - unary of a group = sum of its members' unaries;
///  - an edge inside a group adds weight * cost(l, l) to the group's unary (zero for Potts,
///    truncated-linear and TSGO step terms);
///  - edges between two groups are merged per (group pair, term) with their weights summed;
///    symmetric terms are merged regardless of edge orientation, asymmetric (table) terms per
///    orientation.
/// O(N * L + E) time, no allocation per edge. Throws std::invalid_argument when the partition
/// has a different number of variables than the energy.
PairwiseEnergy reduce(const PairwiseEnergy& energy, const GroupIds& groups);

/// reduce(energy, GroupIds(partition)) for any Partition type.
template <Partition P>
PairwiseEnergy reduce(const PairwiseEnergy& energy, const P& partition) {
  return reduce(energy, GroupIds(partition));
}

/// An energy type whose reduction by a partition of type P (energy_traits<E>::reduce) is an
/// energy of the same type, so one solver type serves every level of a coarse-to-fine run.
template <class E, class P = DensePartition>
concept ReducibleEnergy = Energy<E> && Partition<P> && requires(const E& e, const P& p) {
  { energy_traits<E>::reduce(e, p) } -> std::same_as<E>;
};

static_assert(ReducibleEnergy<PairwiseEnergy>);

}  // namespace c2f

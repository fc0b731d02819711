#pragma once
// The PartitionProvider concept: the source of a coarse-to-fine sequence of partitions.

#include <concepts>
#include <optional>

#include "c2f/core/energy.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

/// A stateful producer of ever finer partitions of the variables of an energy of type E.
/// Contract: each call of `next(energy)` returns the next level's partition, which refines
/// the previous one, or std::nullopt when no coarser level remains (the next level is the
/// original problem); once it has returned std::nullopt it keeps doing so. Partitions are
/// produced on demand, so their cost lands on the run clock of whoever calls next().
template <class P, class E>
concept PartitionProvider = Energy<E> && requires(P& provider, const E& energy) {
  { provider.next(energy) } -> std::same_as<std::optional<DensePartition>>;
};

}  // namespace c2f

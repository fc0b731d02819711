#pragma once
// The PartitionProvider concept: the source of a coarse-to-fine sequence of partitions.

#include <concepts>
#include <optional>
#include <utility>

#include "c2f/core/energy.hpp"
#include "c2f/core/partition.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

namespace detail {
template <class T>
inline constexpr bool is_optional_partition = false;
template <Partition P>
inline constexpr bool is_optional_partition<std::optional<P>> = true;
}  // namespace detail

/// A std::optional of a type that models Partition.
template <class T>
concept OptionalPartition = detail::is_optional_partition<T>;

/// A stateful producer of ever finer partitions of the variables of an energy of type E.
/// Contract: each call of `next(energy)` returns the next level's partition (any type that
/// models Partition), or std::nullopt when no coarser level remains (the next level is the
/// original problem); once it has returned std::nullopt it keeps doing so. Partitions are
/// produced on demand, so their cost lands on the run clock of whoever calls next(). Whether
/// each level refines the previous one is checked by the driver.
template <class P, class E>
concept PartitionProvider = Energy<E> && requires(P& provider, const E& energy) {
  { provider.next(energy) } -> OptionalPartition;
};

/// The partition type a PartitionProvider P yields for energies of type E.
template <class P, class E>
requires PartitionProvider<P, E>
using provided_partition_t =
    typename decltype(std::declval<P&>().next(std::declval<const E&>()))::value_type;

}  // namespace c2f

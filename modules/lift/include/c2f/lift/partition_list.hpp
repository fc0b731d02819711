#pragma once
// PartitionList: a provider that hands out partitions computed elsewhere.

#include <cstddef>
#include <optional>
#include <vector>

#include "c2f/core/energy.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

/// Returns the given partitions in order, then std::nullopt. An empty list is the flat run
/// (only the original problem). The partitions were built before the run, so their cost is
/// not on the run clock: use it for tests and for partitions loaded from files.
class PartitionList {
 public:
  PartitionList() = default;
  /// Throws std::invalid_argument unless all partitions cover the same number of variables
  /// and each refines the one before it.
  explicit PartitionList(std::vector<DensePartition> partitions);

  /// Throws std::invalid_argument when the partition does not cover the energy's variables.
  template <Energy E>
  std::optional<DensePartition> next(const E& energy) {
    if (position_ >= partitions_.size()) return std::nullopt;
    check_size(energy_traits<E>::num_variables(energy));
    return partitions_[position_++];
  }

  [[nodiscard]] std::size_t size() const noexcept { return partitions_.size(); }

 private:
  void check_size(std::size_t num_variables) const;

  std::vector<DensePartition> partitions_;
  std::size_t position_ = 0;
};

}  // namespace c2f

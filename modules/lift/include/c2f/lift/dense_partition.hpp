#pragma once
// DensePartition: the library's partition of variables into groups ("lifted pixels").

#include <cstddef>
#include <cstdint>
#include <span>
#include <utility>
#include <vector>

#include "c2f/core/labeling.hpp"
#include "c2f/core/partition.hpp"

namespace c2f {

/// A partition with dense group ids 0..num_groups-1, every group non-empty, and the members of
/// each group stored contiguously (CSR) in ascending variable order. Immutable.
class DensePartition {
 public:
  /// Throws std::invalid_argument naming the field unless every group_of[v] < num_groups and
  /// every group has at least one member.
  DensePartition(std::vector<VariableIndex> group_of, std::size_t num_groups);

  /// Groups variables with equal ids; group numbers follow the first occurrence of each id in
  /// variable order. Throws std::invalid_argument for negative ids.
  static DensePartition from_ids(std::span<const std::int64_t> ids);
  static DensePartition from_ids(std::span<const int> ids);
  /// Every variable alone: the original problem.
  static DensePartition identity(std::size_t num_variables);
  /// All variables in one group.
  static DensePartition single_group(std::size_t num_variables);

  [[nodiscard]] std::size_t num_variables() const noexcept { return group_of_.size(); }
  [[nodiscard]] std::size_t num_groups() const noexcept { return offsets_.size() - 1; }
  [[nodiscard]] VariableIndex group_of(std::size_t v) const noexcept { return group_of_[v]; }
  [[nodiscard]] std::span<const VariableIndex> group_ids() const noexcept { return group_of_; }
  /// Members of group g, ascending.
  [[nodiscard]] std::span<const VariableIndex> members(std::size_t g) const noexcept {
    return {members_.data() + offsets_[g], offsets_[g + 1] - offsets_[g]};
  }
  [[nodiscard]] bool is_identity() const noexcept { return num_groups() == num_variables(); }

  /// True when every group of this partition lies inside one group of `coarser` (this is finer
  /// than or equal to coarser). False when the variable counts differ. O(N + groups).
  [[nodiscard]] bool is_refinement_of(const DensePartition& coarser) const {
    return refines(*this, coarser);
  }

  friend bool operator==(const DensePartition& a, const DensePartition& b) {
    return a.group_of_ == b.group_of_;
  }

 private:
  std::vector<VariableIndex> group_of_;
  std::vector<std::size_t> offsets_;  // num_groups + 1 entries
  std::vector<VariableIndex> members_;
};

static_assert(Partition<DensePartition>);

/// Any Partition as a DensePartition (read through partition_traits), for code that needs its
/// member lists or stores levels (e.g. a PartitionList). O(N) for a foreign type; a
/// DensePartition is passed through. reduce, the transfers and the driver take any Partition
/// and need no conversion.
template <Partition P>
DensePartition to_dense_partition(const P& partition) {
  using Traits = partition_traits<P>;
  std::vector<VariableIndex> group_of(Traits::num_variables(partition));
  for (std::size_t v = 0; v < group_of.size(); ++v)
    group_of[v] = static_cast<VariableIndex>(Traits::group_of(partition, v));
  return DensePartition(std::move(group_of), Traits::num_groups(partition));
}
inline DensePartition to_dense_partition(DensePartition partition) {
  return partition;
}

/// The coarsest partition that refines both `a` and `b`: two variables share a group exactly
/// when they share one in `a` and one in `b`. Throws std::invalid_argument when the variable
/// counts differ. O(N).
DensePartition intersect(const DensePartition& a, const DensePartition& b);

}  // namespace c2f

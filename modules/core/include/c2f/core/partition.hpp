#pragma once
// The Partition concept: a map from variables to groups ("lifted pixels") with dense group
// ids and the member list of every group.

#include <concepts>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "c2f/core/labeling.hpp"

namespace c2f {

/// How the library reads a partition type. The default forwards to members `num_variables()`,
/// `num_groups()`, `group_of(v)` and `members(g)`; foreign types specialise this instead.
template <class P>
struct partition_traits {
  template <class T = P>
  static auto num_variables(const T& p) -> decltype(p.num_variables()) {
    return p.num_variables();
  }
  template <class T = P>
  static auto num_groups(const T& p) -> decltype(p.num_groups()) {
    return p.num_groups();
  }
  template <class T = P>
  static auto group_of(const T& p, std::size_t v) -> decltype(p.group_of(v)) {
    return p.group_of(v);
  }
  template <class T = P>
  static auto members(const T& p, std::size_t g) -> decltype(p.members(g)) {
    return p.members(g);
  }
};

/// A partition of num_variables variables into num_groups non-empty groups.
/// Contract: group_of(v) lies in [0, num_groups); members(g) lists, in ascending order, exactly
/// the variables v with group_of(v) == g.
template <class P>
concept Partition = requires(const P& p, std::size_t i) {
  { partition_traits<P>::num_variables(p) } -> std::convertible_to<std::size_t>;
  { partition_traits<P>::num_groups(p) } -> std::convertible_to<std::size_t>;
  { partition_traits<P>::group_of(p, i) } -> std::convertible_to<std::size_t>;
  { partition_traits<P>::members(p, i) } -> std::convertible_to<std::span<const VariableIndex>>;
};

namespace detail {
template <class P>
concept StoresGroupIds = requires(const P& p) {
  { p.group_ids() } -> std::convertible_to<std::span<const VariableIndex>>;
};
}  // namespace detail

/// The group of every variable of a Partition in one contiguous array: how reduce, the
/// transfers and the driver read any partition type. Borrowed from a type that stores it (a
/// member `group_ids()`, e.g. DensePartition: no copy, and the partition must outlive this);
/// otherwise gathered once through partition_traits::group_of, O(N) time and one VariableIndex
/// per variable (no member lists). Throws std::invalid_argument when a gathered group id is not
/// below num_groups.
class GroupIds {
 public:
  template <Partition P>
  explicit GroupIds(const P& partition)
      : num_groups_(static_cast<std::size_t>(partition_traits<P>::num_groups(partition))) {
    if constexpr (detail::StoresGroupIds<P>) {
      ids_ = partition.group_ids();
    } else {
      owned_.resize(static_cast<std::size_t>(partition_traits<P>::num_variables(partition)));
      for (std::size_t v = 0; v < owned_.size(); ++v) {
        const auto g = static_cast<std::size_t>(partition_traits<P>::group_of(partition, v));
        if (g >= num_groups_) {
          throw std::invalid_argument("partition: variable " + std::to_string(v) + " is in group " +
                                      std::to_string(g) + ", but there are " +
                                      std::to_string(num_groups_) + " groups");
        }
        owned_[v] = static_cast<VariableIndex>(g);
      }
      ids_ = owned_;
    }
  }
  GroupIds(const GroupIds&) = delete;  // ids_ may point into owned_
  GroupIds& operator=(const GroupIds&) = delete;

  [[nodiscard]] std::size_t num_variables() const noexcept { return ids_.size(); }
  [[nodiscard]] std::size_t num_groups() const noexcept { return num_groups_; }
  [[nodiscard]] VariableIndex operator[](std::size_t v) const noexcept { return ids_[v]; }
  [[nodiscard]] std::span<const VariableIndex> ids() const noexcept { return ids_; }

 private:
  std::vector<VariableIndex> owned_;
  std::span<const VariableIndex> ids_;
  std::size_t num_groups_;
};

/// True when every group of `fine` lies inside one group of `coarse` (fine is finer than or
/// equal to coarse); false when the variable counts differ. O(N + groups of fine).
template <Partition Fine, Partition Coarse>
bool refines(const Fine& fine, const Coarse& coarse) {
  const GroupIds f(fine), c(coarse);
  if (f.num_variables() != c.num_variables()) return false;
  constexpr VariableIndex kUnset = std::numeric_limits<VariableIndex>::max();
  std::vector<VariableIndex> coarse_group(f.num_groups(), kUnset);
  for (std::size_t v = 0; v < f.num_variables(); ++v) {
    VariableIndex& seen = coarse_group[f[v]];
    if (seen == kUnset) {
      seen = c[v];
    } else if (seen != c[v]) {
      return false;
    }
  }
  return true;
}

}  // namespace c2f

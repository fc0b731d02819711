#pragma once
// The Partition concept: a map from variables to groups ("lifted pixels") with dense group
// ids and the member list of every group.

#include <concepts>
#include <cstddef>
#include <span>

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

}  // namespace c2f

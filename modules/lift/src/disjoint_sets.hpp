#pragma once
// Internal to the lift module: union-find over variables 0..n-1, for partitions built by
// merging neighbours (threshold partitions, connected components).

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

#include "c2f/lift/dense_partition.hpp"

namespace c2f::detail {

class DisjointSets {
 public:
  explicit DisjointSets(std::size_t n) : parent_(n) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  /// The representative of x's set: its smallest member (path halving on the way).
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) x = parent_[x] = parent_[parent_[x]];
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }
  /// One group per set, numbered in order of the sets' smallest members.
  DensePartition partition() {
    std::vector<std::int64_t> roots(parent_.size());
    for (std::size_t v = 0; v < roots.size(); ++v) roots[v] = static_cast<std::int64_t>(find(v));
    return DensePartition::from_ids(roots);
  }

 private:
  std::vector<std::size_t> parent_;
};

}  // namespace c2f::detail

#pragma once
// BlockHierarchy: nested square pixel blocks, a content-blind baseline partition sequence.

#include <cstddef>
#include <optional>
#include <vector>

#include "c2f/core/energy.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

/// The partition of a width x height grid into block x block squares (the last row and column
/// of blocks may be smaller); pixel v = y * width + x.
DensePartition block_partition(GridShape shape, std::size_t block);

/// Provides block partitions for the given block sizes, coarsest first. Each size must divide
/// the one before it, so every level refines the previous one (checked on construction,
/// std::invalid_argument otherwise).
class BlockHierarchy {
 public:
  BlockHierarchy(GridShape shape, std::vector<std::size_t> block_sizes);

  /// Throws std::invalid_argument when the energy's variables are not the grid's pixels.
  template <Energy E>
  std::optional<DensePartition> next(const E& energy) {
    if (position_ >= block_sizes_.size()) return std::nullopt;
    check_size(energy_traits<E>::num_variables(energy));
    return block_partition(shape_, block_sizes_[position_++]);
  }

 private:
  void check_size(std::size_t num_variables) const;

  GridShape shape_;
  std::vector<std::size_t> block_sizes_;
  std::size_t position_ = 0;
};

}  // namespace c2f

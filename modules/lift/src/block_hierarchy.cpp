#include "c2f/lift/block_hierarchy.hpp"

#include <stdexcept>
#include <string>

namespace c2f {

DensePartition block_partition(GridShape shape, std::size_t block) {
  if (shape.width == 0 || shape.height == 0) {
    throw std::invalid_argument("block_partition: the grid is empty");
  }
  if (block == 0) throw std::invalid_argument("block_partition: block size must be >= 1");
  const std::size_t blocks_per_row = (shape.width + block - 1) / block;
  const std::size_t blocks_per_column = (shape.height + block - 1) / block;
  std::vector<VariableIndex> group_of(shape.size());
  for (std::size_t y = 0; y < shape.height; ++y) {
    for (std::size_t x = 0; x < shape.width; ++x) {
      group_of[y * shape.width + x] =
          static_cast<VariableIndex>((y / block) * blocks_per_row + x / block);
    }
  }
  return DensePartition(std::move(group_of), blocks_per_row * blocks_per_column);
}

BlockHierarchy::BlockHierarchy(GridShape shape, std::vector<std::size_t> block_sizes)
    : shape_(shape), block_sizes_(std::move(block_sizes)) {
  if (shape_.width == 0 || shape_.height == 0) {
    throw std::invalid_argument("BlockHierarchy: the grid is empty");
  }
  for (std::size_t i = 0; i < block_sizes_.size(); ++i) {
    if (block_sizes_[i] == 0) {
      throw std::invalid_argument("BlockHierarchy: block size " + std::to_string(i) + " is 0");
    }
    if (i > 0 && block_sizes_[i - 1] % block_sizes_[i] != 0) {
      throw std::invalid_argument("BlockHierarchy: block size " + std::to_string(block_sizes_[i]) +
                                  " does not divide the previous size " +
                                  std::to_string(block_sizes_[i - 1]) +
                                  ", so the levels would not refine each other");
    }
  }
}

void BlockHierarchy::check_size(std::size_t num_variables) const {
  require_grid_size(num_variables, shape_, "BlockHierarchy");
}

}  // namespace c2f

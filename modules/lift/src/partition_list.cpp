#include "c2f/lift/partition_list.hpp"

#include <stdexcept>
#include <string>

namespace c2f {

PartitionList::PartitionList(std::vector<DensePartition> partitions)
    : partitions_(std::move(partitions)) {
  for (std::size_t i = 1; i < partitions_.size(); ++i) {
    if (partitions_[i].num_variables() != partitions_[0].num_variables()) {
      throw std::invalid_argument("PartitionList: partition " + std::to_string(i) + " covers " +
                                  std::to_string(partitions_[i].num_variables()) +
                                  " variables, partition 0 covers " +
                                  std::to_string(partitions_[0].num_variables()));
    }
    if (!partitions_[i].is_refinement_of(partitions_[i - 1])) {
      throw std::invalid_argument("PartitionList: partition " + std::to_string(i) +
                                  " does not refine partition " + std::to_string(i - 1));
    }
  }
}

void PartitionList::check_size(std::size_t num_variables) const {
  if (partitions_[position_].num_variables() != num_variables) {
    throw std::invalid_argument("PartitionList: partition " + std::to_string(position_) +
                                " covers " +
                                std::to_string(partitions_[position_].num_variables()) +
                                " variables, the energy has " + std::to_string(num_variables));
  }
}

}  // namespace c2f

#include "c2f/lift/dense_partition.hpp"

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <unordered_map>

namespace c2f {

DensePartition::DensePartition(std::vector<VariableIndex> group_of, std::size_t num_groups)
    : group_of_(std::move(group_of)), offsets_(num_groups + 1, 0) {
  if (group_of_.size() > std::numeric_limits<VariableIndex>::max()) {
    throw std::invalid_argument("DensePartition: " + std::to_string(group_of_.size()) +
                                " variables do not fit a 32-bit variable index");
  }
  for (std::size_t v = 0; v < group_of_.size(); ++v) {
    if (group_of_[v] >= num_groups) {
      throw std::invalid_argument("DensePartition: group_of[" + std::to_string(v) +
                                  "] = " + std::to_string(group_of_[v]) +
                                  " is out of range, num_groups = " + std::to_string(num_groups));
    }
    ++offsets_[group_of_[v] + 1];
  }
  for (std::size_t g = 0; g < num_groups; ++g) {
    if (offsets_[g + 1] == 0) {
      throw std::invalid_argument("DensePartition: group " + std::to_string(g) +
                                  " has no members (group ids must be dense)");
    }
    offsets_[g + 1] += offsets_[g];
  }
  members_.resize(group_of_.size());
  std::vector<std::size_t> cursor(offsets_.begin(), offsets_.end() - 1);
  for (std::size_t v = 0; v < group_of_.size(); ++v) {
    members_[cursor[group_of_[v]]++] = static_cast<VariableIndex>(v);
  }
}

namespace {
template <class Id>
DensePartition dense_from_ids(std::span<const Id> ids) {
  std::vector<VariableIndex> group_of(ids.size());
  std::unordered_map<Id, VariableIndex> dense;
  dense.reserve(ids.size() / 4 + 16);
  for (std::size_t v = 0; v < ids.size(); ++v) {
    if (ids[v] < 0) {
      throw std::invalid_argument("DensePartition::from_ids: ids[" + std::to_string(v) +
                                  "] = " + std::to_string(ids[v]) + " is negative");
    }
    const auto [it, inserted] = dense.try_emplace(ids[v], static_cast<VariableIndex>(dense.size()));
    group_of[v] = it->second;
  }
  const std::size_t num_groups = dense.size();
  return DensePartition(std::move(group_of), num_groups);
}
}  // namespace

DensePartition DensePartition::from_ids(std::span<const std::int64_t> ids) {
  return dense_from_ids(ids);
}

DensePartition DensePartition::from_ids(std::span<const int> ids) {
  return dense_from_ids(ids);
}

DensePartition DensePartition::identity(std::size_t num_variables) {
  std::vector<VariableIndex> group_of(num_variables);
  for (std::size_t v = 0; v < num_variables; ++v) group_of[v] = static_cast<VariableIndex>(v);
  return DensePartition(std::move(group_of), num_variables);
}

DensePartition DensePartition::single_group(std::size_t num_variables) {
  return DensePartition(std::vector<VariableIndex>(num_variables, 0), num_variables == 0 ? 0 : 1);
}

DensePartition intersect(const DensePartition& a, const DensePartition& b) {
  if (a.num_variables() != b.num_variables()) {
    throw std::invalid_argument("intersect: the partitions cover " +
                                std::to_string(a.num_variables()) + " and " +
                                std::to_string(b.num_variables()) + " variables");
  }
  std::vector<std::int64_t> ids(a.num_variables());
  const auto stride = static_cast<std::int64_t>(b.num_groups());
  for (std::size_t v = 0; v < ids.size(); ++v)
    ids[v] = static_cast<std::int64_t>(a.group_of(v)) * stride + b.group_of(v);
  return DensePartition::from_ids(ids);
}

}  // namespace c2f

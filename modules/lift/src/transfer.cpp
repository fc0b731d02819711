#include "c2f/lift/transfer.hpp"

#include <stdexcept>
#include <string>

namespace c2f {

Labeling expand(std::span<const Label> labeling_on_groups, const DensePartition& partition) {
  if (labeling_on_groups.size() != partition.num_groups()) {
    throw std::invalid_argument(
        "expand: the labeling has " + std::to_string(labeling_on_groups.size()) +
        " entries, the partition has " + std::to_string(partition.num_groups()) + " groups");
  }
  Labeling ground(partition.num_variables());
  for (std::size_t v = 0; v < ground.size(); ++v)
    ground[v] = labeling_on_groups[partition.group_of(v)];
  return ground;
}

Labeling transfer_labels(std::span<const Label> labeling, const DensePartition& from,
                         const DensePartition& to) {
  if (labeling.size() != from.num_groups()) {
    throw std::invalid_argument(
        "transfer_labels: the labeling has " + std::to_string(labeling.size()) +
        " entries, the source partition has " + std::to_string(from.num_groups()) + " groups");
  }
  if (from.num_variables() != to.num_variables()) {
    throw std::invalid_argument("transfer_labels: the partitions cover " +
                                std::to_string(from.num_variables()) + " and " +
                                std::to_string(to.num_variables()) + " variables");
  }
  if (!to.is_refinement_of(from)) {
    throw std::invalid_argument(
        "transfer_labels: the target partition does not refine the source partition (some "
        "target group spans several source groups), so no labeling with the same energy exists");
  }
  Labeling out(to.num_groups());
  for (std::size_t g = 0; g < out.size(); ++g) out[g] = labeling[from.group_of(to.members(g)[0])];
  return out;
}

}  // namespace c2f

#include <algorithm>

namespace c2f {

Labeling transfer_labels_by_majority(std::span<const Label> labeling, const DensePartition& from,
                                     const DensePartition& to) {
  if (labeling.size() != from.num_groups() || from.num_variables() != to.num_variables()) {
    throw std::invalid_argument(
        "transfer_labels_by_majority: the labeling has " + std::to_string(labeling.size()) +
        " entries for " + std::to_string(from.num_groups()) + " groups, the partitions cover " +
        std::to_string(from.num_variables()) + " and " + std::to_string(to.num_variables()) +
        " variables");
  }
  Labeling out(to.num_groups());
  std::vector<Label> votes;
  for (std::size_t g = 0; g < out.size(); ++g) {
    votes.clear();
    for (const VariableIndex v : to.members(g)) votes.push_back(labeling[from.group_of(v)]);
    std::sort(votes.begin(), votes.end());
    Label best = votes.front();
    std::size_t best_count = 0;
    for (std::size_t i = 0; i < votes.size();) {
      std::size_t j = i;
      while (j < votes.size() && votes[j] == votes[i]) ++j;
      if (j - i > best_count) {
        best_count = j - i;
        best = votes[i];
      }
      i = j;
    }
    out[g] = best;
  }
  return out;
}

}  // namespace c2f

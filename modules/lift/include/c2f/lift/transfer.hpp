#pragma once
// Moving labelings between levels without changing their energy. Every partition argument may
// be of any type that models Partition (read through partition_traits).

#include <algorithm>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "c2f/core/labeling.hpp"
#include "c2f/core/partition.hpp"

namespace c2f {

/// The labeling of the original variables in which every member of group g gets
/// labeling_on_groups[g]. Throws std::invalid_argument when the size is not num_groups.
template <Partition P>
Labeling expand(std::span<const Label> labeling_on_groups, const P& partition) {
  const GroupIds groups(partition);
  if (labeling_on_groups.size() != groups.num_groups()) {
    throw std::invalid_argument(
        "expand: the labeling has " + std::to_string(labeling_on_groups.size()) +
        " entries, the partition has " + std::to_string(groups.num_groups()) + " groups");
  }
  Labeling ground(groups.num_variables());
  for (std::size_t v = 0; v < ground.size(); ++v) ground[v] = labeling_on_groups[groups[v]];
  return ground;
}

/// The labeling of the groups of `to` that stands for the same original labeling as
/// `labeling` on the groups of `from`, so its energy on reduce(e, to) equals the energy of
/// `labeling` on reduce(e, from). Requires `to` to refine `from`; otherwise (or on size
/// mismatch, or an empty group of `to`) throws std::invalid_argument.
template <Partition From, Partition To>
Labeling transfer_labels(std::span<const Label> labeling, const From& from, const To& to) {
  const GroupIds source(from);
  if (labeling.size() != source.num_groups()) {
    throw std::invalid_argument(
        "transfer_labels: the labeling has " + std::to_string(labeling.size()) +
        " entries, the source partition has " + std::to_string(source.num_groups()) + " groups");
  }
  const auto target_variables = static_cast<std::size_t>(partition_traits<To>::num_variables(to));
  if (source.num_variables() != target_variables) {
    throw std::invalid_argument("transfer_labels: the partitions cover " +
                                std::to_string(source.num_variables()) + " and " +
                                std::to_string(target_variables) + " variables");
  }
  if (!refines(to, from)) {
    throw std::invalid_argument(
        "transfer_labels: the target partition does not refine the source partition (some "
        "target group spans several source groups), so no labeling with the same energy exists");
  }
  Labeling out(static_cast<std::size_t>(partition_traits<To>::num_groups(to)));
  for (std::size_t g = 0; g < out.size(); ++g) {
    const std::span<const VariableIndex> members = partition_traits<To>::members(to, g);
    if (members.empty())
      throw std::invalid_argument("transfer_labels: group " + std::to_string(g) +
                                  " of the target partition has no members");
    out[g] = labeling[source[members.front()]];
  }
  return out;
}

/// For level sequences that do not refine each other (allowed only on request): every group of
/// `to` takes the label most of its variables had under `labeling` on `from` (ties: the lower
/// label). Equals transfer_labels when `to` refines `from`; otherwise the energy of the
/// result can differ from the energy of `labeling`. Throws std::invalid_argument on size
/// mismatch or an empty group of `to`.
template <Partition From, Partition To>
Labeling transfer_labels_by_majority(std::span<const Label> labeling, const From& from,
                                     const To& to) {
  const GroupIds source(from);
  const auto target_variables = static_cast<std::size_t>(partition_traits<To>::num_variables(to));
  if (labeling.size() != source.num_groups() || source.num_variables() != target_variables) {
    throw std::invalid_argument(
        "transfer_labels_by_majority: the labeling has " + std::to_string(labeling.size()) +
        " entries for " + std::to_string(source.num_groups()) + " groups, the partitions cover " +
        std::to_string(source.num_variables()) + " and " + std::to_string(target_variables) +
        " variables");
  }
  Labeling out(static_cast<std::size_t>(partition_traits<To>::num_groups(to)));
  std::vector<Label> votes;
  for (std::size_t g = 0; g < out.size(); ++g) {
    votes.clear();
    for (const VariableIndex v : partition_traits<To>::members(to, g))
      votes.push_back(labeling[source[v]]);
    if (votes.empty())
      throw std::invalid_argument("transfer_labels_by_majority: group " + std::to_string(g) +
                                  " of the target partition has no members");
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

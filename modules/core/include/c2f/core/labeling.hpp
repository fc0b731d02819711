#pragma once
// Labels, variable indices and labelings: the vocabulary every module shares.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace c2f {

/// A label index in [0, num_labels).
using Label = std::int32_t;

/// A variable index (a pixel, or a group of pixels on a reduced level) in [0, num_variables).
using VariableIndex = std::uint32_t;

/// One label per variable, indexed by VariableIndex.
using Labeling = std::vector<Label>;

/// Throws std::invalid_argument, naming `what`, unless `labeling` has exactly `num_variables`
/// entries and every entry lies in [0, num_labels).
void validate_labeling(std::span<const Label> labeling, std::size_t num_variables, int num_labels,
                       std::string_view what = "labeling");

}  // namespace c2f

#pragma once
// Command line of c2f-synthetic: parsing and validation.

#include <optional>
#include <string>
#include <vector>

#include "c2f/core/memory_budget.hpp"
#include "c2f/driver/options.hpp"
#include "c2f/vision/synthetic_problem.hpp"

namespace c2f::examples {

struct SyntheticCommand {
  vision::SyntheticSpec spec;
  std::vector<std::size_t> block_sizes;  ///< coarse levels, coarsest first
  Options options;                       ///< plateau and time limit, the same for both runs
  std::string out_dir;                   ///< empty: no files
  MemoryBudget memory;                   ///< --memory, else the machine's default
};

/// Parses argv. Returns std::nullopt after printing --help. Throws std::invalid_argument with a
/// message naming the flag for anything invalid.
std::optional<SyntheticCommand> parse_synthetic_command(int argc, char** argv);

}  // namespace c2f::examples

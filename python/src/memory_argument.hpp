#pragma once
// The `memory` argument of c2f.solve, c2f.stereo_energy and c2f.segment: the run's memory budget
// in GiB, as the tools' --memory (c2f/core/memory_budget.hpp), with every refusal a ValueError
// naming `memory`.

#include <pybind11/pybind11.h>

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/core/memory_budget.hpp"

namespace c2f::python {

/// `gib` GiB (a real number > 0), or the machine's default budget (default_memory_budget) for
/// None. ValueError naming `memory` for a value <= 0 or not finite, TypeError for what is no
/// number.
MemoryBudget memory_budget_from(const pybind11::handle& gib);

/// MemoryBudget::require (the budget, then what the machine has available), as a ValueError
/// "memory: <what> needs N, more than the run's memory budget of M (...)".
void require_memory_within(const MemoryBudget& budget, const std::string& what,
                           std::optional<std::size_t> bytes);

}  // namespace c2f::python

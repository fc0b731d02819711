#pragma once
// The `memory` argument of c2f.solve, c2f.stereo_energy and c2f.segment: the run's memory budget
// in GiB, as the tools' --memory (c2f/core/memory_budget.hpp, c2f/adapters/run_memory.hpp), with
// every refusal a ValueError naming `memory`.

#include <pybind11/pybind11.h>

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/adapters/coop/coop_memory.hpp"
#include "c2f/adapters/solver_choice.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::python {

/// `gib` GiB (a real number), or the machine's default budget (default_memory_budget) for 0.
/// ValueError naming `memory` for a negative or non-finite value, TypeError for what is no
/// number.
MemoryBudget memory_budget_from(const pybind11::handle& gib);

/// MemoryBudget::require (the budget, then what the machine has available), as a ValueError
/// "memory: <what> needs N, more than the run's memory budget of M (...)".
void require_memory_within(const MemoryBudget& budget, const std::string& what,
                           std::optional<std::size_t> bytes);

/// `choice` with its recycled move graphs limited to what `budget` leaves above the run's floor
/// on `energy`, and its coarse levels to the room the budget gives them (fit_to_budget); a
/// ValueError naming `memory` when the floor does not fit.
SolverChoice fit_to_memory(SolverChoice choice, const PairwiseEnergy& energy,
                           const MemoryBudget& budget);

/// The cooperative-cut solver's `options` fitted to `budget` for a run on `coop` with `potts`
/// kept beside it (fit_to_budget of coop_memory.hpp); a ValueError naming `memory` when the
/// floor does not fit.
CoopSolverOptions fit_coop_to_memory(const CoopSolverOptions& options, const CoopEnergy& coop,
                                     const PairwiseEnergy& potts, const MemoryBudget& budget);

}  // namespace c2f::python

#pragma once
// A cooperative-cut run's memory within a budget (c2f/adapters/run_memory.hpp): what a run of
// CoopSolver cannot do without, and what its alpha-expansion may keep in recycled move graphs.

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/adapters/run_memory.hpp"
#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/memory_budget.hpp"

namespace c2f {

/// The bytes CoopSolver with `options` works in on an energy of `size` besides its
/// alpha-expansion: the labelings it tries and keeps, and with AuxStrategy::ceres the
/// relaxation's logits, probabilities and L-BFGS history (Ceres' default rank 20: 43 doubles
/// per variable and label). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> coop_solver_bytes(const CoopSolverOptions& options,
                                                           const ProblemSize& size);

/// `options` for a run on `energy` within `budget`, while the caller keeps `kept_bytes` more
/// beside it (e.g. the Potts energy of the same data): graph_memory_limit lowered to what the
/// budget leaves above the run's floor, on every level (the alpha-expansion of each step recycles
/// its graphs within it). The floor: `energy`, one step's pairwise energy E_h (pairwise_energy,
/// measured for h all 1), coop_solver_bytes and alpha-expansion's floor on E_h's sizes
/// (run_memory_floor). A coarse level's reduced energies and working memory are not admitted
/// by size: they replace the original level's E_h and working memory, which the floor counts,
/// while the coarse level runs. Throws std::invalid_argument "<what> needs N, more than the
/// run's memory budget of M" (MemoryBudget::require) when the floor does not fit.
[[nodiscard]] CoopSolverOptions fit_to_budget(CoopSolverOptions options, const CoopEnergy& energy,
                                              std::size_t kept_bytes, const MemoryBudget& budget,
                                              const std::string& what);

}  // namespace c2f

#pragma once
// One memory budget for a run: the bytes its data (images, cost volume, energy, the levels'
// reduced energies) and its solvers' optional memory (recycled move graphs, kept move problems)
// may take together. Whatever the data leave is what the solvers may keep; a run whose data do
// not fit is refused with "needs N GiB" before it allocates.

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

struct MemoryBudget {
  std::size_t bytes = 0;
  /// How the budget was chosen, for reports: "--memory 2", "half of this machine's 23.5 GiB".
  std::string origin;

  /// "11.7 GiB (half of this machine's 23.5 GiB)".
  [[nodiscard]] std::string describe() const;

  /// Throws std::invalid_argument "<what> needs <bytes>, more than the run's memory budget of
  /// <budget> (<origin>)" when `bytes` (std::nullopt: beyond std::size_t) exceeds the budget.
  void require_within(const std::string& what, std::optional<std::size_t> bytes) const;
  /// require_within, then require_memory: before allocating, also what the machine has.
  void require(const std::string& what, std::optional<std::size_t> bytes) const;
};

/// The default: half of the machine's physical memory, at most what it has available
/// (available_memory_bytes), leaving the rest to the user's other work. A machine that reports
/// neither gets 4 GiB.
[[nodiscard]] MemoryBudget default_memory_budget();

/// A budget of `gib` GiB chosen by `origin` (e.g. "--memory 2"). Throws std::invalid_argument
/// naming origin unless gib is finite and > 0.
[[nodiscard]] MemoryBudget memory_budget_of_gib(double gib, const std::string& origin);

/// The bytes the arrays of `energy` take: its unaries, terms and edges.
[[nodiscard]] std::size_t energy_memory_bytes(const PairwiseEnergy& energy);

}  // namespace c2f

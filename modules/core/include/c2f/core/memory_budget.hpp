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
  /// How the budget was chosen, for reports: "--memory 2", "a quarter of this machine's ...".
  std::string origin;
  /// What a run whose needs (its floor, its data preparation) exceed `bytes` may take instead:
  /// the default budget grows to a run's needs up to half of the machine; a budget given
  /// explicitly does not grow (0, or anything up to bytes).
  std::size_t growth_limit = 0;

  /// The most a run may need: bytes, or growth_limit when larger.
  [[nodiscard]] std::size_t ceiling() const noexcept;
  /// The budget of a run whose needs are `need` bytes: bytes, grown to `need` up to ceiling().
  [[nodiscard]] std::size_t for_need(std::size_t need) const noexcept;

  /// "5.9 GiB (a quarter of this machine's 23.5 GiB; a run that needs more may take up to
  /// 11.8 GiB)", "2.0 GiB (--memory 2)".
  [[nodiscard]] std::string describe() const;

  /// Throws std::invalid_argument "<what> needs <bytes>, more than the run's memory budget of
  /// <budget> (<origin>)" when `bytes` (std::nullopt: beyond std::size_t) exceeds ceiling().
  void require_within(const std::string& what, std::optional<std::size_t> bytes) const;
  /// require_within, then require_memory: before allocating, also what the machine has.
  void require(const std::string& what, std::optional<std::size_t> bytes) const;
};

/// The default: a quarter of the machine's physical memory, growing to what a run needs up to
/// half of it, and at most what the machine has available (available_memory_bytes), leaving the
/// rest to the user's other work. The solvers' optional memory (recycled move graphs) buys
/// little beyond that (docs/performance.md, "One memory budget"). A machine that reports
/// neither gets 4 GiB.
[[nodiscard]] MemoryBudget default_memory_budget();

/// A budget of `gib` GiB chosen by `origin` (e.g. "--memory 2"). Throws std::invalid_argument
/// naming origin unless gib is finite and > 0.
[[nodiscard]] MemoryBudget memory_budget_of_gib(double gib, const std::string& origin);

/// The bytes the arrays of `energy` take: its unaries, terms and edges.
[[nodiscard]] std::size_t energy_memory_bytes(const PairwiseEnergy& energy);

/// The sizes of a problem that a solver's memory depends on (each solver's options answer
/// their own working memory from it: working_memory_bytes), known before the energy is built
/// or read from it (problem_size).
struct ProblemSize {
  std::size_t variables = 0;
  int labels = 0;
  std::size_t edges = 0;
  std::size_t energy_bytes = 0;  ///< what the energy's arrays take (energy_memory_bytes)
};

/// The sizes of `energy`.
[[nodiscard]] ProblemSize problem_size(const PairwiseEnergy& energy);

}  // namespace c2f

#include "c2f/adapters/coop/coop_memory.hpp"

#include <algorithm>

#include "c2f/core/memory_need.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

namespace {

/// Ceres' L-BFGS on n = variables x labels unknowns: its history (2 x rank 20 vectors of n) and
/// about three more vectors of n (logits, probabilities and gradients).
constexpr std::size_t kRelaxationDoublesPerUnknown = 43;

}  // namespace

std::optional<std::size_t> coop_solver_bytes(const CoopSolverOptions& options,
                                             const ProblemSize& size) {
  const auto labels = static_cast<std::size_t>(std::max(size.labels, 0));
  // The labeling kept, the one tried and the expansion's start.
  const auto labelings = checked_product({size.variables, 3, sizeof(Label)});
  const auto relaxation =
      options.strategy == AuxStrategy::ceres
          ? checked_product({size.variables, labels, kRelaxationDoublesPerUnknown, sizeof(double)})
          : std::optional<std::size_t>{0};
  if (!labelings || !relaxation) return std::nullopt;
  return checked_sum({*labelings, *relaxation});
}

CoopSolverOptions fit_to_budget(CoopSolverOptions options, const CoopEnergy& energy,
                                std::size_t kept_bytes, const MemoryBudget& budget,
                                const std::string& what) {
  // Alpha-expansion runs on E_h, which has the energy's variables and labels and one edge per
  // cooperative edge of positive weight; beside it the run holds the cooperative energy, the
  // caller's bytes and the solver's own.
  const PairwiseEnergy all_linear =
      pairwise_energy(energy, CoopAuxiliary(energy.num_labels(), energy.num_classes()));
  ProblemSize size = problem_size(all_linear);
  const std::optional<std::size_t> own = coop_solver_bytes(options, size);
  const std::optional<std::size_t> beside =
      own ? checked_sum({size.energy_bytes, energy_memory_bytes(energy), kept_bytes, *own}) : own;
  if (!beside) budget.require_within(what, std::nullopt);  // throws: the count overflows
  size.energy_bytes = *beside;
  // CoopSolver's alpha-expansion: whole moves on our max-flow, SolverChoice's defaults.
  const SolverChoice fitted = fit_to_budget(SolverChoice{}, size, budget, what);
  options.graph_memory_limit = std::min(options.graph_memory_limit, fitted.graph_memory_bytes());
  return options;
}

}  // namespace c2f

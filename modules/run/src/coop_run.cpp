#include "c2f/run/coop_run.hpp"

#include <algorithm>

#include "c2f/core/pairwise_energy.hpp"
#include "c2f/run/run_error.hpp"
#include "c2f/support/memory_need.hpp"

namespace c2f {

namespace {

/// Ceres' L-BFGS on n = variables x labels unknowns: its history (2 x rank 20 vectors of n) and
/// about three more vectors of n (logits, probabilities and gradients).
constexpr std::size_t kRelaxationDoublesPerUnknown = 43;

}  // namespace

std::string CoopRunConfig::validate() const {
  if (std::string problem = solver.validate(); !problem.empty()) return "solver: " + problem;
  return validate_limits_and_memory(limits, memory);
}

std::optional<std::size_t> working_memory_bytes(const CoopSolverOptions& options,
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

std::size_t sweep_steps(const CoopSolverOptions& options, const CoopEnergy& energy) {
  if (const std::string problem = options.validate(); !problem.empty())
    throw RunConfigError("solver", problem);
  return CoopSolver(options).quiet_steps_to_converge(energy);
}

MemoryPlan plan_run(const CoopEnergy& energy, const CoopRunConfig& config) {
  RunConfigError::throw_if(config.validate());
  // Alpha-expansion runs on E_h, which has the energy's variables and labels and one edge per
  // cooperative edge of positive weight; beside it the run holds the cooperative energy, the
  // caller's bytes and the solver's own.
  const PairwiseEnergy all_linear =
      pairwise_energy(energy, CoopAuxiliary(energy.num_labels(), energy.num_classes()));
  ProblemSize size = problem_size(all_linear);
  const std::optional<std::size_t> own = working_memory_bytes(config.solver, size);
  const std::optional<std::size_t> beside =
      own ? checked_sum({size.energy_bytes, energy_memory_bytes(energy), config.kept_bytes, *own})
          : own;
  try {
    const MemoryBudget budget = budget_or_default(config.memory);
    if (!beside) budget.require_within(config.energy_name, std::nullopt);  // throws: overflow
    size.energy_bytes = *beside;
    // CoopSolver's alpha-expansion: whole moves on our max-flow, with default options.
    return plan_memory(SolverSpec{}, size, budget,
                       config.graph_memory.value_or(config.solver.graph_memory_limit),
                       config.energy_name);
  } catch (const std::invalid_argument& error) {
    throw RunConfigError("memory", error.what());
  }
}

}  // namespace c2f

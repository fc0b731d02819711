#pragma once
// The run layer's entry point for cooperative-cut energies: run(energy, levels, config,
// observer) as for pairwise energies (c2f/run/run.hpp), with CoopSolver. The floor: the
// cooperative energy, one step's pairwise energy E_h, the solver's own memory, alpha-expansion's
// working memory on E_h and what the caller keeps beside the run; each step's alpha-expansion
// recycles its graphs within what the budget leaves. A coarse level's reduced energies and
// working memory replace the original level's E_h and working memory, which the floor counts,
// while it runs, so every level is solved.

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/driver/observer.hpp"
#include "c2f/run/memory_plan.hpp"
#include "c2f/run/run_config.hpp"

namespace c2f {

/// A run of a cooperative-cut energy.
struct CoopRunConfig {
  CoopSolverOptions solver;
  /// The driver's rules, as RunConfig::limits (coarse_level_fits is refused).
  Options limits;
  /// The bytes the whole run may take; unset: the machine's default (default_memory_budget).
  std::optional<MemoryBudget> memory = std::nullopt;
  /// At most this many bytes of the budget for each step's recycled move graphs; unset:
  /// solver.graph_memory_limit. Either is lowered to what the budget leaves above the floor.
  std::optional<std::size_t> graph_memory = std::nullopt;
  /// Bytes the caller keeps beside the run (e.g. the Potts energy of the same data), counted
  /// in the floor.
  std::size_t kept_bytes = 0;
  /// How a refusal names what is run ("<energy_name> needs N, more than ...").
  std::string energy_name = "the cooperative energy";

  /// Empty when usable, else "<field>: <problem>" ("solver: ...", "limits: ...").
  [[nodiscard]] std::string validate() const;
};

/// What CoopSolver with `options` works in on a problem of `size` (E_h's sizes) besides its
/// alpha-expansion: the labelings it tries and keeps, and with AuxStrategy::ceres the
/// relaxation's logits, probabilities and L-BFGS history (Ceres' default rank 20: 43 doubles
/// per variable and label). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> working_memory_bytes(const CoopSolverOptions& options,
                                                              const ProblemSize& size);

/// The plan of a run of `config` on `energy`. Throws RunConfigError (field "memory") when the
/// floor does not fit the budget, or naming the field config.validate() reports.
[[nodiscard]] MemoryPlan plan_run(const CoopEnergy& energy, const CoopRunConfig& config);

/// The steps without decrease that mean convergence of CoopSolver with `options` on `energy`
/// (its quiet_steps_to_converge), for rules that scale with it.
[[nodiscard]] std::size_t sweep_steps(const CoopSolverOptions& options, const CoopEnergy& energy);

/// Minimises `energy` over the partitions `levels` provides (none: flat) with CoopSolver as
/// `config` says (the report's flow_parts, flow_threads, near_radius and near_seeds: what each
/// step's expansion used on the original problem).
/// Throws as plan_run, and what coarse_to_fine throws.
template <PartitionProvider<CoopEnergy> P>
RunReport run(const CoopEnergy& energy, P& levels, const CoopRunConfig& config,
              const Observer& observer = {}) {
  RunReport report;
  report.budget = budget_or_default(config.memory);
  CoopRunConfig planned = config;
  planned.memory = report.budget;
  report.plan = plan_run(energy, planned);
  report.recycles = true;
  CoopSolverOptions options = config.solver;
  options.graph_memory_limit = report.plan.graph_memory;
  CoopSolver solver(options);
  // The levels (superpixels) are built on the solve's threads.
  if constexpr (requires { levels.set_threads(1); }) levels.set_threads(options.threads);
  report.summary = coarse_to_fine(energy, levels, solver, config.limits, observer);
  report.optional_memory_used = solver.kept_bytes();
  report.flow_parts = solver.flow_parts(energy);
  report.flow_threads = detail::threads_on_parts(options.threads, report.flow_parts);
  if (options.near_radius > 0 && energy.num_variables() >= options.near_moves_min_variables) {
    report.near_radius = options.near_radius;
    report.near_seeds = NearSeeds::label;
  }
  return report;
}

}  // namespace c2f

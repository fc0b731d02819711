#pragma once
// The run layer's entry point for pairwise energies: run(energy, levels, config, observer)
// validates the configuration, plans the memory budget (the floor must fit; the graph-cut
// solvers' recycled graphs get what it leaves; a coarse level is solved when its reduced
// energy, working memory and kept problems fit, its recycled graphs getting what they leave),
// builds the solver(s) the spec names, runs coarse_to_fine and reports the Summary with the
// memory given and used. The tools, the Python package and the benches call it.

#include <algorithm>
#include <cstddef>
#include <limits>
#include <span>
#include <stdexcept>
#include <string>

#include "c2f/core/local_gain.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/driver/observer.hpp"
#include "c2f/run/detail/level_budget_solver.hpp"
#include "c2f/run/memory_plan.hpp"
#include "c2f/run/run_config.hpp"
#include "c2f/run/run_error.hpp"
#include "c2f/run/solver_spec.hpp"

namespace c2f {

namespace detail {

/// The optional memory a solver reports holding (kept_bytes), 0 for one that keeps none.
template <class Solver>
std::size_t kept_bytes_of(const Solver& solver) {
  if constexpr (requires { solver.kept_bytes(); }) {
    return solver.kept_bytes();
  } else {
    return 0;
  }
}

/// The regions a solver's last binding made its moves on (region_count), 1 for one that has
/// none.
template <class Solver>
std::size_t regions_of(const Solver& solver) {
  if constexpr (requires { solver.region_count(); }) {
    return solver.region_count();
  } else {
    return 1;
  }
}

/// Under loopy BP: the schedule, the bands and the threads of the messages a solver's last
/// binding sent (LbpSolver), into `report` (solve_threads the messages' threads); nothing for
/// a solver that sends none.
template <class Solver>
void report_bp_messages(const Solver& solver, RunReport& report) {
  if constexpr (requires { solver.message_threads(); }) {
    report.bp_schedule = solver.schedule();
    report.bp_band_variables = solver.band_variables();
    report.solve_threads = solver.message_threads();
  }
}

/// The parts the max-flow of a solver's moves over every variable of `energy` is solved in
/// (ExpansionSolver::flow_parts), 1 for a solver that has none.
template <class Solver>
std::size_t flow_parts_of(const Solver& solver, const PairwiseEnergy& energy) {
  if constexpr (requires { solver.flow_parts(energy); }) {
    return solver.flow_parts(energy);
  } else {
    return 1;
  }
}

/// The threads that solve `parts` max-flow parts at once under `options`: at most one per part
/// and ExpansionOptions::threads (resolved); 1 with one part.
[[nodiscard]] unsigned flow_threads(const SolverOptions& options, std::size_t parts);

/// `spec` with expansion's shift_moves_unless_submodular, near_moves_only_if_local and near_seeds
/// decided on `energy` (makes_shift_moves, makes_near_moves, near_seeds_in_use) on every level:
/// shift_moves, near_radius and near_seeds say, so that the memory plan counts the shift and
/// near moves' solver only where they are made, gives recycled move graphs where near moves are
/// not, and the report names the seeds the moves start from.
[[nodiscard]] SolverSpec with_moves_decided(SolverSpec spec, const PairwiseEnergy& energy);

/// The threads a run of `options` solves `regions` regions on: half of them at once, at most
/// ExpansionOptions::threads (resolved); 1 without regions.
[[nodiscard]] unsigned solve_threads(const SolverOptions& options, std::size_t regions);

/// The threads the levels of a run of `options` are built on (ScheduleProvider::set_threads):
/// ExpansionOptions::threads or LbpOptions::threads (0: the machine's cores), 1 for any other
/// solver.
[[nodiscard]] int partition_threads(const SolverOptions& options);

}  // namespace detail

/// The plan of a run of `config` on `energy` (MemoryPlan): the floor, the graph memory and the
/// room of coarse levels. Throws RunConfigError (field "memory") when the floor does not fit
/// the budget, or naming the field config.validate() reports.
[[nodiscard]] MemoryPlan plan_run(const PairwiseEnergy& energy, const RunConfig& config);

/// The steps without decrease that mean convergence of the original problem's solver on
/// `energy` (its quiet_steps_to_converge: one sweep of its moves), for rules that scale with it
/// (e.g. segmentation's coarse plateau).
[[nodiscard]] std::size_t sweep_steps(const SolverSpec& spec, const PairwiseEnergy& energy);
/// The same for the coarse levels' solver (spec.coarse_options()): their labels are the
/// original problem's, so one sweep of their moves on `energy` is one on any coarse level.
[[nodiscard]] std::size_t coarse_sweep_steps(const SolverSpec& spec, const PairwiseEnergy& energy);

/// At most this many local costs (variables x labels) visited by the progress-rate rule's
/// estimate of the original problem's first-sweep gain (local_gain): 2 MiB of doubles, a few
/// milliseconds plus a pass over the edges.
inline constexpr std::size_t kLocalGainCosts = std::size_t{1} << 18;

/// Minimises `energy` over the partitions `levels` provides (none: flat) as `config` says. Throws
/// RunConfigError naming the field of a configuration that is not usable or a budget the floor
/// does not fit, and what coarse_to_fine throws (e.g. a start labeling of the wrong size).
template <PartitionProvider<PairwiseEnergy> P>
RunReport run(const PairwiseEnergy& energy, P& levels, const RunConfig& config,
              const Observer& observer = {}) {
  RunReport report;
  report.budget = budget_or_default(config.memory);
  RunConfig planned = config;
  planned.memory = report.budget;
  report.plan = plan_run(energy, planned);
  const SolverSpec spec =
      with_memory_plan(detail::with_moves_decided(config.solver, energy), report.plan);
  report.recycles = recycles_move_graphs(spec.original);
  if (const auto* expansion = std::get_if<ExpansionOptions>(&spec.original)) {
    report.shift_moves = expansion->shift_moves;
    report.near_radius = expansion->near_radius;
    report.near_seeds = expansion->near_seeds;
  }
  const ProblemSize size = problem_size(energy);
  Options options = config.limits;
  if (config.progress_rate) {
    options.progress_sweep_steps = static_cast<int>(
        std::min<std::size_t>(coarse_sweep_steps(spec, energy),
                              static_cast<std::size_t>(std::numeric_limits<int>::max())));
    options.next_level_gain = [&energy](std::span<const Label> ground) {
      return local_gain(energy, ground, kLocalGainCosts);
    };
  }
  options.coarse_level_fits = coarse_level_admission(spec, size, report.plan);
  if constexpr (requires { levels.set_threads(1); })
    levels.set_threads(detail::partition_threads(spec.original));
  const auto solve = [&](auto&& solvers) {
    Summary summary = coarse_to_fine(energy, levels, solvers, options, observer);
    report.optional_memory_used = detail::kept_bytes_of(detail::original_of(solvers));
    report.regions = detail::regions_of(detail::original_of(solvers));
    report.solve_threads = detail::solve_threads(spec.original, report.regions);
    report.flow_parts = detail::flow_parts_of(detail::original_of(solvers), energy);
    report.flow_threads = detail::flow_threads(spec.original, report.flow_parts);
    detail::report_bp_messages(detail::original_of(solvers), report);
    return summary;
  };
  report.summary = std::visit(
      [&]<class Options>(const Options& original) -> Summary {
        const Options& coarse = std::get<Options>(spec.coarse_options());
        if constexpr (std::is_base_of_v<MoveOptions, Options>) {
          // Graph-cut solvers: the coarse levels' recycled graphs get what each level leaves.
          return with_maxflow_backend(spec.maxflow, [&]<class Backend>(Backend) -> Summary {
            using Solver = typename detail::SolverFor<Options, Backend>::type;
            Solver original_solver(original);
            detail::LevelBudgetSolver<Solver, Options> coarse_solver(coarse, spec, size,
                                                                     report.plan);
            return solve(LevelSolvers(coarse_solver, original_solver));
          });
        } else {
          return detail::with_level_solvers<Options, DynamicMaxFlow>(original, coarse, solve);
        }
      },
      spec.original);
  return report;
}

}  // namespace c2f

#pragma once
// coarse_to_fine: Algorithm 1 of the paper for any energy, partition provider and anytime
// solver.

#include <functional>
#include <optional>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/energy.hpp"
#include "c2f/driver/detail/run_clock.hpp"
#include "c2f/driver/observer.hpp"
#include "c2f/driver/options.hpp"
#include "c2f/driver/rules.hpp"
#include "c2f/driver/summary.hpp"
#include "c2f/lift/partition_provider.hpp"
#include "c2f/lift/reduce.hpp"
#include "c2f/lift/transfer.hpp"

namespace c2f {

/// A PartitionProvider whose partitions E reduces by: what coarse_to_fine takes as its levels.
template <class P, class E>
concept LevelsFor = PartitionProvider<P, E> && ReducibleEnergy<E, provided_partition_t<P, E>>;

/// The start labeling of a level's energy: each variable's cheapest unary label, or all 0.
template <Energy E>
Labeling initial_labeling(const E& energy, InitialLabeling kind) {
  const std::size_t n = energy_traits<E>::num_variables(energy);
  Labeling labeling(n, 0);
  if (kind == InitialLabeling::zero) return labeling;
  for (std::size_t v = 0; v < n; ++v) labeling[v] = cheapest_label(energy, v);
  return labeling;
}

namespace detail {

/// The solver of the level being solved: `coarse` on every reduced energy, `original` on the
/// original one. Both may be the same object; when they differ and the coarse solver is a
/// ReleasingSolver, it is released as the original problem begins, so the coarse levels' memory
/// (e.g. recycled move graphs) is not held beside the original problem's.
template <class E, class CoarseSolver, class OriginalSolver>
class LevelSolver {
 public:
  LevelSolver(CoarseSolver& coarse, OriginalSolver& original)
      : coarse_(coarse), original_(original) {}

  void bind(const E& energy, std::span<const Label> start, bool at_original) {
    at_original_ = at_original;
    if (at_original) {
      if constexpr (ReleasingSolver<CoarseSolver>) {
        if (static_cast<const void*>(&coarse_) != static_cast<const void*>(&original_))
          coarse_.release();
      }
      original_.bind(energy, start);
    } else {
      coarse_.bind(energy, start);
    }
  }
  double step() { return at_original_ ? original_.step() : coarse_.step(); }
  [[nodiscard]] double energy() const {
    return at_original_ ? original_.energy() : coarse_.energy();
  }
  [[nodiscard]] std::span<const Label> labeling() const {
    return at_original_ ? original_.labeling() : coarse_.labeling();
  }
  /// The variables the last step worked over (StepScopeSolver), else `level_variables`.
  [[nodiscard]] std::size_t step_variables(std::size_t level_variables) const {
    return at_original_ ? step_variables_of(original_, level_variables)
                        : step_variables_of(coarse_, level_variables);
  }

 private:
  template <class S>
  static std::size_t step_variables_of(const S& solver, std::size_t level_variables) {
    if constexpr (StepScopeSolver<S>) {
      return solver.last_step().variables;
    } else {
      return level_variables;
    }
  }

  CoarseSolver& coarse_;
  OriginalSolver& original_;
  bool at_original_ = false;
};

/// The solver of the coarse levels and of the original problem in `solvers` (one object for
/// a single solver).
template <class S>
auto& coarse_of(S& solvers) {
  if constexpr (is_level_solvers<std::remove_cvref_t<S>>) {
    return solvers.coarse;
  } else {
    return solvers;
  }
}
template <class S>
auto& original_of(S& solvers) {
  if constexpr (is_level_solvers<std::remove_cvref_t<S>>) {
    return solvers.original;
  } else {
    return solvers;
  }
}

/// Algorithm 1 with the rules, start and transfer already worked out from the options.
template <class E, class P, class CoarseSolver, class OriginalSolver>
Summary run_levels(const E& energy, P& levels, CoarseSolver& coarse_solver,
                   OriginalSolver& original_solver, const Rules& rules, const Observer& observer,
                   InitialLabeling init, std::span<const Label> start_labeling,
                   LevelTransfer transfer,
                   const std::function<bool(std::size_t)>& coarse_level_fits) {
  if (!start_labeling.empty()) {
    const std::size_t n = energy_traits<E>::num_variables(energy);
    const int num_labels = energy_traits<E>::num_labels(energy);
    if (start_labeling.size() != n) {
      throw std::invalid_argument("coarse_to_fine: Options::start_labeling has " +
                                  std::to_string(start_labeling.size()) +
                                  " labels, the energy has " + std::to_string(n) + " variables");
    }
    for (std::size_t v = 0; v < n; ++v) {
      if (start_labeling[v] < 0 || start_labeling[v] >= num_labels) {
        throw std::invalid_argument("coarse_to_fine: Options::start_labeling gives variable " +
                                    std::to_string(v) + " label " +
                                    std::to_string(start_labeling[v]) + ", outside [0, " +
                                    std::to_string(num_labels - 1) + "]");
      }
    }
  }
  using LevelPartition = provided_partition_t<P, E>;
  using Traits = partition_traits<LevelPartition>;
  LevelSolver<E, CoarseSolver, OriginalSolver> solver(coarse_solver, original_solver);
  RunClock clock;
  Summary summary;
  std::optional<LevelPartition> previous;  // partition of the last finished level
  Labeling labeling;                       // labeling on the last finished level
  int previous_level = -1;                 // its index
  bool solved_any = false;                 // a level before this one was solved
  std::vector<double> history;
  bool finished = false;

  for (int level = 0; !finished; ++level) {
    LevelSummary stats;
    stats.level = level;
    const double level_start = clock.elapsed();
    std::optional<LevelPartition> partition = levels.next(energy);
    const double partition_done = clock.elapsed();
    stats.partition_seconds = partition_done - level_start;

    const bool at_original = !partition.has_value();
    if (!at_original && previous && transfer == LevelTransfer::exact &&
        !refines(*partition, *previous)) {
      throw std::invalid_argument(
          "coarse_to_fine: the partition of level " + std::to_string(level) + " (" +
          std::to_string(Traits::num_groups(*partition)) + " groups) does not refine level " +
          std::to_string(previous_level) + " (" + std::to_string(Traits::num_groups(*previous)) +
          " groups), so labels cannot be handed down with the same energy; order the levels "
          "coarse to fine, or hand labels down by majority (LevelTransfer::majority)");
    }
    const std::size_t groups = at_original ? 0 : Traits::num_groups(*partition);
    if (!at_original && coarse_level_fits && !coarse_level_fits(groups)) {
      stats.skipped = true;
      stats.num_variables = groups;
      summary.levels.push_back(stats);
      continue;
    }
    std::optional<E> reduced;
    if (!at_original) reduced.emplace(energy_traits<E>::reduce(energy, *partition));
    const E& level_energy = at_original ? energy : *reduced;

    Labeling start;
    if (!solved_any && !start_labeling.empty()) {
      start = at_original ? Labeling(start_labeling.begin(), start_labeling.end())
                          : transfer_labels_by_majority(
                                start_labeling, DensePartition::identity(start_labeling.size()),
                                *partition);
    } else if (!solved_any) {
      start = initial_labeling(level_energy, init);
    } else if (at_original) {
      start = expand(labeling, *previous);
    } else {
      start = transfer == LevelTransfer::exact
                  ? transfer_labels(labeling, *previous, *partition)
                  : transfer_labels_by_majority(labeling, *previous, *partition);
    }
    solver.bind(level_energy, start, at_original);
    const double setup_done = clock.elapsed();
    stats.setup_seconds = setup_done - partition_done;
    stats.num_variables = energy_traits<E>::num_variables(level_energy);

    std::optional<GroupIds> group_ids;  // borrowed from the partition when it stores them
    if (!at_original) group_ids.emplace(*partition);
    const std::span<const VariableIndex> group_of =
        group_ids ? group_ids->ids() : std::span<const VariableIndex>{};
    history.assign(1, solver.energy());
    stats.start_energy = history.back();

    for (long step = 0;; ++step) {
      if (step > 0) {
        history.push_back(solver.step());
        ++summary.total_steps;
      }
      const StepEvent event{clock.elapsed(),
                            level,
                            step,
                            summary.total_steps,
                            history.back(),
                            stats.num_variables,
                            step > 0 ? solver.step_variables(stats.num_variables) : 0,
                            at_original,
                            history,
                            solver.labeling(),
                            group_of};
      if (observer &&
          clock.off_the_clock([&] { return observer(event); }) == ObserverDecision::stop) {
        summary.reason = TerminationReason::observer;
        finished = true;
        break;
      }
      const Verdict verdict = rules.decide(event);
      if (verdict.decision == Decision::stop ||
          (verdict.decision == Decision::refine && at_original)) {
        summary.reason = verdict.reason;
        finished = true;
        break;
      }
      if (verdict.decision == Decision::refine) break;
    }

    stats.steps = static_cast<long>(history.size()) - 1;
    stats.final_energy = history.back();
    stats.solve_seconds = clock.elapsed() - setup_done;
    summary.levels.push_back(stats);
    solved_any = true;
    const std::span<const Label> result = solver.labeling();
    labeling.assign(result.begin(), result.end());
    if (at_original) {
      previous.reset();  // the labeling is already on the original variables
    } else {
      previous = std::move(partition);
      previous_level = level;
    }
  }

  summary.labeling = previous ? expand(labeling, *previous) : labeling;
  summary.energy = energy_traits<E>::evaluate(energy, summary.labeling);
  summary.seconds = clock.elapsed();
  summary.observer_seconds = clock.excluded();
  return summary;
}

/// `options` with plateau_steps_at_original = 0 replaced by what the original problem's solver
/// says convergence is on `energy` (ConvergingSolver); unchanged for a solver that does not say
/// and when plateau_steps is empty (no plateau rule on any level).
template <class E, class S>
Options with_solver_convergence(Options options, const S& original_solver, const E& energy) {
  if constexpr (ConvergingSolver<S, E>) {
    if (options.plateau_steps_at_original == 0 && !options.plateau_steps.empty()) {
      options.plateau_steps_at_original =
          static_cast<int>(original_solver.quiet_steps_to_converge(energy));
    }
  }
  return options;
}

}  // namespace detail

/// Minimises `energy` coarse to fine: the one entry point of the driver. For each partition
/// that `levels` provides (coarsest first), the energy is reduced by it, the current labeling
/// is transferred to it (same energy), the coarse solver is bound to the reduced energy and
/// stepped until the rules of `options` say refine; then the original problem's solver solves
/// the original energy the same way, until the rules say refine (finished) or stop. `solvers`
/// is one AnytimeSolver for every level, or LevelSolvers{coarse, original} (e.g. whole
/// expansion moves on the coarse levels and near moves on the original problem). A provider
/// that yields no partition gives the flat run, with the same code and clock.
///
/// The original problem ends where its solver says it has converged (a ConvergingSolver's
/// quiet_steps_to_converge) unless options.plateau_steps_at_original says otherwise, so
/// default options converge for every shipped solver. Throws std::invalid_argument when
/// options.validate() reports a problem.
///
/// The run clock starts before the first partition is built; partitions, reductions, transfers
/// and binding are on it; time inside `observer` is not. The observer sees every step,
/// including step 0 of every level, with the energy of the current labeling (equal to the
/// energy of the ground labeling it stands for, by Theorem 1).
///
/// With LevelTransfer::exact (the default) every level must refine the previous one and the
/// energy is handed down unchanged; LevelTransfer::majority accepts any level sequence and
/// hands labels down by majority vote, which can change the energy at a level switch.
///
/// Levels may come as any Partition type, read through partition_traits without conversion.
/// Throws std::invalid_argument when a provided partition does not cover the energy's variables
/// or, with LevelTransfer::exact, does not refine the previous level.
template <Energy E, LevelsFor<E> P, SolversFor<E> Solvers>
Summary coarse_to_fine(const E& energy, P& levels, Solvers&& solvers, const Options& options,
                       const Observer& observer = {}) {
  auto& coarse = detail::coarse_of(solvers);
  auto& original = detail::original_of(solvers);
  return detail::run_levels(energy, levels, coarse, original,
                            detail::with_solver_convergence(options, original, energy).rules(),
                            observer, options.initial_labeling, options.start_labeling,
                            options.level_transfer, options.coarse_level_fits);
}

}  // namespace c2f

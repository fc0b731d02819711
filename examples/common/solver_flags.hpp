#pragma once
// The options that choose a solver and end its run, shared by the tools that offer every
// solver (c2f-stereo, c2f-solve): --solver, --maxflow, --memory, --graph-memory, --near-radius,
// --shift-moves, --near-levels, --label-order, and
// --time-limit, --max-steps, --plateau, --plateau-tolerance, --final-plateau; and the run with
// the solver they choose.

#include <string>

#include "c2f/adapters/run_memory.hpp"
#include "c2f/adapters/solver_choice.hpp"
#include "c2f/core/observer.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/driver/options.hpp"
#include "tool_options.hpp"

namespace c2f::examples {

class SolverFlags {
 public:
  /// Declares the eight options in `options` (this object receives their values, so it must
  /// outlive options.parse()).
  void declare(ToolOptions& options);

  /// The solver the parsed options choose. Throws std::invalid_argument naming the option for
  /// an unknown name, a visit order the solver does not take, or a backend not in this build.
  [[nodiscard]] SolverChoice choice() const;
  /// The run's memory budget: --memory, else the machine's default (default_memory_budget).
  [[nodiscard]] MemoryBudget budget() const;

 private:
  std::string solver_ = "expansion", label_order_ = "sequential", maxflow_ = "dynamic",
              near_levels_;        // empty: not given (SolverChoice's default)
  std::string graph_memory_text_;  // empty: what the budget leaves
  double memory_gib_ = 0.0;        // 0: default_memory_budget()
  int near_radius_ = 0;
  bool shift_moves_ = false;
};

/// "memory budget 5.9 GiB (a quarter of this machine's 23.5 GiB; a run that needs more may take
/// up to 11.8 GiB), recycled move graphs up to 2.1 GiB" (the second part for expansion and
/// swap): the budget line of a tool's summary.
[[nodiscard]] std::string memory_line(const MemoryBudget& budget, const SolverChoice& choice);

/// The options that end levels and the run; the values are public (defaults as shown).
struct RunRuleFlags {
  double time_limit = 0.0;  ///< seconds on the run clock, 0: none
  long max_steps = 0;       ///< steps in the whole run, 0: none
  int plateau = 4;          ///< steps without decrease that end a coarse level
  double plateau_tolerance =
      0.0;                ///< coarse levels only: decreases below this fraction count as none
  int final_plateau = 0;  ///< on the original problem; 0: the solver's own convergence

  /// Declares the five options in `options` (this object receives their values).
  void declare(ToolOptions& options);

  /// The driver's options: these rules (with --final-plateau 0 the original problem ends where
  /// its solver has converged: one sweep of its moves).
  [[nodiscard]] Options options() const;
};

/// The tools' run step: coarse_to_fine with the solver(s) `choice` builds for this run
/// (with_chosen_solvers), each coarse level solved only when it fits choice.coarse_level_room
/// (coarse_level_admission). Throws std::invalid_argument when the choice or the options are
/// not usable.
template <PartitionProvider<PairwiseEnergy> P>
Summary run_chosen_solver(const PairwiseEnergy& energy, P& levels, const SolverChoice& choice,
                          Options options, const Observer& observer = {}) {
  options.coarse_level_fits = coarse_level_admission(choice, problem_size(energy));
  return with_chosen_solvers(choice, [&](auto&& solvers) {
    return coarse_to_fine(energy, levels, solvers, options, observer);
  });
}

}  // namespace c2f::examples

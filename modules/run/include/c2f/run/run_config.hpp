#pragma once
// A run configured ("this energy, that solver, this budget") and reported: RunConfig holds the
// solver, the driver's limits and the memory budget, with one validator whose messages name the
// field; RunReport is the driver's Summary plus the memory given and used, in the shape of
// Ceres' Solver::Summary.

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/core/memory_budget.hpp"
#include "c2f/driver/options.hpp"
#include "c2f/driver/summary.hpp"
#include "c2f/run/memory_plan.hpp"
#include "c2f/run/solver_spec.hpp"

namespace c2f {

/// The budget a run uses: `memory` when given, else the machine's default
/// (default_memory_budget).
[[nodiscard]] MemoryBudget budget_or_default(const std::optional<MemoryBudget>& memory);

/// Empty when a run's `limits` and `memory` are usable, else "limits: <problem>" or
/// "memory: <problem>" (the part of RunConfig::validate every kind of run shares).
[[nodiscard]] std::string validate_limits_and_memory(const Options& limits,
                                                     const std::optional<MemoryBudget>& memory);

/// A run of a pairwise energy: run(energy, levels, config, observer) in c2f/run/run.hpp.
struct RunConfig {
  SolverSpec solver;
  /// The driver's rules: when a level is left and the run ends, the start labeling, the
  /// transfer. Its coarse_level_fits is the run layer's (the budget decides which coarse levels
  /// fit); one set here is refused.
  Options limits;
  /// The bytes the whole run may take; unset: the machine's default (default_memory_budget).
  std::optional<MemoryBudget> memory = std::nullopt;
  /// Whether a coarse level is also left, after its first sweep of its solver's moves
  /// (coarse_sweep_steps), once its energy decrease per variable moved has fallen to what the
  /// original problem is expected to give: the local gain (local_gain) of the labeling it would
  /// hand down, over a sweep of whole moves on the original variables (the driver's
  /// progress_rate rule). The plateau rule of `limits` still applies.
  bool progress_rate = false;
  /// At most this many bytes of the budget for the graph-cut solvers' recycled move graphs;
  /// unset: all that the budget leaves above the run's floor and expansion's kept move
  /// problems (which are planned first, apart from this limit).
  std::optional<std::size_t> graph_memory = std::nullopt;
  /// How a refusal names what is run: "<energy_name> needs N, more than the run's memory
  /// budget of M".
  std::string energy_name = "the energy";

  /// Empty when usable, else "<field>: <problem>" ("solver.original: near_radius must be >= 0",
  /// "limits: time_limit_seconds must be ...", "memory: ...").
  [[nodiscard]] std::string validate() const;
};

/// What a run did: the driver's Summary, and the memory it was given and used.
struct RunReport {
  Summary summary;
  MemoryBudget budget;  ///< the budget given (or the default)
  MemoryPlan plan;      ///< the floor and the limits the budget became
  /// Whether the solver keeps optional memory (graph-cut solvers: recycled move graphs).
  bool recycles = false;
  /// The optional memory (kept move problems and recycled move graphs) the original problem's
  /// solver held at the end (within plan.problem_memory + plan.graph_memory).
  std::size_t optional_memory_used = 0;
  /// The regions of the original problem's moves (ExpansionOptions::regions; 1: none, every
  /// move over every variable) and the threads that solved them at once (1 without regions).
  std::size_t regions = 1;
  unsigned solve_threads = 1;
  /// The parts the max-flow of the original problem's moves over every variable was solved in
  /// (ExpansionOptions::flow_parts; 1: one) and the threads that solved them at once.
  std::size_t flow_parts = 1;
  unsigned flow_threads = 1;
  /// Whether the original problem's solver makes shift moves on this energy (expansion:
  /// makes_shift_moves, which ExpansionOptions::shift_moves_unless_submodular may decide).
  bool shift_moves = false;
  /// The radius of the original problem's near moves on this energy (0: none; expansion:
  /// makes_near_moves, which ExpansionOptions::near_moves_only_if_local may decide) and where
  /// they start on it (near_seeds_in_use).
  int near_radius = 0;
  NearSeeds near_seeds = NearSeeds::label_and_cheapest;
  /// Under loopy BP on the original problem: its schedule and the variables per band its
  /// messages were sent in (LbpSolver::band_variables); std::nullopt and 0 for other solvers.
  /// solve_threads is then the threads that sent the messages.
  std::optional<BpSchedule> bp_schedule;
  std::size_t bp_band_variables = 0;

  /// "memory budget 5.9 GiB (a quarter of ...), recycled move graphs up to 2.1 GiB, kept move
  /// problems 12.0 MiB" (the second part for solvers that recycle, the third when problems are
  /// kept), as the tools' summaries write it.
  [[nodiscard]] std::string memory_line() const;
  /// memory_line with the floor and what was used: "memory: budget 5.9 GiB (...), floor
  /// 380 MiB, recycled move graphs up to 2.1 GiB, kept move problems 12.0 MiB, 1.2 GiB used at
  /// the end".
  [[nodiscard]] std::string memory_report() const;
  /// "solve: moves by 16 regions on 2 threads with near moves of radius 5", "solve: near moves
  /// of radius 3 from their label (whole moves where they stall) on one thread" or "solve: every
  /// move over every variable on one thread" (the original problem's binding), with ", max-flow
  /// in 4 parts on 2 threads" after the moves when the max-flow of moves over every variable is
  /// solved in parts, and ending " with shift moves" (" and shift moves" after the regions' near
  /// moves) when it makes them, as the tools' summaries write it. Under loopy BP: "solve: BP
  /// messages by bands of 19200 variables on 2 threads", "... in variable order on one thread"
  /// or "... from the previous iteration's on 2 threads".
  [[nodiscard]] std::string threads_line() const;
};

namespace detail {
/// The threads that solve `parts` max-flow parts at once on up to `threads` threads (0: the
/// machine's cores): 1 for one part (RunReport::flow_threads).
[[nodiscard]] unsigned threads_on_parts(int threads, std::size_t parts);
}  // namespace detail

}  // namespace c2f

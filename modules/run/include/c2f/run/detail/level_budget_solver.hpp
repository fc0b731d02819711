#pragma once
// Internal to run(): the graph-cut solver of the coarse levels, whose recycled move graphs get,
// on each level, what the coarse levels' room leaves beside that level's reduced energy,
// working memory and kept move problems. A level whose fixed part fits is therefore never
// skipped for its optional memory: it runs with fewer recycled graphs.

#include <algorithm>
#include <cstddef>
#include <span>
#include <utility>

#include "c2f/core/labeling.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/run/memory_plan.hpp"

namespace c2f::detail {

template <class Solver, class Options>
class LevelBudgetSolver {
 public:
  /// `options` (graph-cut options with the plan's limits) for levels of a problem of `size`
  /// run under `spec` and `plan`.
  LevelBudgetSolver(Options options, SolverSpec spec, ProblemSize size, MemoryPlan plan)
      : options_(std::move(options)),
        spec_(std::move(spec)),
        size_(size),
        plan_(plan),
        solver_(options_) {}

  /// Binds a solver whose graph_memory_limit is what the room leaves beside this level's fixed
  /// part (coarse_level_memory without graphs), at most the plan's.
  void bind(const PairwiseEnergy& energy, std::span<const Label> start) {
    const std::optional<std::size_t> fixed =
        coarse_level_memory(spec_, size_, energy.num_variables(), 0, plan_.problem_memory);
    const std::size_t left =
        fixed && *fixed < plan_.coarse_level_room ? plan_.coarse_level_room - *fixed : 0;
    Options level = options_;
    level.graph_memory_limit = std::min(options_.graph_memory_limit, left);
    solver_ = Solver(level);
    solver_.bind(energy, start);
  }
  double step() { return solver_.step(); }
  [[nodiscard]] double energy() const noexcept { return solver_.energy(); }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return solver_.labeling(); }
  [[nodiscard]] std::size_t quiet_steps_to_converge(const PairwiseEnergy& energy) const {
    return solver_.quiet_steps_to_converge(energy);
  }
  [[nodiscard]] const auto& last_step() const noexcept { return solver_.last_step(); }
  /// Frees what the last level built.
  void release() { solver_ = Solver(options_); }

 private:
  Options options_;
  SolverSpec spec_;
  ProblemSize size_;
  MemoryPlan plan_;
  Solver solver_;
};

}  // namespace c2f::detail

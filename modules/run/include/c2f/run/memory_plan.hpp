#pragma once
// A run's memory budget (c2f/core/memory_budget.hpp) turned into limits: what a run of a
// SolverSpec cannot do without (its floor: each solver's options answer their own working
// memory), what its graph-cut solvers may keep to go faster (recycled move graphs and kept move
// problems, MoveOptions::graph_memory_limit), and which coarse levels fit beside them.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>

#include "c2f/core/memory_budget.hpp"
#include "c2f/run/solver_spec.hpp"

namespace c2f {

/// What the run layer planned for a run within a budget, in the shape of Ceres' given/used.
struct MemoryPlan {
  /// The bytes the run may take: the budget, a default budget grown to the floor when that is
  /// more (MemoryBudget::for_need).
  std::size_t budget = 0;
  /// What the run cannot do without: the process and its images (128 MiB), the energy,
  /// labelings and partitions (64 bytes per variable), and the original problem's solver's
  /// working memory.
  std::size_t floor = 0;
  /// Alpha-expansion's problem_memory_limit: its kept move problems (num_labels x (N + E)
  /// doubles, which make a move's problem cost what changed since) when they fit what the
  /// budget leaves above the floor, else 0. They come first: a small graph cap never drops them.
  std::size_t problem_memory = 0;
  /// The graph-cut solvers' graph_memory_limit on every level: what the budget leaves above the
  /// floor and the kept problems, or less when the run's graph_memory says so.
  std::size_t graph_memory = 0;
  /// The bytes a coarse level's reduced energy, its solver's working memory and its recycled
  /// graphs may take: what the budget leaves above the floor, plus the original problem's
  /// solver's share of the floor (coarse levels run before that solver is built).
  std::size_t coarse_level_room = 0;
};

/// What the solver of `options` works in on a problem of `size` (graph-cut solvers on the
/// backend `maxflow`), besides its optional memory. std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> working_memory_bytes(const SolverOptions& options,
                                                              MaxFlowKind maxflow,
                                                              const ProblemSize& size);

/// The floor of a run of `spec` on a problem of `size` (MemoryPlan::floor). std::nullopt when
/// the count overflows.
[[nodiscard]] std::optional<std::size_t> run_memory_floor(const SolverSpec& spec,
                                                          const ProblemSize& size);

/// The plan of a run of `spec` on a problem of `size` within `budget`, its recycled move graphs
/// at most `graph_memory` bytes when set. Throws std::invalid_argument "<what> needs N, more
/// than the run's memory budget of M" (MemoryBudget::require_within) when the floor does not
/// fit.
[[nodiscard]] MemoryPlan plan_memory(const SolverSpec& spec, const ProblemSize& size,
                                     const MemoryBudget& budget,
                                     std::optional<std::size_t> graph_memory,
                                     const std::string& what);

/// `spec` with every graph-cut options' graph_memory_limit (original and coarse) set to
/// plan.graph_memory, and expansion's problem_memory_limit to plan.problem_memory.
[[nodiscard]] SolverSpec with_memory_plan(SolverSpec spec, const MemoryPlan& plan);

/// An upper estimate of the bytes a coarse level of `groups` groups of a problem of `size` takes
/// beside the floor: its reduced energy (unaries in double, at most as many edges as the
/// original), its solver's working memory (spec.coarse_options()), its kept move problems
/// (expansion, when they fit problem_memory) and its recycled move graphs (one per move, at most
/// graph_memory). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> coarse_level_memory(const SolverSpec& spec,
                                                             const ProblemSize& size,
                                                             std::size_t groups,
                                                             std::size_t graph_memory,
                                                             std::size_t problem_memory = 0);

/// Whether a coarse level of this many groups is solved (the driver's Options::coarse_level_fits).
using CoarseLevelFits = std::function<bool(std::size_t groups)>;

/// Options::coarse_level_fits for a run of `spec` on `size` planned as `plan`: a level fits when
/// its fixed part (coarse_level_memory without recycled graphs) is at most
/// plan.coarse_level_room. Its recycled graphs are optional: run() gives each coarse level
/// what the room leaves beside that part (at most plan.graph_memory).
[[nodiscard]] CoarseLevelFits coarse_level_admission(const SolverSpec& spec,
                                                     const ProblemSize& size,
                                                     const MemoryPlan& plan);

/// How a grid energy stores its unary costs (PairwiseEnergy::single_precision).
enum class CostStorage { double_precision, single_precision };

/// The sizes of a 4-connected width x height grid energy with `labels` labels, its unaries
/// stored as `storage` says, and one L x L table term, before it is built. std::nullopt when
/// they overflow.
[[nodiscard]] std::optional<ProblemSize> grid_problem_size(std::size_t width, std::size_t height,
                                                           int labels, CostStorage storage);

/// What a run of `spec` on a 4-connected width x height grid energy with `labels` labels
/// (unaries stored as `storage`) needs before anything is built: the larger of `preparation`
/// (the peak of building the energy, e.g. tsgo_memory_estimate) and run_memory_floor of
/// grid_problem_size. std::nullopt when either overflows (preparation std::nullopt included).
/// Give it to MemoryBudget::require.
[[nodiscard]] std::optional<std::size_t> grid_run_memory_need(
    const SolverSpec& spec, std::size_t width, std::size_t height, int labels, CostStorage storage,
    std::optional<std::size_t> preparation);

}  // namespace c2f

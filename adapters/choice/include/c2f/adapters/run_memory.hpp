#pragma once
// A run's memory budget (c2f/core/memory_budget.hpp) split between what a run of a chosen
// solver cannot do without (its floor) and what its solver may keep to go faster: the recycled
// move graphs and kept move problems of expansion and swap (MoveOptions::graph_memory_limit).

#include <cstddef>
#include <functional>
#include <optional>

#include "c2f/adapters/solver_choice.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

/// The sizes of a problem that its memory depends on, known before the energy is built.
struct ProblemSize {
  std::size_t variables = 0;
  int labels = 0;
  std::size_t edges = 0;
  std::size_t energy_bytes = 0;  ///< what the energy's arrays take (energy_memory_bytes)
};

/// The sizes of `energy`.
[[nodiscard]] ProblemSize problem_size(const PairwiseEnergy& energy);

/// How a grid energy stores its unary costs (PairwiseEnergy::single_precision).
enum class CostStorage { double_precision, single_precision };

/// The sizes of a 4-connected width x height grid energy with `labels` labels, its unaries
/// stored as `storage` says, and one L x L table term, before it is built. std::nullopt when
/// they overflow.
[[nodiscard]] std::optional<ProblemSize> grid_problem_size(std::size_t width, std::size_t height,
                                                           int labels, CostStorage storage);

/// An upper estimate of the bytes a run of `choice` on a problem of this size takes besides the
/// solver's optional memory: the process and its images (128 MiB), the energy, labelings and
/// partitions (64 bytes per variable), and the original problem's solver's working memory
/// (graph cuts: the shared plain and QPBO move graphs, the move's problem and, with near moves,
/// a second solver; belief propagation: its messages). A coarse level's reduced energy and
/// solver come and go before the original problem's solver is built; they draw on the share
/// that solver will take (coarse_level_admission). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> run_memory_floor(const SolverChoice& choice,
                                                          const ProblemSize& size);

/// What a run of `choice` on a 4-connected width x height grid energy with `labels` labels
/// (unaries stored as `storage`) needs before anything is built: the larger of `preparation`
/// (the peak of building the energy, e.g. tsgo_memory_estimate) and run_memory_floor of
/// grid_problem_size. std::nullopt when either overflows (preparation std::nullopt included).
/// Give it to MemoryBudget::require.
[[nodiscard]] std::optional<std::size_t> grid_run_memory_need(
    const SolverChoice& choice, std::size_t width, std::size_t height, int labels,
    CostStorage storage, std::optional<std::size_t> preparation);

/// An upper estimate of the bytes a coarse level of `groups` groups of a problem of `size` takes
/// beside the floor: its reduced energy (unaries in double, at most as many edges as the
/// original), its solver's working memory and its recycled move graphs (at most one per move,
/// and at most choice.graph_memory_limit). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> coarse_level_memory(const SolverChoice& choice,
                                                             const ProblemSize& size,
                                                             std::size_t groups);

/// Whether a coarse level of this many groups is solved (the driver's Options::coarse_level_fits).
using CoarseLevelFits = std::function<bool(std::size_t groups)>;

/// Options::coarse_level_fits for a run of `choice` on a problem of `size`: a level fits when
/// coarse_level_memory is at most choice.coarse_level_room.
[[nodiscard]] CoarseLevelFits coarse_level_admission(const SolverChoice& choice,
                                                     const ProblemSize& size);

/// `choice` fitted to `budget`: graph_memory_limit set to what `budget` leaves above
/// run_memory_floor (a default budget first grown to the floor when that is more:
/// MemoryBudget::for_need; a smaller limit already set in `choice` stays), and coarse_level_room
/// what the budget leaves above the floor plus the original problem's solver's working memory (not
/// yet built while coarse levels run). Throws std::invalid_argument "<what> needs N, more than the
/// run's memory budget of M" (MemoryBudget::require) when the floor does not fit.
[[nodiscard]] SolverChoice fit_to_budget(SolverChoice choice, const ProblemSize& size,
                                         const MemoryBudget& budget, const std::string& what);

}  // namespace c2f

#pragma once
// Choosing a shipped solver at run time (command lines, benchmarks): one enum in the
// to_string/from_string vocabulary, and the chosen solver built for a caller (which hands it to
// coarse_to_fine; solvers do not drive levels).
// Graph-cut solvers run on the chosen max-flow backend (ours, DynamicMaxFlow, by default;
// Boost's; Kolmogorov's when the build has it).

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/adapters/graphcut/swap.hpp"
#include "c2f/adapters/icm/icm.hpp"
#include "c2f/adapters/lbp/lbp.hpp"
#include "c2f/adapters/maxflow/boost_maxflow.hpp"
#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
#include "c2f/adapters/maxflow/kolmogorov_maxflow.hpp"
#endif
#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/core/visit_order.hpp"

namespace c2f {

enum class SolverKind {
  expansion,  ///< alpha-expansion with QPBO moves (ExpansionSolver)
  swap,       ///< alpha-beta swap (SwapSolver)
  lbp,        ///< loopy belief propagation (LbpSolver)
  icm,        ///< iterated conditional modes (IcmSolver)
};

std::string_view to_string(SolverKind kind);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
SolverKind solver_kind_from_string(std::string_view text);

/// The max-flow backend of the graph-cut solvers (expansion, swap).
enum class MaxFlowKind {
  dynamic,     ///< ours: DynamicMaxFlow, with recycled per-label graphs (the default)
  boost,       ///< Boost Graph's boykov_kolmogorov_max_flow (BoostMaxFlow)
  kolmogorov,  ///< Kolmogorov's maxflow 3.0, GPL-3, only in builds configured with it
};

std::string_view to_string(MaxFlowKind kind);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
MaxFlowKind maxflow_kind_from_string(std::string_view text);

/// Whether this program was built with the backend (kolmogorov needs the optional target
/// c2f::kolmogorov_maxflow, which defines C2F_HAVE_KOLMOGOROV_MAXFLOW for its users).
constexpr bool maxflow_available(MaxFlowKind kind) noexcept {
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
  (void)kind;
  return true;
#else
  return kind != MaxFlowKind::kolmogorov;
#endif
}

/// Calls f(Backend{}) with a value of the backend type `kind` names. Throws
/// std::invalid_argument for a backend this build does not have.
template <class F>
decltype(auto) with_maxflow_backend(MaxFlowKind kind, F&& f) {
  switch (kind) {
    case MaxFlowKind::dynamic:
      return f(DynamicMaxFlow{});
    case MaxFlowKind::boost:
      return f(BoostMaxFlow{});
    case MaxFlowKind::kolmogorov:
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
      return f(KolmogorovMaxFlow{});
#else
      break;
#endif
  }
  throw std::invalid_argument(
      "max-flow backend 'kolmogorov' is not in this build (configure with "
      "-DC2F_WITH_KOLMOGOROV_MAXFLOW=ON)");
}

/// Where expansion's near moves (SolverChoice::near_radius > 0) and shift moves
/// (SolverChoice::shift_moves) are made in a coarse-to-fine run.
enum class NearLevels {
  original,  ///< on the original problem only; coarse levels make whole expansion moves only
  all,       ///< on every level
};

std::string_view to_string(NearLevels levels);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
NearLevels near_levels_from_string(std::string_view text);

/// A solver and its options, as command lines give them: what every move-making solver has
/// (MoveOptions, IcmOptions) and expansion's own kinds of move.
struct SolverChoice {
  SolverKind kind = SolverKind::expansion;
  VisitOrder order = VisitOrder::sequential;   ///< expansion, swap (labels), icm (variables)
  std::uint64_t seed = 1;                      ///< for VisitOrder::random
  MaxFlowKind maxflow = MaxFlowKind::dynamic;  ///< expansion, swap
  /// expansion, swap: MoveOptions::graph_memory_limit (for the dynamic backend). Unset: what
  /// the run's memory budget leaves above its floor once fit_to_budget has fitted the choice,
  /// MoveOptions' default before (graph_memory_bytes).
  std::optional<std::size_t> graph_memory_limit = std::nullopt;
  int near_radius = 0;       ///< expansion: ExpansionOptions::near_radius (0: whole moves only)
  bool shift_moves = false;  ///< expansion: ExpansionOptions::shift_moves
  /// expansion with near_radius > 0 or shift_moves: the levels that make near and shift moves.
  /// On the original problem only (the default) was the faster coarse-to-fine run in every
  /// measurement (docs/history/results-2026-11.md, "Near moves on the original problem only").
  NearLevels near_levels = NearLevels::original;
  /// The bytes a coarse level's reduced energy, its solver's working memory and its recycled
  /// graphs may take (coarse_level_admission; fit_to_budget sets it from the run's memory
  /// budget). The default admits every level.
  std::size_t coarse_level_room = static_cast<std::size_t>(-1);

  /// The limit the solvers get: graph_memory_limit, or MoveOptions' default when unset.
  [[nodiscard]] std::size_t graph_memory_bytes() const {
    return graph_memory_limit.value_or(MoveOptions{}.graph_memory_limit);
  }
  /// Swap's options.
  [[nodiscard]] SwapOptions swap_options() const {
    SwapOptions options;
    options.order = order;
    options.seed = seed;
    options.graph_memory_limit = graph_memory_bytes();
    return options;
  }
  /// Expansion's options on the original problem.
  [[nodiscard]] ExpansionOptions expansion_options() const {
    ExpansionOptions options;
    options.order = order;
    options.seed = seed;
    options.graph_memory_limit = graph_memory_bytes();
    options.near_radius = near_radius;
    options.shift_moves = shift_moves;
    return options;
  }
  /// The choice the coarse levels run: without near and shift moves unless near_levels is all.
  [[nodiscard]] SolverChoice coarse_levels_choice() const {
    SolverChoice coarse = *this;
    if (near_levels == NearLevels::original) {
      coarse.near_radius = 0;
      coarse.shift_moves = false;
    }
    return coarse;
  }
  /// Expansion's options on coarse levels (coarse_levels_choice). coarse_to_fine gives the
  /// coarse levels a solver of their own exactly when these differ from expansion_options().
  [[nodiscard]] ExpansionOptions coarse_expansion_options() const {
    return coarse_levels_choice().expansion_options();
  }

  /// Empty when usable, else a message naming the field (an order the solver cannot take).
  [[nodiscard]] std::string validate() const;
};

/// Builds the chosen solver fresh and returns f(solvers): the solver itself, or
/// LevelSolvers{coarse, original} when the coarse levels need a solver of their own (expansion
/// whose coarse_expansion_options() differ from expansion_options()). What f does with them is
/// the caller's: coarse_to_fine(energy, levels, solvers, options) runs them. Throws
/// std::invalid_argument when choice.validate() reports a problem.
template <class F>
decltype(auto) with_chosen_solvers(const SolverChoice& choice, F&& f) {
  if (const std::string problem = choice.validate(); !problem.empty())
    throw std::invalid_argument("solver choice: " + problem);
  switch (choice.kind) {
    case SolverKind::expansion:
      return with_maxflow_backend(choice.maxflow, [&]<class Backend>(Backend) -> decltype(auto) {
        ExpansionSolver<Backend> solver(choice.expansion_options());
        if (choice.coarse_expansion_options() == choice.expansion_options()) return f(solver);
        ExpansionSolver<Backend> coarse_solver(choice.coarse_expansion_options());
        return f(LevelSolvers(coarse_solver, solver));
      });
    case SolverKind::swap:
      return with_maxflow_backend(choice.maxflow, [&]<class Backend>(Backend) -> decltype(auto) {
        SwapSolver<Backend> solver(choice.swap_options());
        return f(solver);
      });
    case SolverKind::lbp: {
      LbpSolver solver;
      return f(solver);
    }
    case SolverKind::icm: {
      IcmSolver solver(IcmOptions{choice.order, choice.seed});
      return f(solver);
    }
  }
  throw std::logic_error("with_chosen_solvers: unknown solver kind");
}

}  // namespace c2f

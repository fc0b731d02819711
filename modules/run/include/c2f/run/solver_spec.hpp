#pragma once
// Which shipped solver a run uses, with its own options: SolverSpec names the max-flow backend
// and holds the original problem's solver options (one of each solver's own Options structs)
// and, optionally, the coarse levels' own. with_solvers builds the solver(s) it describes for
// coarse_to_fine.

#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <variant>

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

namespace c2f {

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

/// How the backend stores its graphs (for the graph-cut solvers' memory estimates).
constexpr GraphStorage graph_storage(MaxFlowKind kind) noexcept {
  return kind == MaxFlowKind::boost ? GraphStorage::adjacency_lists : GraphStorage::arrays;
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

/// A shipped solver's options: which one it is, and everything it is told.
using SolverOptions = std::variant<ExpansionOptions, SwapOptions, LbpOptions, IcmOptions>;

/// The shipped solvers by name, in the order of SolverOptions' alternatives.
enum class SolverKind {
  expansion,  ///< alpha-expansion with QPBO moves (ExpansionSolver, ExpansionOptions)
  swap,       ///< alpha-beta swap (SwapSolver, SwapOptions)
  lbp,        ///< loopy belief propagation (LbpSolver, LbpOptions)
  icm,        ///< iterated conditional modes (IcmSolver, IcmOptions)
};

std::string_view to_string(SolverKind kind);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
SolverKind solver_kind_from_string(std::string_view text);

/// The solver `options` belong to.
[[nodiscard]] SolverKind solver_kind(const SolverOptions& options) noexcept;
/// The default options of the solver `kind` names.
[[nodiscard]] SolverOptions default_solver_options(SolverKind kind);

/// Whether the graph-cut solvers' optional memory applies (expansion, swap).
[[nodiscard]] bool recycles_move_graphs(const SolverOptions& options) noexcept;

/// Where expansion's near and shift moves are made in a coarse-to-fine run (expansion_spec).
enum class NearLevels {
  original,  ///< on the original problem only; coarse levels make whole expansion moves only
  all,       ///< on every level
};

std::string_view to_string(NearLevels levels);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
NearLevels near_levels_from_string(std::string_view text);

/// A run's solver: the backend and the options of the original problem's solver, and the
/// coarse levels' own options of the same solver when they differ. The graph-cut solvers'
/// graph_memory_limit is the run's to set (RunConfig::graph_memory and the memory budget); what
/// the spec holds there is replaced.
struct SolverSpec {
  MaxFlowKind maxflow = MaxFlowKind::dynamic;  ///< expansion, swap
  SolverOptions original = ExpansionOptions{};
  /// The coarse levels' options (the same solver as `original`); unset: as `original`.
  std::optional<SolverOptions> coarse = std::nullopt;

  [[nodiscard]] SolverKind kind() const noexcept { return solver_kind(original); }
  /// The options the coarse levels run.
  [[nodiscard]] const SolverOptions& coarse_options() const noexcept {
    return coarse ? *coarse : original;
  }
  /// Empty when usable, else a message naming the field ("maxflow: ...", "original: ...",
  /// "coarse: ...").
  [[nodiscard]] std::string validate() const;
};

/// Expansion with `options` on the original problem; on coarse levels too with NearLevels::all,
/// and with NearLevels::original the same options less near and shift moves (whole moves only:
/// the faster coarse-to-fine run in every measurement, docs/results.md).
[[nodiscard]] SolverSpec expansion_spec(const ExpansionOptions& options,
                                        NearLevels levels = NearLevels::original,
                                        MaxFlowKind maxflow = MaxFlowKind::dynamic);

namespace detail {

/// The solver type that takes Options (on Backend, for the graph-cut solvers).
template <class Options, class Backend>
struct SolverFor;
template <class Backend>
struct SolverFor<ExpansionOptions, Backend> {
  using type = ExpansionSolver<Backend>;
};
template <class Backend>
struct SolverFor<SwapOptions, Backend> {
  using type = SwapSolver<Backend>;
};
template <class Backend>
struct SolverFor<LbpOptions, Backend> {
  using type = LbpSolver;
};
template <class Backend>
struct SolverFor<IcmOptions, Backend> {
  using type = IcmSolver;
};

/// f(solver) when the coarse options equal the original ones, else
/// f(LevelSolvers{coarse, original}).
template <class Options, class Backend, class F>
decltype(auto) with_level_solvers(const Options& original, const Options& coarse, F&& f) {
  using Solver = typename SolverFor<Options, Backend>::type;
  Solver solver(original);
  if (coarse == original) return f(solver);
  Solver coarse_solver(coarse);
  return f(LevelSolvers(coarse_solver, solver));
}

}  // namespace detail

/// Builds the solver(s) `spec` describes fresh and returns f(solvers): the solver itself, or
/// LevelSolvers{coarse, original} when the coarse levels' options differ. f must return the
/// same type for every solver. Throws std::invalid_argument "solver.<field>: ..." when
/// spec.validate() reports a problem.
template <class F>
decltype(auto) with_solvers(const SolverSpec& spec, F&& f) {
  if (const std::string problem = spec.validate(); !problem.empty())
    throw std::invalid_argument("solver." + problem);
  return std::visit(
      [&]<class Options>(const Options& original) -> decltype(auto) {
        const Options& coarse = std::get<Options>(spec.coarse_options());
        if constexpr (std::is_base_of_v<MoveOptions, Options>) {
          return with_maxflow_backend(spec.maxflow, [&]<class Backend>(Backend) -> decltype(auto) {
            return detail::with_level_solvers<Options, Backend>(original, coarse, f);
          });
        } else {
          return detail::with_level_solvers<Options, DynamicMaxFlow>(original, coarse, f);
        }
      },
      spec.original);
}

}  // namespace c2f

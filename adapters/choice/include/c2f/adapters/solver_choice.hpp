#pragma once
// Choosing a shipped solver at run time (command lines, benchmarks): one enum in the
// to_string/from_string vocabulary, each solver's sweep length, and coarse_to_fine with the
// chosen solver. Graph-cut solvers run on the default max-flow backend (Boost).

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/adapters/graphcut/swap.hpp"
#include "c2f/adapters/icm/icm.hpp"
#include "c2f/adapters/lbp/lbp.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/core/visit_order.hpp"
#include "c2f/driver/coarse_to_fine.hpp"

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

/// A solver and the options every move-making solver shares (MoveOptions, IcmOptions).
struct SolverChoice {
  SolverKind kind = SolverKind::expansion;
  VisitOrder order = VisitOrder::sequential;  ///< expansion, swap (labels), icm (variables)
  std::uint64_t seed = 1;                     ///< for VisitOrder::random

  /// Empty when usable, else a message naming the field (an order the solver cannot take).
  [[nodiscard]] std::string validate() const;
};

/// Steps without a decrease that mean convergence with this solver on an energy with
/// num_labels labels: one sweep of its moves (the solver's steps_per_sweep).
std::size_t steps_per_sweep(SolverKind kind, int num_labels);

/// coarse_to_fine (see c2f/driver/coarse_to_fine.hpp) with the chosen solver, built fresh for
/// this run. Throws std::invalid_argument when choice.validate() reports a problem.
template <PartitionProvider<PairwiseEnergy> P>
Summary coarse_to_fine(const PairwiseEnergy& energy, P& levels, const SolverChoice& choice,
                       const Options& options, const Observer& observer = {}) {
  if (const std::string problem = choice.validate(); !problem.empty())
    throw std::invalid_argument("solver choice: " + problem);
  switch (choice.kind) {
    case SolverKind::expansion: {
      ExpansionSolver<> solver(ExpansionOptions{choice.order, choice.seed});
      return coarse_to_fine(energy, levels, solver, options, observer);
    }
    case SolverKind::swap: {
      SwapSolver<> solver(SwapOptions{choice.order, choice.seed});
      return coarse_to_fine(energy, levels, solver, options, observer);
    }
    case SolverKind::lbp: {
      LbpSolver solver;
      return coarse_to_fine(energy, levels, solver, options, observer);
    }
    case SolverKind::icm: {
      IcmSolver solver(IcmOptions{choice.order, choice.seed});
      return coarse_to_fine(energy, levels, solver, options, observer);
    }
  }
  throw std::logic_error("coarse_to_fine: unknown solver kind");
}

}  // namespace c2f

#pragma once
// Internal to the graph-cut solvers (expansion, swap): the state both carry between steps.
// Installed only because the solver templates include it; not part of the API.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <memory>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/move_options.hpp"
#include "c2f/core/energy_tally.hpp"
#include "c2f/core/huge_page_allocator.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// Decreases of at most this fraction of max(1, |E|) are rounding, not progress: a labeling
/// whose exact energy ties with the current one may sum to a value a few units in the last
/// place lower, and taking it would restart the count of moves without decrease.
inline constexpr double kRoundingTolerance = 1e-13;

/// How much lower than `value` a move's energy must be to be accepted: MoveOptions::tolerance,
/// at least kRoundingTolerance, times max(1, |value|).
[[nodiscard]] inline double acceptance_margin(double tolerance, double value) noexcept {
  return std::max(tolerance, kRoundingTolerance) * std::max(1.0, std::abs(value));
}

/// The current labeling and its exact energy, the binary problem of a move and its solver, and
/// the candidate labeling a move proposes, accepted only when its exact energy is lower.
template <MaxFlow Backend>
struct MoveState {
  const PairwiseEnergy* energy = nullptr;  ///< null until bind()
  Labeling labeling;                       ///< the current labeling
  Labeling candidate;                      ///< what the current move proposes
  double value = 0.0;                      ///< exact energy of `labeling`
  /// `labeling`'s energy by chunks, for moves that list what they change (tally_changes()).
  EnergyTally tally;
  BinaryMoveSolver<Backend> moves;
  LargeVector<double> d, p;    ///< the move's binary problem (see binary_move.hpp)
  LargeVector<MoveLabel> out;  ///< its solution

  /// Validates `start` against the energy (messages begin with `context`), takes it as the
  /// current labeling and fixes the move graphs' topology; moves with keys 0..num_keys-1 may
  /// recycle their graphs within graph_memory_limit bytes (BinaryMoveSolver::recycle, which
  /// takes first_move_own).
  void bind(const PairwiseEnergy& e, std::span<const Label> start, std::string_view context,
            std::size_t num_keys, std::size_t graph_memory_limit, bool first_move_own = false) {
    validate_labeling(start, e.num_variables(), e.num_labels(), context);
    energy = &e;
    labeling.assign(start.begin(), start.end());
    candidate.resize(labeling.size());
    moves.bind(e);
    moves.recycle(num_keys, graph_memory_limit, first_move_own);
    d.resize(e.num_variables());
    p.resize(e.edges().size());
    out.resize(e.num_variables());
    value = e.evaluate_unchecked(labeling);
    tally = {};
  }

  /// From now on, moves that list the variables they change are evaluated by chunks
  /// (EnergyTally, on up to `threads` threads): call after bind().
  void tally_changes(std::shared_ptr<const EdgeIncidence> incidence, int threads) {
    tally.bind(*energy, labeling, std::move(incidence), threads);
  }

  /// Solves the move's binary problem (d, p) into `out` on the graphs of `key`; returns the
  /// step record of a move between alpha and beta (expansion: beta == alpha) with the solver's
  /// statistics.
  MoveStep solve_move(Label alpha, Label beta, std::size_t key) {
    return solve_move(alpha, beta, key, d, p);
  }

  /// The same for a binary problem held elsewhere.
  MoveStep solve_move(Label alpha, Label beta, std::size_t key, std::span<const double> move_d,
                      std::span<const double> move_p) {
    const BinaryMoveStats stats = moves.solve(move_d, move_p, out, key);
    MoveStep step;
    step.alpha = alpha;
    step.beta = beta;
    step.variables = move_d.size();
    step.unlabeled = stats.unlabeled;
    step.used_qpbo = stats.used_qpbo;
    step.recycled = stats.recycled;
    step.flow_seconds = stats.flow_seconds;
    return step;
  }

  /// Ends a move whose `candidate` differs from the labeling in `changed` variables: takes it
  /// when that lowers the energy (accept_candidate_if_lower) and records that in `step`.
  /// Returns the energy afterwards.
  double finish_move(MoveStep& step, std::size_t changed, double tolerance) {
    if (changed > 0 && accept_candidate_if_lower(tolerance)) {
      step.changed = changed;
      step.improved = true;
    }
    return value;
  }

  /// The same for a candidate that differs from the labeling only in the variables `changed`
  /// lists.
  double finish_move(MoveStep& step, std::span<const VariableIndex> changed, double tolerance) {
    if (!changed.empty() && accept_candidate_if_lower(tolerance, changed)) {
      step.changed = changed.size();
      step.improved = true;
    }
    return value;
  }

  /// Makes `candidate` the current labeling when its exact energy is lower than
  /// value - acceptance_margin(tolerance, value); returns whether it did. The energy therefore
  /// never increases.
  bool accept_candidate_if_lower(double tolerance) {
    const double margin = acceptance_margin(tolerance, value);
    const double candidate_value = energy->evaluate_unchecked(candidate);
    if (!(candidate_value < value - margin)) return false;
    labeling.swap(candidate);
    value = candidate_value;
    return true;
  }

  /// The same for a candidate that differs from the labeling only in the variables `changed`
  /// lists: evaluated by the tally's chunks when tally_changes() was called (the same bits).
  bool accept_candidate_if_lower(double tolerance, std::span<const VariableIndex> changed) {
    if (!tally.bound()) return accept_candidate_if_lower(tolerance);
    const double margin = acceptance_margin(tolerance, value);
    const double candidate_value = tally.evaluate_changed(candidate, changed);
    if (!(candidate_value < value - margin)) return false;
    labeling.swap(candidate);
    value = candidate_value;
    tally.keep();
    return true;
  }
};

}  // namespace c2f::detail

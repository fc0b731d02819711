#pragma once
// Alpha-expansion (Boykov, Veksler and Zabih) as an AnytimeSolver for PairwiseEnergy, with
// QPBO for non-submodular moves (as OpenGM's alpha-expansion fusion, which the paper used).
//
// One step() = one expansion move for one label alpha: every variable may switch to alpha.
// Labels are cycled in the configured order, restarting at the first label on every bind()
// (VisitOrder::frequency: the labels the start labeling uses most first, so that on a coarse
// level handed a labeling, or on the original problem after coarse levels, the moves that
// matter come first and a plateau rule is not fired by a run of unused labels).
// Each label's move problem is kept and patched where accepted moves changed the labeling
// (detail/expansion_problems.hpp), and on the default backend each label's graph is recycled
// (binary_move.hpp), so late moves cost in proportion to what changed since the label's last.
// Each move's binary problem goes straight into the max-flow graph when all its pairwise
// terms are submodular; otherwise it is solved with QPBO on the doubled graph and variables
// QPBO leaves unlabelled keep their label. The move is accepted only when the exact double
// energy of the new labeling is lower than the current one (so the energy never increases,
// and moves that only trade equal-energy labelings are not taken: a sweep without an
// accepted move means no move found a lower energy, which for submodular moves means none
// exists).

#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/expansion_problems.hpp"
#include "c2f/adapters/graphcut/detail/move_state.hpp"
#include "c2f/adapters/graphcut/move_cycle.hpp"
#include "c2f/adapters/graphcut/move_options.hpp"
#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

template <MaxFlow Backend = DynamicMaxFlow>
class ExpansionSolver {
 public:
  /// Throws std::invalid_argument when options.validate() reports a problem.
  explicit ExpansionSolver(ExpansionOptions options = {}) : options_(options) {
    if (const std::string problem = options_.validate(); !problem.empty()) {
      throw std::invalid_argument("ExpansionOptions: " + problem);
    }
  }

  /// Steps in one sweep (one move per label): that many steps without a decrease mean no
  /// single expansion move lowers the energy.
  [[nodiscard]] static std::size_t steps_per_sweep(int num_labels) noexcept {
    return static_cast<std::size_t>(num_labels);
  }

  /// Starts from `start` (validated); fixes the move graphs' topology. Of
  /// options.graph_memory_limit, up to a quarter keeps every label's move problem (d, p) for
  /// patching, the rest recycled move graphs.
  void bind(const PairwiseEnergy& energy, std::span<const Label> start) {
    problems_.bind(energy, options_.graph_memory_limit / 4);
    state_.bind(energy, start, "ExpansionSolver::bind: start",
                static_cast<std::size_t>(energy.num_labels()),
                options_.graph_memory_limit - problems_.memory_bytes());
    std::vector<Label> labels(static_cast<std::size_t>(energy.num_labels()));
    for (std::size_t l = 0; l < labels.size(); ++l) labels[l] = static_cast<Label>(l);
    if (options_.order == VisitOrder::frequency) {
      const std::vector<std::size_t> count = label_counts(state_.labeling, energy.num_labels());
      sort_most_used_first(labels, [&](Label l) { return count[static_cast<std::size_t>(l)]; });
    }
    cycle_ = MoveCycle<Label>(std::move(labels), options_.order, options_.seed);
    last_ = {};
  }

  /// One expansion move; returns the energy afterwards (never larger than before).
  double step() {
    if (state_.energy == nullptr)
      throw std::logic_error("ExpansionSolver::step: call bind() first");
    const Labeling& labeling = state_.labeling;
    const Label alpha = cycle_.next();
    std::span<const double> d, p;
    problems_.update(alpha, labeling, d, p);
    last_ = state_.solve_move(alpha, alpha, static_cast<std::size_t>(alpha), d, p);
    moved_.clear();
    for (std::size_t i = 0; i < labeling.size(); ++i) {
      const bool to_alpha = state_.out[i] == MoveLabel::one && labeling[i] != alpha;
      state_.candidate[i] = to_alpha ? alpha : labeling[i];
      if (to_alpha) moved_.push_back(static_cast<VariableIndex>(i));
    }
    const double value = state_.finish_move(last_, moved_.size(), options_.tolerance);
    if (last_.improved) problems_.log_changes(moved_);
    return value;
  }

  [[nodiscard]] double energy() const noexcept { return state_.value; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return state_.labeling; }
  /// What the last step() did (all zero before the first step of a binding).
  [[nodiscard]] const MoveStep& last_step() const noexcept { return last_; }

 private:
  ExpansionOptions options_;
  detail::MoveState<Backend> state_;
  detail::ExpansionProblems problems_;
  std::vector<VariableIndex> moved_;  // the variables the last move proposed to change
  MoveCycle<Label> cycle_;
  MoveStep last_;
};

static_assert(AnytimeSolver<ExpansionSolver<>, PairwiseEnergy>);

}  // namespace c2f

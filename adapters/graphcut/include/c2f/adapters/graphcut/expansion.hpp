#pragma once
// Alpha-expansion (Boykov, Veksler and Zabih) as an AnytimeSolver for PairwiseEnergy, with
// QPBO for non-submodular moves (as OpenGM's alpha-expansion fusion, which the paper used).
//
// One step() = one expansion move for one label alpha: every variable may switch to alpha
// (with ExpansionOptions::near_radius, only the variables near alpha, in sweeps that alternate with
// whole sweeps: see there and detail/near_moves.hpp). A sweep is one move per label; with
// ExpansionOptions::shift_moves it begins with two shift moves, in which every variable may step
// one label up (then down) at once (detail/shift_moves.hpp).
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

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/expansion_problems.hpp"
#include "c2f/adapters/graphcut/detail/move_state.hpp"
#include "c2f/adapters/graphcut/detail/near_moves.hpp"
#include "c2f/adapters/graphcut/detail/shift_moves.hpp"
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

  /// Steps without a decrease that mean convergence on `energy` with these options: one sweep
  /// (L moves, L + 2 with shift moves); with near moves (ExpansionOptions::near_radius) three
  /// sweeps. Near and whole moves come in sweeps aligned with the label cycle's passes, and a
  /// near sweep without decrease is always followed by a whole one; so three sweeps' steps
  /// without decrease hold two complete sweeps, one of them a whole sweep that found nothing.
  [[nodiscard]] std::size_t quiet_steps_to_converge(const PairwiseEnergy& energy) const noexcept {
    return (options_.near_radius > 0 ? 3 : 1) * steps_per_sweep(energy.num_labels());
  }

  /// Starts from `start` (validated); fixes the move graphs' topology. Every label's move
  /// problem (d, p) is kept for patching within options.problem_memory_limit, recycled move
  /// graphs (keys: the labels, then shifts up and down) within options.graph_memory_limit.
  void bind(const PairwiseEnergy& energy, std::span<const Label> start) {
    problems_.bind(energy, options_.problem_memory_limit);
    state_.bind(energy, start, "ExpansionSolver::bind: start",
                static_cast<std::size_t>(energy.num_labels()) + shift_steps(),
                options_.graph_memory_limit);
    std::vector<Label> labels(static_cast<std::size_t>(energy.num_labels()));
    for (std::size_t l = 0; l < labels.size(); ++l) labels[l] = static_cast<Label>(l);
    if (options_.order == VisitOrder::frequency) {
      const std::vector<std::size_t> count = label_counts(state_.labeling, energy.num_labels());
      sort_most_used_first(labels, [&](Label l) { return count[static_cast<std::size_t>(l)]; });
    }
    cycle_ = MoveCycle<Label>(std::move(labels), options_.order, options_.seed);
    last_ = {};
    if (options_.near_radius > 0) near_.bind(energy, options_.near_radius);
    sweep_steps_done_ = 0;
    whole_sweep_ = options_.near_radius == 0;
  }

  /// Frees what bind() built (move problems, recycled graphs, near-move graphs); the options
  /// stay. bind() again before the next step().
  void release() { *this = ExpansionSolver(options_); }

  /// One move (a sweep's shift moves first, then one expansion move per label); returns the
  /// energy afterwards (never larger than before).
  double step() {
    if (state_.energy == nullptr)
      throw std::logic_error("ExpansionSolver::step: call bind() first");
    if (sweep_steps_done_ == 0) sweep_start_ = state_.value;
    if (sweep_steps_done_ < shift_steps()) {
      shift_move(sweep_steps_done_ == 0 ? 1 : -1);
    } else if (whole_sweep_) {
      whole_move(cycle_.next());
    } else {
      near_move(cycle_.next());
    }
    if (++sweep_steps_done_ == steps_per_sweep(state_.energy->num_labels())) {
      sweep_steps_done_ = 0;
      end_sweep();
    }
    if (last_.improved) problems_.log_changes(moved_);
    return state_.value;
  }

  [[nodiscard]] double energy() const noexcept { return state_.value; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return state_.labeling; }
  /// What the last step() did (all zero before the first step of a binding).
  [[nodiscard]] const MoveStep& last_step() const noexcept { return last_; }
  /// The optional memory in use: the kept move problems (within options.problem_memory_limit)
  /// and the recycled move graphs (within options.graph_memory_limit).
  [[nodiscard]] std::size_t kept_bytes() const noexcept {
    return problems_.memory_bytes() + state_.moves.recycled_bytes();
  }

 private:
  /// Steps of a sweep spent on shift moves: up, then down.
  [[nodiscard]] std::size_t shift_steps() const noexcept { return options_.shift_moves ? 2 : 0; }
  /// Steps in one sweep: the shift moves, then one expansion move per label.
  [[nodiscard]] std::size_t steps_per_sweep(int num_labels) const noexcept {
    return shift_steps() + static_cast<std::size_t>(num_labels);
  }

  /// Chooses the next sweep's moves. With near moves: a near sweep that lowered the energy by
  /// at most near_sweep_gain of it hands over to one sweep of whole moves, then near again.
  void end_sweep() {
    if (options_.near_radius == 0) return;
    if (whole_sweep_) {
      whole_sweep_ = false;
      return;
    }
    const double gain = sweep_start_ - state_.value;
    whole_sweep_ = gain <= options_.near_sweep_gain * std::max(1.0, std::abs(sweep_start_));
  }

  /// The shift move by `shift` labels over every variable (detail/shift_moves.hpp).
  void shift_move(int shift) {
    const Labeling& labeling = state_.labeling;
    shifted_.resize(labeling.size());
    detail::shift_problem(*state_.energy, labeling, shift, shifted_, state_.d, state_.p);
    const auto key = static_cast<std::size_t>(state_.energy->num_labels()) + (shift > 0 ? 0 : 1);
    last_ = state_.solve_move(0, 0, key);
    last_.shift = shift;
    moved_.clear();
    for (std::size_t i = 0; i < labeling.size(); ++i) {
      const bool moves = state_.out[i] == MoveLabel::one && shifted_[i] != labeling[i];
      state_.candidate[i] = moves ? shifted_[i] : labeling[i];
      if (moves) moved_.push_back(static_cast<VariableIndex>(i));
    }
    state_.finish_move(last_, moved_.size(), options_.tolerance);
  }

  /// The move to alpha over every variable.
  void whole_move(Label alpha) {
    const Labeling& labeling = state_.labeling;
    std::span<const double> d, p;
    problems_.update(alpha, labeling, d, p);
    last_ = state_.solve_move(alpha, alpha, static_cast<std::size_t>(alpha), d, p);
    moved_.clear();
    for (std::size_t i = 0; i < labeling.size(); ++i) {
      const bool to_alpha = state_.out[i] == MoveLabel::one && labeling[i] != alpha;
      state_.candidate[i] = to_alpha ? alpha : labeling[i];
      if (to_alpha) moved_.push_back(static_cast<VariableIndex>(i));
    }
    state_.finish_move(last_, moved_.size(), options_.tolerance);
  }

  /// The move to alpha over the variables near alpha (detail/near_moves.hpp), on a graph of
  /// their own built for this move.
  void near_move(Label alpha) {
    near_.build(alpha, state_.labeling);
    const auto free = near_.free();
    last_ = {};
    last_.alpha = last_.beta = alpha;
    last_.near = true;
    moved_.clear();
    if (free.empty()) return;
    near_solver_.bind(free.size(), near_.pairs());
    near_out_.resize(free.size());
    const BinaryMoveStats stats = near_solver_.solve(near_.d(), near_.p(), near_out_);
    last_.unlabeled = stats.unlabeled;
    last_.used_qpbo = stats.used_qpbo;
    last_.flow_seconds = stats.flow_seconds;
    state_.candidate = state_.labeling;
    for (std::size_t k = 0; k < free.size(); ++k) {
      if (near_out_[k] != MoveLabel::one) continue;
      state_.candidate[free[k]] = alpha;
      moved_.push_back(free[k]);
    }
    state_.finish_move(last_, moved_.size(), options_.tolerance);
  }

  ExpansionOptions options_;
  detail::MoveState<Backend> state_;
  detail::ExpansionProblems problems_;
  std::vector<VariableIndex> moved_;  // the variables the last move proposed to change
  MoveCycle<Label> cycle_;
  MoveStep last_;
  std::size_t sweep_steps_done_ = 0;  // steps of the current sweep so far
  double sweep_start_ = 0.0;          // the energy when it began
  bool whole_sweep_ = true;           // it makes whole moves (else near moves)
  // Near moves (options_.near_radius > 0).
  detail::NearMoves near_;
  BinaryMoveSolver<Backend> near_solver_;
  std::vector<MoveLabel> near_out_;
  // Shift moves (options_.shift_moves).
  Labeling shifted_;  // the labeling shifted by the current shift move's shift
};

static_assert(AnytimeSolver<ExpansionSolver<>, PairwiseEnergy>);

}  // namespace c2f

#pragma once
// Alpha-expansion (Boykov, Veksler and Zabih) as an AnytimeSolver for PairwiseEnergy, with
// QPBO for non-submodular moves (as OpenGM's alpha-expansion fusion, which the paper used).
//
// One step() = one expansion move for one label alpha: every variable may switch to alpha
// (with ExpansionOptions::near_radius, only the variables near alpha, in sweeps that alternate with
// whole sweeps: see there and detail/near_moves.hpp). A sweep is one move per label; with
// ExpansionOptions::shift_moves it begins with two shift moves, in which every variable may step
// one label up (then down) at once (detail/shift_moves.hpp).
// With ExpansionOptions::regions and near moves, near and shift moves are made region by region,
// the regions of one colour at once on several threads (detail/region_moves.hpp); a near sweep
// that gains little hands over to a sweep of region moves over every variable, and that one to
// a sweep of whole moves.
// Labels are cycled in the configured order, restarting at the first label on every bind()
// (VisitOrder::frequency: the labels the start labeling uses most first, so that on a coarse
// level handed a labeling, or on the original problem after coarse levels, the moves that
// matter come first and a plateau rule is not fired by a run of unused labels).
// Each label's move problem is kept and patched where accepted moves changed the labeling
// (detail/expansion_problems.hpp), and on the default backend each label's graph is recycled
// (binary_move.hpp), so late moves cost in proportion to what changed since the label's last.
// Each move's binary problem goes straight into the max-flow graph when all its pairwise
// terms are submodular; otherwise it is solved with QPBO on the doubled graph and variables
// QPBO leaves unlabelled keep their label. The max-flow is solved in parts at once on several
// threads (ExpansionOptions::flow_parts, up to 4 by default with our max-flow), and the passes
// over a move's variables and edges run by bands (detail/bands.hpp); results never depend on
// the thread count. The move is accepted only when the exact double energy of the new
// labeling, re-summed where the move changed it (EnergyTally), is lower than the current one
// by more than rounding (detail::acceptance_margin; so the energy never increases, and moves
// that only trade equal-energy labelings are not taken: a sweep without an accepted move
// means no move found a lower energy, which for submodular moves means none exists).

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/expansion_problems.hpp"
#include "c2f/adapters/graphcut/detail/move_state.hpp"
#include "c2f/adapters/graphcut/detail/near_moves.hpp"
#include "c2f/adapters/graphcut/detail/region_layout.hpp"
#include "c2f/adapters/graphcut/detail/region_moves.hpp"
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
  /// (L moves, L + 2 with shift moves) when every sweep is a whole one; else K + 1 sweeps, K
  /// being the kinds of sweep in use (near, region, whole). Sweeps are aligned with the label
  /// cycle's passes, and a near or region sweep without decrease is always followed by the
  /// next kind up, ending in a whole sweep; so K + 1 sweeps' steps without decrease hold K
  /// complete sweeps, the last a whole sweep that found nothing.
  [[nodiscard]] std::size_t quiet_steps_to_converge(const PairwiseEnergy& energy) const {
    const bool near = makes_near_moves(options_, energy);
    const std::size_t kinds = 1 + (near ? 1 : 0) + (near && regions_on(energy) ? 1 : 0);
    const std::size_t shifts = makes_shift_moves(options_, energy) ? 2 : 0;
    return (kinds == 1 ? 1 : kinds + 1) * (shifts + static_cast<std::size_t>(energy.num_labels()));
  }

  /// Starts from `start` (validated); fixes the move graphs' topology. Every label's move
  /// problem (d, p) is kept for patching within options.problem_memory_limit, recycled move
  /// graphs (keys: the labels, then shifts up and down) within options.graph_memory_limit.
  void bind(const PairwiseEnergy& energy, std::span<const Label> start) {
    // One set of edge incidences for the kept problems, the regions and the near moves.
    detail::SharedIncidence incidences(energy);
    problems_.bind(energy, options_.problem_memory_limit, &incidences, options_.threads);
    shift_moves_ = makes_shift_moves(options_, energy);
    const std::size_t keys = static_cast<std::size_t>(energy.num_labels()) + shift_steps();
    near_radius_ = makes_near_moves(options_, energy) ? options_.near_radius : 0;
    // recycled_graph_limit, for this energy (no near moves on it: the whole limit).
    const std::size_t graph_limit =
        near_radius_ > 0 ? recycled_graph_limit(options_) : options_.graph_memory_limit;
    regions_ = {};
    if (options_.regions > 1 && near_radius_ > 0) {
      regions_.bind(energy, static_cast<std::size_t>(options_.regions), keys, graph_limit,
                    options_.threads, detail::kMinRegionVariables, &incidences);
    }
    // Region and whole sweeps never hold their graphs at once (end_sweep), so each may recycle
    // within the whole limit.
    state_.bind(energy, start, "ExpansionSolver::bind: start", keys, graph_limit,
                options_.first_move_own_graph);
    state_.tally_changes(incidences.get(), options_.threads);
    incidence_ = shift_moves_ ? incidences.get() : nullptr;
    parts_ = flow_parts(energy);
    state_.moves.solve_in_parts(parts_, options_.threads);
    std::vector<Label> labels(static_cast<std::size_t>(energy.num_labels()));
    for (std::size_t l = 0; l < labels.size(); ++l) labels[l] = static_cast<Label>(l);
    if (options_.order == VisitOrder::frequency) {
      const std::vector<std::size_t> count = label_counts(state_.labeling, energy.num_labels());
      sort_most_used_first(labels, [&](Label l) { return count[static_cast<std::size_t>(l)]; });
    }
    cycle_ = MoveCycle<Label>(std::move(labels), options_.order, options_.seed);
    last_ = {};
    if (near_radius_ > 0) {
      near_.bind(energy, near_radius_, near_seeds_in_use(options_, energy), &incidences,
                 options_.threads);
    }
    sweep_steps_done_ = 0;
    sweep_ = first_sweep();
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
      const int shift = sweep_steps_done_ == 0 ? 1 : -1;
      if (sweep_ == Sweep::whole || !regions_.active()) {
        shift_move(shift);
      } else {
        region_move(Move::shift, 0, shift);
      }
    } else if (sweep_ == Sweep::whole) {
      whole_move(cycle_.next());
    } else if (sweep_ == Sweep::regions) {
      region_move(Move::whole, cycle_.next(), 0);
    } else if (regions_.active()) {
      region_move(Move::near, cycle_.next(), 0);
    } else {
      near_move(cycle_.next());
    }
    if (++sweep_steps_done_ == steps_per_sweep(state_.energy->num_labels())) {
      sweep_steps_done_ = 0;
      end_sweep();
    }
    return state_.value;
  }

  [[nodiscard]] double energy() const noexcept { return state_.value; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return state_.labeling; }
  /// What the last step() did (all zero before the first step of a binding).
  [[nodiscard]] const MoveStep& last_step() const noexcept { return last_; }
  /// The optional memory in use: the kept move problems (within options.problem_memory_limit)
  /// and the recycled move graphs (within options.graph_memory_limit).
  [[nodiscard]] std::size_t kept_bytes() const noexcept {
    return problems_.memory_bytes() + state_.moves.recycled_bytes() + regions_.recycled_bytes();
  }
  /// Whether this binding's sweeps begin with shift moves (makes_shift_moves).
  [[nodiscard]] bool shift_moves() const noexcept { return shift_moves_; }
  /// The regions of this binding's moves (1: none, every move is over every variable).
  [[nodiscard]] std::size_t region_count() const noexcept {
    return regions_.active() ? regions_.count() : 1;
  }

  /// The parts the max-flow of a move over n variables is solved in
  /// (ExpansionOptions::flow_parts; 0: kDefaultFlowParts): at most that many, at least
  /// kMinRegionVariables variables each, at least one; one on a backend that cannot solve in
  /// parts.
  [[nodiscard]] std::size_t flow_parts(std::size_t n) const noexcept {
    if constexpr (!PartedMaxFlow<Backend>) return 1;
    const int wanted = options_.flow_parts == 0 ? kDefaultFlowParts : options_.flow_parts;
    return std::max<std::size_t>(1, std::min<std::size_t>(static_cast<std::size_t>(wanted),
                                                          n / detail::kMinRegionVariables));
  }

  /// The parts the max-flow of a move over every variable of `energy` is solved in:
  /// flow_parts(n), except that by default (ExpansionOptions::flow_parts = 0) it is the most
  /// parts up to flow_parts(n) for which at most kMaxShareBetweenParts of the energy's edges join
  /// variables of different parts, one when there are none (on a graph without locality in its
  /// variable order the parts' flows leave nearly all the work to the stage that joins them; a
  /// coarse level, whose large groups have neighbours in many rows, often passes with 2 parts
  /// and not with 4). Near moves use at most as many. O(E) per count tried.
  [[nodiscard]] std::size_t flow_parts(const PairwiseEnergy& energy) const {
    const std::size_t parts = flow_parts(energy.num_variables());
    if (parts < 2 || options_.flow_parts != 0) return parts;
    for (std::size_t count = parts; count >= 2; --count) {
      if (share_of_edges_between_parts(energy, count) <= kMaxShareBetweenParts) return count;
    }
    return 1;
  }

 private:
  /// Steps of a sweep spent on shift moves: up, then down.
  [[nodiscard]] std::size_t shift_steps() const noexcept { return shift_moves_ ? 2 : 0; }
  /// Steps in one sweep: the shift moves, then one expansion move per label.
  [[nodiscard]] std::size_t steps_per_sweep(int num_labels) const noexcept {
    return shift_steps() + static_cast<std::size_t>(num_labels);
  }

  /// The kinds of sweep: near moves (ExpansionOptions::near_radius; by regions when there are
  /// regions), moves over every variable by regions, and whole moves over every variable.
  enum class Sweep { near, regions, whole };
  /// The kinds of move a region move makes.
  enum class Move { whole, near, shift };

  /// Whether moves on `energy` are made by regions (at least two in its layout).
  [[nodiscard]] bool regions_on(const PairwiseEnergy& energy) const {
    return options_.regions > 1 &&
           detail::region_layout(energy, static_cast<std::size_t>(options_.regions)).count() >= 2;
  }

  /// The sweep a binding starts with, and returns to after each whole sweep. Without near
  /// moves every sweep is a whole one: sweeps of region moves then cost more steps to
  /// convergence than their threads save (docs/performance.md).
  [[nodiscard]] Sweep first_sweep() const noexcept {
    return near_radius_ > 0 ? Sweep::near : Sweep::whole;
  }

  /// Chooses the next sweep's moves: a near or region sweep that lowered the energy by at most
  /// near_sweep_gain of it hands over to the next kind up (near, regions, whole); a whole sweep
  /// hands back to the first kind. Region and whole moves never hold their graphs at once.
  void end_sweep() {
    const double gain = sweep_start_ - state_.value;
    const bool stalled = gain <= options_.near_sweep_gain * std::max(1.0, std::abs(sweep_start_));
    const Sweep before = sweep_;
    switch (sweep_) {
      case Sweep::near:
        if (stalled) sweep_ = regions_.active() ? Sweep::regions : Sweep::whole;
        break;
      case Sweep::regions:
        if (stalled) sweep_ = Sweep::whole;
        break;
      case Sweep::whole:
        sweep_ = first_sweep();
        break;
    }
    if (!regions_.active() || sweep_ == before) return;
    if (sweep_ == Sweep::whole) {
      regions_.drop_graphs();
    } else if (before == Sweep::whole) {
      state_.moves.drop_graphs();
    }
  }

  /// The shift move by `shift` labels over every variable (detail/shift_moves.hpp).
  void shift_move(int shift) {
    const Labeling& labeling = state_.labeling;
    shifted_.resize(labeling.size());
    detail::shift_problem(*state_.energy, *incidence_, labeling, shift, shifted_, state_.d,
                          state_.p, options_.threads);
    const auto key = static_cast<std::size_t>(state_.energy->num_labels()) + (shift > 0 ? 0 : 1);
    last_ = state_.solve_move(0, 0, key);
    last_.shift = shift;
    propose([this](std::size_t i) { return shifted_[i]; });
    finish_move();
  }

  /// The move to alpha over every variable.
  void whole_move(Label alpha) {
    const Labeling& labeling = state_.labeling;
    std::span<const double> d, p;
    problems_.update(alpha, labeling, d, p);
    last_ = state_.solve_move(alpha, alpha, static_cast<std::size_t>(alpha), d, p);
    propose([alpha](std::size_t) { return alpha; });
    finish_move();
  }

  /// The candidate of a move over every variable: variable i takes proposal(i) where the move's
  /// solution says so (state_.out[i] is one) and that is not its label, else keeps its label;
  /// moved_ lists the variables that change, ascending. By bands on the threads.
  template <class Proposal>
  void propose(const Proposal& proposal) {
    const Labeling& labeling = state_.labeling;
    moved_.clear();
    detail::append_by_bands(
        labeling.size(), band_moved_, moved_,
        [&](std::size_t first, std::size_t last, std::vector<VariableIndex>& out) {
          for (std::size_t i = first; i < last; ++i) {
            const Label to = proposal(i);
            const bool moves = state_.out[i] == MoveLabel::one && to != labeling[i];
            state_.candidate[i] = moves ? to : labeling[i];
            if (moves) out.push_back(static_cast<VariableIndex>(i));
          }
        },
        options_.threads);
  }

  /// The move to alpha over the variables near alpha (detail/near_moves.hpp), on a graph of
  /// their own built for this move.
  void near_move(Label alpha) {
    near_.build(alpha, state_.labeling);
    const auto free = near_.free();
    last_ = {};
    last_.alpha = last_.beta = alpha;
    last_.near = true;
    last_.variables = free.size();
    moved_.clear();
    if (free.empty()) return;
    near_solver_.bind(free.size(), near_.pairs());
    near_solver_.solve_in_parts(std::min(parts_, flow_parts(free.size())), options_.threads);
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
    finish_move();
  }

  /// Ends a move over every variable or over the near ones: takes its candidate when it lowers
  /// the energy, and logs what changed for the kept problems.
  void finish_move() {
    state_.finish_move(last_, moved_, options_.tolerance);
    if (last_.improved) problems_.log_changes(moved_);
  }

  /// A move made by regions (detail/region_moves.hpp): to `alpha` over every variable
  /// (Move::whole) or the near ones (Move::near), or by `shift` labels (Move::shift). Each
  /// phase's problem is built from the labeling the phase before left; a near move's variables
  /// are chosen once, from the labeling it begins with (each phase's variables keep their labels
  /// until that phase). The move as a whole is then checked as every move is: its labeling's
  /// exact energy must be lower (MoveState::accept_candidate_if_lower), else it is undone, so
  /// energy() is always the energy of labeling().
  void region_move(Move move, Label alpha, int shift) {
    const PairwiseEnergy& energy = *state_.energy;
    last_ = {};
    last_.alpha = last_.beta = alpha;
    last_.shift = shift;
    last_.near = move == Move::near;
    moved_.clear();
    state_.candidate = state_.labeling;
    move_start_ = state_.labeling;
    const double start_value = state_.value;
    if (move == Move::near) near_.select(alpha, state_.labeling);
    const std::size_t variables = move == Move::near ? near_.free().size() : state_.labeling.size();
    const auto key = move == Move::shift
                         ? static_cast<std::size_t>(energy.num_labels()) + (shift > 0 ? 0 : 1)
                         : static_cast<std::size_t>(alpha);
    for (int colour = 0; colour < 2; ++colour) {
      const std::size_t before = moved_.size();
      if (move == Move::near) {
        regions_.near_phase(colour, alpha, near_, options_.tolerance, state_.labeling,
                            state_.candidate, state_.value, moved_, last_);
      } else {
        detail::MoveProblem problem;
        if (move == Move::whole) {
          problems_.update(alpha, state_.labeling, problem.d, problem.p);
          problem.proposal = [alpha](VariableIndex) { return alpha; };
        } else {
          shifted_.resize(state_.labeling.size());
          detail::shift_problem(energy, state_.labeling, shift, shifted_, state_.d, state_.p);
          problem.d = state_.d;
          problem.p = state_.p;
          problem.proposal = [this](VariableIndex v) { return shifted_[v]; };
        }
        regions_.phase(colour, problem, key, options_.tolerance, state_.labeling, state_.candidate,
                       state_.value, moved_, last_);
      }
      problems_.log_changes(std::span<const VariableIndex>(moved_).subspan(before));
    }
    last_.variables = variables;
    // The regions' changes summed; the exact energy decides, as for a move on one graph.
    // The candidate already holds the moved labeling; the labeling goes back to the start.
    state_.value = start_value;
    state_.labeling.swap(move_start_);
    if (!moved_.empty() && state_.accept_candidate_if_lower(options_.tolerance, moved_)) {
      last_.changed = moved_.size();
      last_.improved = true;
    } else {
      state_.candidate = state_.labeling;
      problems_.log_changes(moved_);  // back to where the move began
      moved_.clear();
    }
  }

  ExpansionOptions options_;
  bool shift_moves_ = false;  // this binding makes shift moves (makes_shift_moves)
  int near_radius_ = 0;       // this binding's near radius (0 unless makes_near_moves)
  std::size_t parts_ = 1;     // the parts of this binding's moves over every variable
  detail::MoveState<Backend> state_;
  detail::ExpansionProblems problems_;
  std::vector<VariableIndex> moved_;  // the variables the last move proposed to change
  std::vector<std::vector<VariableIndex>> band_moved_;  // propose()'s, per band
  MoveCycle<Label> cycle_;
  MoveStep last_;
  std::size_t sweep_steps_done_ = 0;  // steps of the current sweep so far
  double sweep_start_ = 0.0;          // the energy when it began
  Sweep sweep_ = Sweep::whole;        // the kind of the current sweep
  // Region moves (options_.regions).
  detail::RegionMoves<Backend> regions_;
  Labeling move_start_;  // the labeling a region move began with
  // Near moves (near_radius_ > 0).
  detail::NearMoves near_;
  BinaryMoveSolver<Backend> near_solver_;
  std::vector<MoveLabel> near_out_;
  // Shift moves (options_.shift_moves).
  Labeling shifted_;  // the labeling shifted by the current shift move's shift
  std::shared_ptr<const EdgeIncidence> incidence_;  // for shift moves' problems by bands
};

static_assert(AnytimeSolver<ExpansionSolver<>, PairwiseEnergy>);

}  // namespace c2f

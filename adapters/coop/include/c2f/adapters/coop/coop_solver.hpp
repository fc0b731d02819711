#pragma once
// Cooperative-cut segmentation as an AnytimeSolver for CoopEnergy: the auxiliary variables h
// (coop_energy.hpp) are updated by one of three strategies, and for a given h the labels are
// found by alpha-expansion of the pairwise energy E_h. Every step reports the true cooperative-
// cut energy of the labeling it keeps, which never increases.
//
//   greedy  the cooperative-cuts reference's descent: one step tries one flip of h(l, g)
//           (labels outer, classes inner), runs alpha-expansion of E_h from the all-zero
//           labeling (the reference) or from the current one, and keeps both only when the true
//           energy decreases. The first step of every binding tries h unchanged.
//   mm      majorise-minimise: h := the optimum for the current labeling (closed form, so
//           E_h(x) + const = E(x)), then one cycle of alpha-expansion of E_h from x; E cannot
//           increase. A step whose h is the last step's goes on with the same expansion; a
//           step known to change nothing is not solved (CoopStep::known_quiet).
//   ceres   a continuous relaxation: label probabilities per pixel (softmax of free logits),
//           relaxed directed cut sizes per (label, class), a smooth concave surrogate of F
//           (soft minimum of its two branches); minimised with Ceres' L-BFGS, warm-started from
//           the previous step's solution (the labeling kept, its label 2 ahead in the logits;
//           a softer start drifts to many-boundary solutions of higher energy, measured); h is
//           read off the relaxed cut sizes, then alpha-expansion of E_h from x, kept only when
//           the true energy decreases.
// h is solver state that means the same on every level (indexed by label and class), so it
// carries over between levels of a coarse-to-fine run.

#include <cstddef>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/adapters/graphcut/move_options.hpp"
#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/labeling.hpp"

namespace c2f {

enum class AuxStrategy { greedy, mm, ceres };

std::string_view to_string(AuxStrategy strategy);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
AuxStrategy aux_strategy_from_string(std::string_view text);

/// Where the greedy strategy's alpha-expansion starts.
enum class ExpansionStart {
  zero,     ///< the all-zero labeling, every trial (the reference)
  current,  ///< the current labeling (warm start)
};

std::string_view to_string(ExpansionStart start);
ExpansionStart expansion_start_from_string(std::string_view text);

struct RelaxationOptions {
  int max_iterations = 30;  ///< L-BFGS iterations per step
  /// Temperature of the soft minimum that smooths F_g, as a fraction of the class's breakpoint.
  double smoothing = 0.05;

  [[nodiscard]] std::string validate() const;
};

struct CoopSolverOptions {
  AuxStrategy strategy = AuxStrategy::mm;
  ExpansionStart start = ExpansionStart::zero;  ///< greedy only
  /// Cycles over all labels of one step's alpha-expansion of E_h (it stops earlier after a
  /// cycle that does not lower E_h); 0: the strategy's own, cycles().
  int expansion_cycles = 0;
  RelaxationOptions relaxation;  ///< ceres only
  /// Bytes each step's alpha-expansion may keep in recycled move graphs
  /// (MoveOptions::graph_memory_limit); the run layer (c2f/run/coop_run.hpp) lowers it to what
  /// a run's memory budget leaves.
  std::size_t graph_memory_limit = MoveOptions{}.graph_memory_limit;
  /// Threads each step's alpha-expansion solves its max-flow's parts on
  /// (ExpansionOptions::threads; 0: the machine's cores). The result is the same for every count.
  int threads = 0;
  /// Near moves in each step's alpha-expansion (ExpansionOptions::near_radius, seeded by the
  /// label's own variables) on energies of at least near_moves_min_variables variables; 0:
  /// whole moves only. A cycle then is one sweep of near moves that lowers E_h, or a sweep of
  /// near moves that lowers nothing followed by a sweep of whole moves, so a quiet cycle ends
  /// in a whole sweep that found nothing.
  int near_radius = 0;
  std::size_t near_moves_min_variables = 0;  ///< with near_radius > 0; 0: any size

  /// The cycles each step's alpha-expansion makes at most: expansion_cycles, or by default 10
  /// for greedy and ceres (the reference's expansion(10)) and 1 for mm, whose next step then
  /// starts from a fresh h = optimal_for(x) (E_h is tighter there); when that h is the same,
  /// the step goes on with the same alpha-expansion, so a fixed point is still confirmed by a
  /// cycle that lowers nothing.
  [[nodiscard]] int cycles() const noexcept;
  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
};

/// What the last step did.
struct CoopStep : StepOutcome {
  int flipped_label = -1;  ///< greedy: the h entry tried (-1: h unchanged)
  int flipped_class = -1;
  std::size_t aux_changes = 0;  ///< entries of h the step changed and kept
  std::size_t expansion_moves = 0;
  double relaxation_seconds = 0.0;  ///< ceres: time in the relaxation
  /// mm: the step was known to change nothing and was not solved. Its h = optimal_for(x) is
  /// the h of the step before, which either kept nothing (the step would repeat it) or kept x
  /// from an expansion of E_h whose last cycle moved nothing (x is that expansion's fixed
  /// point). Reset by bind().
  bool known_quiet = false;
};

class CoopSolver {
 public:
  /// Throws std::invalid_argument when options.validate() reports a problem.
  explicit CoopSolver(CoopSolverOptions options = {});
  ~CoopSolver();
  CoopSolver(CoopSolver&&) noexcept;
  CoopSolver& operator=(CoopSolver&&) noexcept;

  /// Steps without a decrease that mean convergence on `energy`: a whole sweep of flips for
  /// greedy (num_labels * num_classes + 1), one step for mm (a fixed point), two for ceres (the
  /// warm-started relaxation may still move once).
  [[nodiscard]] std::size_t quiet_steps_to_converge(const CoopEnergy& energy) const noexcept;

  /// The parts each step's alpha-expansion on `energy` solves its max-flow in
  /// (ExpansionSolver::flow_parts of the energy's pairwise form, whose edges do not depend on h).
  [[nodiscard]] std::size_t flow_parts(const CoopEnergy& energy) const;

  /// Starts from `start` (validated). h is kept from the previous binding when it has this
  /// energy's shape (labels, classes), else it starts all 1.
  void bind(const CoopEnergy& energy, std::span<const Label> start);
  /// One step of the strategy; returns the true energy of the labeling kept.
  double step();

  [[nodiscard]] double energy() const noexcept { return value_; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return labeling_; }
  [[nodiscard]] const CoopStep& last_step() const noexcept { return last_; }
  /// The current auxiliary variables.
  [[nodiscard]] const CoopAuxiliary& aux() const noexcept { return h_; }
  /// The most optional memory (recycled move graphs, kept move problems) any of this solver's
  /// alpha-expansions has held (within options.graph_memory_limit).
  [[nodiscard]] std::size_t kept_bytes() const noexcept { return kept_bytes_; }

 private:
  struct Relaxation;
  struct KeptExpansion;
  /// Alpha-expansion of E_h from `start` (options.cycles() cycles at most); the labeling it
  /// ends with. The expansion is kept after the step, and the next call with the same h from
  /// the labeling it ended with goes on with it (its recycled graphs, its kept move problems)
  /// instead of building E_h and its graphs again.
  Labeling expand_for(const CoopAuxiliary& h, std::span<const Label> start);
  /// Keeps `candidate` (and h) when its true energy is lower; fills last_.
  void keep_if_lower(Labeling candidate, const CoopAuxiliary& h);
  void greedy_step();
  void mm_step();
  void ceres_step();

  CoopSolverOptions options_;
  const CoopEnergy* energy_ = nullptr;
  Labeling labeling_;
  double value_ = 0.0;
  CoopAuxiliary h_;
  CoopStep last_;
  bool tried_unchanged_ = false;  ///< greedy: the binding's first trial (h unchanged) is done
  std::size_t next_flip_ = 0;     ///< greedy: index l * K + g of the next entry to flip
  std::ptrdiff_t last_kept_flip_ = -1;
  std::unique_ptr<Relaxation> relaxation_;
  std::unique_ptr<KeptExpansion> expansion_;  ///< the last step's, for this binding
  std::size_t kept_bytes_ = 0;
  bool expansion_ended_quiet_ = false;  ///< expand_for's last cycle lowered nothing
  /// mm: an h whose step from the current labeling is known to change nothing (CoopStep::
  /// known_quiet); empty after bind() and after a step that kept a labeling still moving.
  std::optional<CoopAuxiliary> quiet_for_;
};

static_assert(AnytimeSolver<CoopSolver, CoopEnergy>);

}  // namespace c2f

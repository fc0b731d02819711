#pragma once
// What the graph-cut solvers (expansion, swap) are told and what they report per step.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/visit_order.hpp"

namespace c2f {

/// What every graph-cut solver (expansion, swap) is told. ICM's IcmOptions has order and seed
/// with the same meaning.
struct MoveOptions {
  VisitOrder order = VisitOrder::sequential;
  std::uint64_t seed = 1;  ///< for VisitOrder::random
  /// A move is accepted when E_new < E_old - max(tolerance, 1e-13) * max(1, |E_old|): with 0
  /// every move that lowers the energy by more than the rounding of its sum is accepted (a
  /// move whose exact energy ties may sum a few units in the last place lower).
  double tolerance = 0.0;
  /// Bytes recycled move graphs may take. With a backend that resumes from its flow (the
  /// default DynamicMaxFlow), each label (expansion) or label pair (swap) keeps its own move
  /// graphs from its second move on while they fit (binary_move.hpp), so a repeated move costs
  /// in proportion to what changed since; moves beyond the limit share one graph. 0 turns
  /// recycling off; expansion with near moves recycles none unless asked to
  /// (recycled_graph_limit). With exact arithmetic results do not depend on it; with rounding,
  /// ties between minimum cuts may break differently.
  std::size_t graph_memory_limit = std::size_t{13} << 28;  // 3.25 GiB
  /// With recycling, false (the default): a key's first move re-solves one shared graph from
  /// whatever move it solved before, and the key gets a graph of its own, a copy of the graph
  /// solved last, on its second move. true: a key's first move builds a graph of its own and
  /// solves it from zero flow, so its second move changes only what moved since its first. That
  /// pays where consecutive keys' moves have little in common, as the two labels' moves of a
  /// binary problem: CoopSolver sets it for E_h (docs/segmentation.md). From a labeling near
  /// its minimum, as on the original level of a coarse-to-fine grid run, re-solving the shared
  /// graph is faster (docs/history/results-2026-12.md).
  bool first_move_own_graph = false;

  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
  bool operator==(const MoveOptions&) const = default;
};

/// Alpha-beta swap's options: those every graph-cut solver has.
struct SwapOptions : MoveOptions {
  bool operator==(const SwapOptions&) const = default;
};

/// Where a near move's search for its free variables starts (ExpansionOptions::near_seeds).
enum class NearSeeds {
  /// The variables labelled alpha and those whose cheapest unary label is alpha: a label no
  /// variable has yet can still spread from where its unaries favour it.
  label_and_cheapest,
  /// The variables labelled alpha only: a move to alpha moves the edges of alpha's regions. From
  /// a labeling handed down by a coarse level, where what is left to do lies along the regions'
  /// edges, it frees far fewer variables than label_and_cheapest on noisy unaries (whose
  /// cheapest labels are scattered everywhere); a label no variable has is left to the sweeps of
  /// whole moves.
  label,
  /// As label, and on an energy of at least kMinLabelsForAdjacentSeeds labels also the
  /// variables labelled alpha - 1 or alpha + 1: a region one label off alpha may move to it as a
  /// whole, however wide. Where labels stand for ordered values that vary smoothly (depths,
  /// intensities), a coarse level leaves steps of a staircase one label off, which moves from
  /// alpha's regions reach only a radius at a time. Alpha-expansion seeds as label where it
  /// makes shift moves (makes_shift_moves), which move such steps already (docs/results.md,
  /// "Defaults").
  label_and_adjacent,
};

/// NearSeeds::label_and_adjacent seeds from alpha's neighbouring labels only on an energy of at
/// least this many labels: with fewer, those labels' variables are a large share of all, and a
/// near move costs about what a whole move does (on the suite's 8-label grids it reached flat's
/// energy later than label; on the 32-label grids sooner).
inline constexpr int kMinLabelsForAdjacentSeeds = 16;

std::string_view to_string(NearSeeds seeds);
/// Parses the names to_string produces ("label_and_cheapest", "label", "label_and_adjacent");
/// throws std::invalid_argument naming the text.
NearSeeds near_seeds_from_string(std::string_view text);

/// Whether a text names seeds as configured (they may still be narrowed on an energy) or as
/// near_seeds_in_use decided them for one.
enum class SeedsAs { configured, in_use };

/// "near moves of radius R", then " from their label" with NearSeeds::label; with
/// NearSeeds::label_and_adjacent " from their label and, on 16 labels or more without shift
/// moves, the labels next to it" as configured, " from their label and the labels next to it"
/// in use; as the tools' summaries name them.
std::string near_moves_text(int radius, NearSeeds seeds, SeedsAs as = SeedsAs::configured);

/// The name the tools and Python give ExpansionOptions::near_moves_only_if_local: "local"
/// (true) or "any" (false).
std::string_view near_graphs_name(bool only_if_local);
/// Parses "local" or "any" (near_graphs_name); throws std::invalid_argument naming the text.
bool near_only_if_local_from_string(std::string_view text);

/// Alpha-expansion's options: those every graph-cut solver has, and its own kinds of move.
struct ExpansionOptions : MoveOptions {
  /// 0: every move may change every variable. r > 0: a move to alpha frees only the variables
  /// within r edges of a variable labelled alpha or, with NearSeeds::label_and_cheapest, of one
  /// whose cheapest unary label is alpha, or with NearSeeds::label_and_adjacent (16 labels or
  /// more, no shift moves) of one labelled alpha - 1 or alpha + 1 (the others keep their labels:
  /// an exact move on a smaller graph of its own). When a sweep of such moves lowers the energy by
  /// at most near_sweep_gain of it, one sweep of whole moves follows, then near moves again.
  /// Convergence therefore takes three sweeps without decrease (ExpansionSolver::sweep_steps).
  int near_radius = 0;
  /// See near_radius: 1e-4 was the best of 0, 1e-4 and 3e-4 on Teddy (docs/performance.md).
  double near_sweep_gain = 1e-4;
  /// With near_radius > 0: the whole sweeps still recycle each label's move graph within
  /// graph_memory_limit (false, the default: none, recycled_graph_limit). That pays where the
  /// whole sweeps after near sweeps repeat with few changes and few labels, as in a cooperative
  /// cut's majorise-minimise steps on a binary image. With first_move_own_graph each label's
  /// first whole move builds the graph its later ones resume (CoopSolver sets both: the step
  /// that confirms convergence resumes its graphs instead of solving them from zero flow).
  bool recycle_with_near_moves = false;
  /// Where near moves start (NearSeeds); only with near_radius > 0.
  NearSeeds near_seeds = NearSeeds::label_and_cheapest;
  /// With near_radius > 0: make near moves only on an energy whose edges are local in its
  /// variables' order (edges_local: a pixel grid, a lattice), decided when the solver is bound;
  /// on any other energy every move is a whole move. On a random graph r rounds of neighbours
  /// reach nearly every variable, so a near move is a whole move on a graph built afresh:
  /// random graphs took 1.95-2.01x flat's time to its energy with near moves from their label
  /// against 1.02-1.11x with whole moves, while lattices gained (docs/history/results-2026-12.md,
  /// "How the defaults were chosen").
  bool near_moves_only_if_local = false;
  /// With near_radius > 0: make near moves only on an energy of at least this many variables
  /// (0: any size), decided when the solver is bound; on a smaller one every move is a whole
  /// move. Whole moves recycle their graphs, which on a small energy costs little, while a near
  /// move builds a graph of its own: on the suite's grids near moves from their label reached
  /// flat's energy sooner from 0.3 MP on (tuning median 0.27 against 0.43 with whole moves) but
  /// not at 0.1 MP (0.54 against 0.51; docs/history/results-2026-12.md, "How the defaults were
  /// chosen").
  std::size_t near_moves_min_variables = 0;
  /// Bytes the kept move problems may take: every label's move problem (d, p) is kept for
  /// patching when all of them fit (detail/expansion_problems.hpp), so a move's problem costs
  /// in proportion to what changed since that label's last move. 0 turns it off; results never
  /// depend on it (a patched problem is bitwise the one computed in full).
  std::size_t problem_memory_limit = std::size_t{13} << 26;  // 0.8125 GiB
  /// Every sweep begins with two shift moves (detail/shift_moves.hpp): every variable may step
  /// one label up, in one move; then one label down. For labels with an order (disparities),
  /// they move a region that is off by one label all at once, which no expansion move can; the
  /// solver then converges where neither kind of move helps. A sweep then has L + 2 steps
  /// (ExpansionSolver::sweep_steps).
  bool shift_moves = false;
  /// With shift_moves false: make shift moves anyway on an energy where some expansion move is
  /// not submodular (!expansion_moves_submodular; e.g. truncated quadratic and TSGO step
  /// terms), decided when the solver is bound. There whole expansion moves alone stop in
  /// staircases of labels that shift moves leave (synthetic truncated-quadratic grids: flat
  /// runs up to 9e-3 higher, and coarse to fine often never within 1e-4 of flat;
  /// docs/history/results-2026-12.md, "How the defaults were chosen").
  bool shift_moves_unless_submodular = false;
  /// Parallel near moves: with near_radius > 0, the variables are cut into at most this many
  /// regions (about equal ranges of indices, at least 4096 variables each, every edge inside
  /// one range or between adjacent ones: bands of rows on a grid; detail/region_layout.hpp),
  /// and near and shift moves are made on the even regions at once, then on the odd ones, the
  /// others held at their labels: an exact move per region, taken when it lowers the energy.
  /// A near sweep that gains at most near_sweep_gain hands over to a sweep of moves over every
  /// variable made by regions, and that one, when it gains as little, to a sweep of whole moves,
  /// so convergence means what it means without regions (quiet_steps_to_converge). The layout
  /// depends on the energy and this number only, so results do not depend on `threads`.
  /// 1 (the default): no regions, every move on one thread. Without near moves it has no
  /// effect. 16 regions on 2 threads measured 1.20x faster to converge on Teddy but 0.77-1.05x
  /// on the aside 2014 Q and KITTI scenes (more sweeps to converge), so it is not the default
  /// (docs/performance.md, "The solve").
  int regions = 1;
  /// Threads solving a move's regions, or its max-flow's parts, at once (0: the machine's
  /// cores). Results are the same for every count.
  int threads = 0;
  /// Moves solve their max-flow (whole and shift moves over every variable, near moves over
  /// their free variables) in this many parts at once on `threads` threads: bands of about
  /// equal ranges of the move's variable indices (bands of rows on a grid), each part's flow
  /// found on its own, then the whole graph's from those (DynamicMaxFlow::solve_cut_in_parts,
  /// resolve_in_parts). The moves are exact either way, but a cut found in parts may differ
  /// from the serial one in floating-point rounding, so results depend on this number, never
  /// on `threads`. At most 255, and at least 4096 variables per part (fewer parts on smaller
  /// problems); only our max-flow (MaxFlowKind::dynamic) solves in parts. 0 (the default):
  /// with our max-flow, the most parts up to kDefaultFlowParts for which at most
  /// kMaxShareBetweenParts of the energy's edges join different parts, else one (the choice
  /// depends on the energy only), and one part with any other backend. 1: one part.
  int flow_parts = 0;

  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
  bool operator==(const ExpansionOptions&) const = default;
};

/// The most parts ExpansionOptions::flow_parts = 0 stands for with our max-flow. On 2 threads 4
/// parts measured 1.26-1.33x faster to converge than one part on one thread on Recycle (2014
/// Q) and KITTI, with the stereo defaults; on one thread they cost 2-10% (docs/performance.md,
/// "The solve").
inline constexpr int kDefaultFlowParts = 4;

/// The largest share of an energy's edges that may join different parts for the default
/// (ExpansionOptions::flow_parts = 0) to solve in parts. On a 300x400 Potts grid with a share
/// of its edges rewired at random, 4 parts on 2 threads were 1.14-1.44x faster than one part on
/// one thread up to 4.2% of the edges between parts, 1.01x at 5.7% and 0.83x at 8.0%
/// (docs/performance.md, "The solve").
inline constexpr double kMaxShareBetweenParts = 0.05;

/// The share of `energy`'s edges whose ends lie in different parts when its n variables are
/// cut into `parts` bands of indices (variable i in part i * parts / n, as the move solvers
/// cut them); 0 without edges. O(E).
[[nodiscard]] double share_of_edges_between_parts(const PairwiseEnergy& energy, std::size_t parts);

/// Whether `energy`'s edges are local in its variables' order: at most kMaxShareBetweenParts of
/// them join different parts when its variables are cut into kDefaultFlowParts bands of indices
/// (share_of_edges_between_parts), as on a pixel grid of at least about 30 rows or a lattice in
/// row order; not on a random graph. O(E).
[[nodiscard]] bool edges_local(const PairwiseEnergy& energy);

/// Whether alpha-expansion with `options` makes near moves on `energy`: near_radius > 0,
/// `energy` has at least near_moves_min_variables variables, and its edges are local unless
/// near_moves_only_if_local is false.
[[nodiscard]] bool makes_near_moves(const ExpansionOptions& options, const PairwiseEnergy& energy);

/// Whether every expansion move on `energy` is submodular, so that none needs QPBO: every edge
/// weight is >= 0 and every pairwise term has cost(a, a) + cost(b, c) <= cost(b, a) + cost(a, c)
/// for all labels a, b, c (metrics such as Potts and truncated linear do; truncated quadratic
/// and TSGO's step term do not). O(T L^3) for T terms of L labels.
[[nodiscard]] bool expansion_moves_submodular(const PairwiseEnergy& energy);

/// Whether alpha-expansion with `options` makes shift moves on `energy`: shift_moves, or
/// shift_moves_unless_submodular on an energy where some expansion move is not submodular.
[[nodiscard]] bool makes_shift_moves(const ExpansionOptions& options, const PairwiseEnergy& energy);

/// Where alpha-expansion with `options` starts its near moves on `energy` (the one place this
/// is decided; the solver, the run layer's report and the tools' summaries ask it):
/// options.near_seeds, except that NearSeeds::label_and_adjacent is NearSeeds::label on an
/// energy of fewer than kMinLabelsForAdjacentSeeds labels or where it makes shift moves
/// (makes_shift_moves), which move a region one label off already. O(T L^3) for T terms of L
/// labels when shift moves depend on submodularity (makes_shift_moves), else O(1).
[[nodiscard]] NearSeeds near_seeds_in_use(const ExpansionOptions& options,
                                          const PairwiseEnergy& energy);

/// The bytes alpha-expansion with `options` may give recycled move graphs: graph_memory_limit,
/// or 0 with near moves. Near moves run on graphs of their own, and the moves over every
/// variable that would recycle come only in the rare whole sweeps (and the two shift moves of
/// a sweep), so a label's copied graph is reused once or twice and the copies cost more than
/// they save: on Teddy (flat, near radius 5, shift moves) 15.8-16.1 s with no recycled graphs,
/// 17.0-17.2 s with 0.3 GiB of them, 18.4 s with all; with whole moves only, recycling all
/// graphs was the faster (15.2 s against 18.0-19.8 s). A solver bound to an energy on which it
/// makes no near moves (near_moves_only_if_local) recycles within graph_memory_limit, and so
/// does one with recycle_with_near_moves.
[[nodiscard]] std::size_t recycled_graph_limit(const ExpansionOptions& options) noexcept;

/// How a max-flow backend stores its graphs, for the memory estimates below: in flat arrays
/// (ours, Kolmogorov's) or in adjacency lists, counted at twice the bytes (Boost Graph's).
enum class GraphStorage { arrays, adjacency_lists };

/// The bytes one binary-move solver works in on a problem of `size`: per variable and per edge,
/// for the plain and the doubled QPBO graph with their capacities and problems, the move's d and
/// p and its outputs (300 and 240 bytes with arrays: a flat Teddy run without recycling peaks at
/// 344 MiB, which this puts at 380; adjacency lists are counted at twice that, 453 MiB against
/// 505). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> move_solver_bytes(const ProblemSize& size,
                                                           GraphStorage storage);

/// What alpha-expansion with `options` works in on a problem of `size` besides its optional
/// memory (graph_memory_limit): one binary-move solver, two with near or shift moves, and the
/// edge incidences its moves' energies are tallied with (EnergyTally).
/// std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> working_memory_bytes(const ExpansionOptions& options,
                                                              const ProblemSize& size,
                                                              GraphStorage storage);
/// The same for alpha-beta swap: one binary-move solver.
[[nodiscard]] std::optional<std::size_t> working_memory_bytes(const SwapOptions& options,
                                                              const ProblemSize& size,
                                                              GraphStorage storage);

/// The bytes alpha-expansion's kept move problems take on a problem of `size`: num_labels x
/// (N + E) doubles. std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> kept_problem_bytes(const ExpansionOptions& options,
                                                            const ProblemSize& size);

/// The recycled move graphs alpha-expansion would keep on a problem of `size` if it had no
/// limit: one per label, each a binary-move solver's size; none with near moves
/// (recycled_graph_limit). std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> wanted_graph_bytes(const ExpansionOptions& options,
                                                            const ProblemSize& size,
                                                            GraphStorage storage);
/// The same for alpha-beta swap: a recycled move graph per pair of labels.
[[nodiscard]] std::optional<std::size_t> wanted_graph_bytes(const SwapOptions& options,
                                                            const ProblemSize& size,
                                                            GraphStorage storage);

/// What the last step of a graph-cut solver did.
struct MoveStep : StepOutcome {
  Label alpha = 0;  ///< expansion: the label moved to; swap: the pair's first label
  Label beta = 0;   ///< swap: the pair's second label; expansion: equal to alpha
  /// Variables of the move's binary problem: every variable of the level for a whole, shift or
  /// swap move (by regions or not), the free ones for a near move (0 when it freed none).
  std::size_t variables = 0;
  std::size_t unlabeled = 0;  ///< variables QPBO left open (they kept their label)
  bool used_qpbo = false;     ///< the move was not submodular and went to QPBO
  bool recycled = false;      ///< solved on the move's own graph, resumed from its last flow
  bool near = false;  ///< expansion: a near move (ExpansionOptions::near_radius), on its own graph
  /// expansion: +1 or -1 for a shift move (ExpansionOptions::shift_moves; alpha and beta are then
  /// 0), 0 for an expansion move
  int shift = 0;
  double flow_seconds = 0.0;  ///< time inside the max-flow backend
};

}  // namespace c2f

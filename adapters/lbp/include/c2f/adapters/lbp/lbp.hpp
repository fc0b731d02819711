#pragma once
// Loopy min-sum belief propagation as an AnytimeSolver for PairwiseEnergy on any graph.
//
// One step() = one full iteration: every directed message is updated once. Messages are
// normalised (minimum 0) and optionally damped. After every iteration the labeling is decoded
// from the beliefs (argmin, ties to the lowest label) and the solver reports the best labeling
// seen since bind(), so the reported energy never increases. On trees BP is exact: after as
// many iterations as the tree's diameter the decoded labeling is a minimiser (when unique).
// Message updates take O(L) for Potts, TSGO step and truncated-linear terms with weight >= 0,
// O(L^2) otherwise.

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

enum class BpSchedule {
  sequential,  ///< variables in index order; each sends with the newest incoming messages
  parallel,    ///< every message of an iteration computed from the previous iteration's
  /// Bands of consecutive variables (LbpOptions::band_variables), each band as `sequential`
  /// within itself, a message from another band taken from the previous iteration: the bands
  /// are sent at once on LbpOptions::threads threads.
  bands,
};

std::string_view to_string(BpSchedule schedule);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
BpSchedule bp_schedule_from_string(std::string_view text);

struct LbpOptions {
  /// `bands` by default: on the grids and the stereo energy measured it came as low as
  /// `sequential` in as many iterations or lower, and its bands run on every core
  /// (docs/performance.md, "The solve").
  BpSchedule schedule = BpSchedule::bands;
  double damping = 0.0;  ///< new = (1 - damping) * computed + damping * old, in [0, 1)
  /// Threads of an iteration's passes (0: the machine's cores): the messages of the `parallel`
  /// and `bands` schedules, decoding and the energy on every schedule (`sequential` sends its
  /// messages on one). Results are the same bits for every count.
  int threads = 0;
  /// Variables per band of the `bands` schedule (the last band shorter); 0: the default,
  /// the larger of kMinBandVariables and a sixteenth of the variables. Depends on the problem
  /// only, never on `threads`.
  std::size_t band_variables = 0;

  static constexpr std::size_t kMinBandVariables = 4096;
  static constexpr std::size_t kDefaultBands = 16;

  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
  bool operator==(const LbpOptions&) const = default;
};

/// What LbpSolver with `options` works in on a problem of `size`: two message arrays of two
/// per edge and label, beliefs and scratch. std::nullopt when the count overflows.
[[nodiscard]] std::optional<std::size_t> working_memory_bytes(const LbpOptions& options,
                                                              const ProblemSize& size);

/// What the last BP iteration did.
struct LbpStep : StepOutcome {
  double message_change = 0.0;  ///< largest change of any message entry (0 at a fixed point)
};

class LbpSolver {
 public:
  /// Throws std::invalid_argument when options.validate() reports a problem.
  explicit LbpSolver(LbpOptions options = {});

  /// BP has no sweep of moves: its best labeling can stall for a few iterations and then
  /// improve again. Four iterations without a decrease (the paper's plateau) is the window
  /// the driver takes as convergence.
  [[nodiscard]] std::size_t quiet_steps_to_converge(
      const PairwiseEnergy& /*energy*/) const noexcept {
    return 4;
  }

  /// Messages start at 0; the best labeling starts as `start` (validated).
  void bind(const PairwiseEnergy& energy, std::span<const Label> start);
  /// One iteration; returns the energy of the best labeling seen so far.
  double step();

  [[nodiscard]] double energy() const noexcept { return best_energy_; }
  /// The best labeling seen since bind().
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return best_; }
  /// The labeling decoded from the beliefs after the last step.
  [[nodiscard]] std::span<const Label> decoded() const noexcept { return decoded_; }
  /// What the last step() did: how many variables of the best labeling changed (when it
  /// improved) and the largest message change.
  [[nodiscard]] const LbpStep& last_step() const noexcept { return last_; }
  /// The variables per band of the `bands` schedule on the bound energy (all of them for
  /// `sequential`, 1 for `parallel`); 0 before bind().
  [[nodiscard]] std::size_t band_variables() const noexcept { return band_; }
  /// The schedule of the messages.
  [[nodiscard]] BpSchedule schedule() const noexcept { return options_.schedule; }
  /// The threads an iteration sends its messages on: 1 under `sequential` (and before
  /// bind()), else one per band (`parallel`: per 1024 variables) up to LbpOptions::threads.
  [[nodiscard]] unsigned message_threads() const;

 private:
  /// A task's buffers of one value per label.
  struct Scratch {
    std::vector<double> belief, h, out;
    explicit Scratch(std::size_t labels) : belief(labels), h(labels), out(labels) {}
  };

  void compute_belief(std::size_t v, std::span<const double> messages,
                      std::span<double> belief) const;
  void compute_message(const Edge& edge, bool from_first, std::span<const double> h,
                       std::span<double> out) const;
  /// Sends every message out of variables [first, last) in index order, reading messages_.
  /// A message to a variable inside [first, last) is written to messages_ when `in_place`,
  /// every other to next_messages_. Returns the largest change of a message entry.
  double send_from(std::size_t first, std::size_t last, bool in_place, Scratch& scratch);
  /// decoded_ from the beliefs, by chunks on options_.threads threads.
  void decode();
  /// The variables each task of an iteration's messages sends from.
  [[nodiscard]] std::size_t task_variables() const noexcept;
  [[nodiscard]] std::size_t message_index(std::uint32_t edge, bool into_second) const noexcept {
    return (2 * static_cast<std::size_t>(edge) + (into_second ? 0 : 1)) * num_labels_;
  }

  LbpOptions options_;
  const PairwiseEnergy* energy_ = nullptr;
  std::size_t num_labels_ = 0;
  EdgeIncidence incidence_;
  std::vector<double> messages_, next_messages_;
  std::size_t band_ = 0;  ///< variables per band (bands of the schedule, see band_variables())
  /// Under `bands`: the edges whose ends lie in different bands, whose messages next_messages_
  /// holds until the iteration ends.
  std::vector<std::uint32_t> edges_between_bands_;
  Labeling decoded_, best_;
  double best_energy_ = 0.0;
  LbpStep last_;
};

static_assert(AnytimeSolver<LbpSolver, PairwiseEnergy>);

}  // namespace c2f

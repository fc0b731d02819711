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
};

std::string_view to_string(BpSchedule schedule);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
BpSchedule bp_schedule_from_string(std::string_view text);

struct LbpOptions {
  BpSchedule schedule = BpSchedule::sequential;
  double damping = 0.0;  ///< new = (1 - damping) * computed + damping * old, in [0, 1)

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

 private:
  void compute_belief(std::size_t v, std::span<const double> messages,
                      std::span<double> belief) const;
  void compute_message(const Edge& edge, bool from_first, std::span<const double> h,
                       std::span<double> out);
  [[nodiscard]] std::size_t message_index(std::uint32_t edge, bool into_second) const noexcept {
    return (2 * static_cast<std::size_t>(edge) + (into_second ? 0 : 1)) * num_labels_;
  }

  LbpOptions options_;
  const PairwiseEnergy* energy_ = nullptr;
  std::size_t num_labels_ = 0;
  EdgeIncidence incidence_;
  std::vector<double> messages_, next_messages_;
  std::vector<double> belief_, h_, scratch_;
  Labeling decoded_, best_;
  double best_energy_ = 0.0;
  LbpStep last_;
};

static_assert(AnytimeSolver<LbpSolver, PairwiseEnergy>);

}  // namespace c2f

#pragma once
// Refinement and stopping rules of a coarse-to-fine run: small composable objects that look at
// the run's progress after every step and say continue, refine (go to the next finer level;
// on the original problem: finish) or stop.

#include <functional>
#include <optional>
#include <string_view>
#include <vector>

#include "c2f/driver/observer.hpp"

namespace c2f {

enum class Decision { continue_level, refine, stop };

/// Why a run ended.
enum class TerminationReason {
  converged,      ///< the last level's refinement rule fired (e.g. no decrease over k steps)
  step_limit,     ///< a step limit was reached
  time_limit,     ///< the run clock passed the time limit
  target_energy,  ///< the energy reached the target
  observer,       ///< the observer asked to stop
};

std::string_view to_string(TerminationReason reason);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
TerminationReason termination_reason_from_string(std::string_view text);

/// A rule's answer; `reason` says why the run ends if this verdict ends it (a refine on the
/// original problem, or a stop).
struct Verdict {
  Decision decision = Decision::continue_level;
  TerminationReason reason = TerminationReason::converged;
};

/// A rule reads the same per-step record the observer sees (StepEvent, c2f/driver/observer.hpp).
using Rule = std::function<Verdict(const StepEvent&)>;

/// Refine when the energy has not decreased by more than tolerance * max(1, |E|) over the
/// last k steps of the level; k = steps_per_level[level] (the last entry serves deeper levels),
/// or steps_at_original on the original problem when that is > 0. On the original problem
/// tolerance_at_original replaces tolerance (0: only a strict plateau ends the run), so a
/// coarse level can be left while its energy still creeps down without changing when the
/// run is considered converged. Every k must be >= 1 and both tolerances finite and >= 0
/// (std::invalid_argument otherwise).
Rule no_decrease(std::vector<int> steps_per_level, double tolerance = 0.0,
                 int steps_at_original = 0, double tolerance_at_original = 0.0);
/// Refine a coarse level once its progress per second has fallen below what the next level is
/// expected to give. Progress per second is the energy decrease over a window of k steps
/// (k = window_per_level[level], the last entry serving deeper levels) over the run-clock
/// seconds they took. The next level is expected to start as this one did, with steps that cost
/// in proportion to its variables: this level's rate over its first window times its variables
/// over the original problem's. (The original problem is the finest the next level can be, so
/// before an intermediate level the expectation is low and the rule leaves late rather than
/// early.) Compared from the end of the second window on (step >= 2k); never on the original
/// problem, nor on a level whose first window did not decrease the energy. Every k must be >= 1
/// (std::invalid_argument otherwise).
Rule progress_rate(std::vector<int> window_per_level);
/// Refine after `max_steps` steps on a level.
Rule level_step_limit(long max_steps);
/// Stop after `max_steps` steps in the whole run.
Rule total_step_limit(long max_steps);
/// Stop once the run clock passes `seconds`.
Rule time_limit(double seconds);
/// Stop once the energy is <= target.
Rule target_energy(double target);

/// A set of rules consulted together: the strongest decision wins (stop over refine over
/// continue); among equally strong verdicts the first rule added wins.
class Rules {
 public:
  Rules() = default;
  Rules& add(Rule rule);
  [[nodiscard]] Verdict decide(const StepEvent& event) const;
  [[nodiscard]] bool empty() const noexcept { return rules_.empty(); }

 private:
  std::vector<Rule> rules_;
};

}  // namespace c2f

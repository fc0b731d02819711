#pragma once
// Refinement and stopping rules of a coarse-to-fine run: small composable objects that look at
// the run's progress after every step and say continue, refine (go to the next finer level;
// on the original problem: finish) or stop.

#include <functional>
#include <optional>
#include <span>
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
/// What the next level is expected to gain over its first sweep, from the labeling of the
/// original variables a coarse level would hand down (e.g. local_gain of the original energy,
/// c2f/core/local_gain.hpp). Called on the run clock.
using NextLevelGain = std::function<double(std::span<const Label> ground)>;

/// Refine a coarse level once its progress has fallen to what the next level is expected to
/// give. Progress is measured per unit of work, the variables the steps' moves worked over
/// (StepEvent::step_variables), not per second: a move's time grows with the variables it
/// moves, and work, unlike the clock, is the same on every machine and thread count, so a run
/// takes the same steps each time. The level's first sweep (k = sweep_per_level[level] steps,
/// the last entry serving deeper levels) always runs. At its end the next level's rate is
/// estimated, once: `next_gain` of the labeling the level would hand down then (unset: the
/// first sweep's own decrease, as if the next level started as this one did) over the work of
/// the next level's first sweep, taken as this first sweep's work times the original variables
/// over the level's (a sweep of whole moves on the original problem; near moves do less, so
/// the estimate is low and the rule leaves no sooner than it should). From step k on, the
/// level's decrease over its last min(4, k) steps per unit of their work is compared with that
/// rate, and the level is refined once it is not above it. Never on the original problem.
/// Every k must be >= 1 (std::invalid_argument otherwise).
Rule progress_rate(std::vector<int> sweep_per_level, NextLevelGain next_gain = {});
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

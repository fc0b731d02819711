#pragma once
// Options of a coarse-to-fine run, in the Ceres shape: plain fields plus a validity check.

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/driver/rules.hpp"

namespace c2f {

/// The labeling the first (coarsest) level starts from.
enum class InitialLabeling {
  unary_argmin,  ///< every variable takes its cheapest unary label
  zero,          ///< every variable takes label 0 (what the reference implementation does)
};

std::string_view to_string(InitialLabeling init);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
InitialLabeling initial_labeling_from_string(std::string_view text);

/// How a labeling is handed to the next level.
enum class LevelTransfer {
  exact,     ///< transfer_labels: same energy; every level must refine the previous one
  majority,  ///< transfer_labels_by_majority: for schedules that do not refine (energy may change)
};

struct Options {
  /// Refine (on the original problem: finish) when the energy has not decreased over the last
  /// k steps; k = plateau_steps[level], the last entry serving deeper levels. Empty: no such rule.
  std::vector<int> plateau_steps{4};
  /// On the original problem (the last level) use this k instead. 0: the original problem's
  /// solver says (quiet_steps_to_converge of a ConvergingSolver: one sweep of its moves), so a
  /// run with default options converges; for a solver that does not say, plateau_steps
  /// applies. (With plateau_steps empty and this 0, no level has a plateau rule.)
  int plateau_steps_at_original = 0;
  /// On coarse levels a decrease over those k steps counts only when larger than
  /// plateau_tolerance * max(1, |E|): with a tolerance > 0 a level whose energy merely creeps
  /// down is refined.
  double plateau_tolerance = 0.0;
  /// The same on the original problem (0: the run converges only on a strict plateau).
  double plateau_tolerance_at_original = 0.0;
  /// When > 0, a coarse level is also refined, after its first sweep of this many steps, once
  /// its progress per variable moved has fallen to what the next level is expected to give
  /// (progress_rate in c2f/driver/rules.hpp). 0: no such rule.
  int progress_sweep_steps = 0;
  /// With progress_sweep_steps > 0: what the next level is expected to gain over its first
  /// sweep (progress_rate's next_gain; unset: the level's own first sweep's decrease).
  NextLevelGain next_level_gain;
  /// Refine after this many steps on one level (0: no limit).
  long max_steps_per_level = 0;
  /// Stop after this many steps in the whole run (0: no limit).
  long max_total_steps = 0;
  /// Stop once the run clock passes this many seconds (0: no limit).
  double time_limit_seconds = 0.0;
  /// Stop once the energy is at or below this value.
  std::optional<double> target_energy;
  InitialLabeling initial_labeling = InitialLabeling::unary_argmin;
  /// When not empty, the labeling the run starts from instead (one label in [0, L) per original
  /// variable; coarse_to_fine throws std::invalid_argument otherwise). On a coarse first level
  /// each group starts at the label most of its members have here (ties: the lower label), so
  /// the run's first energy can differ from this labeling's.
  Labeling start_labeling;
  /// exact unless the partition provider was explicitly allowed to produce levels that do not
  /// refine each other.
  LevelTransfer level_transfer = LevelTransfer::exact;
  /// When set, asked with each coarse level's number of groups, after its partition is built
  /// and before its energy is reduced, whether the level fits (e.g. the run's memory budget:
  /// coarse_level_admission in c2f/run/memory_plan.hpp). A level it declines is skipped:
  /// nothing is reduced or solved there (LevelSummary::skipped) and the next level starts from
  /// the last level solved. Unset: every level is solved.
  std::function<bool(std::size_t groups)> coarse_level_fits;
  /// Rules of your own (c2f/driver/rules.hpp), consulted after the ones the fields above
  /// describe; the strongest verdict wins. They do not replace the rule that ends every level.
  std::vector<Rule> extra_rules;

  /// Empty when the options are usable, else a message naming the offending field. Options
  /// must contain a rule that ends every level (plateau_steps or max_steps_per_level).
  [[nodiscard]] std::string validate() const;
  /// The rules these options describe. Throws std::invalid_argument when validate() fails.
  [[nodiscard]] Rules rules() const;
};

}  // namespace c2f

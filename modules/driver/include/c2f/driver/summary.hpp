#pragma once
// What a coarse-to-fine run reports when it ends.

#include <cstddef>
#include <string>
#include <vector>

#include "c2f/core/labeling.hpp"
#include "c2f/driver/rules.hpp"

namespace c2f {

struct LevelSummary {
  int level = 0;
  std::size_t num_variables = 0;  ///< variables (groups) on this level
  long steps = 0;
  double start_energy = 0.0;  ///< after the transfer from the previous level
  double final_energy = 0.0;
  double partition_seconds = 0.0;  ///< building this level's partition
  double setup_seconds = 0.0;      ///< reduction, label transfer and solver binding
  double solve_seconds = 0.0;      ///< solver steps and rule checks
  /// Options::coarse_level_fits declined the level: num_variables is its number of groups, and
  /// nothing was reduced or solved.
  bool skipped = false;
};

struct Summary {
  Labeling labeling;    ///< final labeling of the original variables
  double energy = 0.0;  ///< evaluate(labeling) on the original energy
  TerminationReason reason = TerminationReason::converged;
  double seconds = 0.0;           ///< run clock at the end (observer time excluded)
  double observer_seconds = 0.0;  ///< time spent inside the observer, not on the run clock
  long total_steps = 0;
  std::vector<LevelSummary> levels;

  /// A few human-readable lines: one per level and the outcome.
  [[nodiscard]] std::string report() const;
};

}  // namespace c2f

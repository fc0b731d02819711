#pragma once
// What c2f runs when the caller names nothing: one definition for the tools (their flags'
// defaults), the C++ API and Python. Each is the configuration measured best on a tuning set and
// confirmed on instances set aside before tuning (docs/results.md, "Defaults"). Every value can
// be overridden; `flat` with the same moves is the fair baseline of each.

#include <cstddef>
#include <optional>
#include <string>

#include "c2f/core/pairwise_energy.hpp"
#include "c2f/run/run_config.hpp"

namespace c2f {

struct RunDefaults {
  std::string grid_schedule;     ///< schedule text on a pixel grid (application presets apply)
  std::string general_schedule;  ///< schedule text on any other graph
  /// Schedule text on a graph that is no pixel grid but whose edges are local in its
  /// variables' order (edges_local: a lattice, a grid given without its shape); empty:
  /// general_schedule there too.
  std::string local_schedule;
  int near_radius = 0;  ///< expansion's near moves, original problem only (0: none)
  /// Where those near moves start (ExpansionOptions::near_seeds) on any graph but a pixel grid.
  NearSeeds near_seeds = NearSeeds::label_and_cheapest;
  /// Where they start on a pixel grid (empty: near_seeds).
  std::optional<NearSeeds> grid_near_seeds;
  /// Those near moves only on an energy whose edges are local (makes_near_moves); on any other
  /// every move is a whole move.
  bool near_moves_only_if_local = false;
  /// Those near moves only on an energy of at least this many variables (0: any size); on a
  /// smaller one every move is a whole move.
  std::size_t near_moves_min_variables = 0;
  bool shift_moves = false;  ///< expansion's shift moves, original problem only
  /// Shift moves also on an energy where some expansion move is not submodular
  /// (ExpansionOptions::shift_moves_unless_submodular), original problem only.
  bool shift_moves_unless_submodular = false;
  int plateau_steps = 4;  ///< steps without decrease that end a coarse level
  /// The plateau rule's tolerance on coarse levels (a decrease over plateau_steps counts only
  /// when larger than this fraction of the energy), on a pixel grid too unless
  /// grid_plateau_tolerance is set.
  double plateau_tolerance = 0.0;
  /// That tolerance on a pixel grid (empty: plateau_tolerance).
  std::optional<double> grid_plateau_tolerance;
  bool progress_rate = false;  ///< RunConfig::progress_rate

  /// The schedule text for `energy`: grid_schedule on a pixel grid (on_grid), else
  /// local_schedule (when set) where its edges are local (edges_local), else
  /// general_schedule. O(E) off a grid. A copy, so that it outlives a temporary RunDefaults
  /// (pairwise_defaults().schedule_for(...)).
  [[nodiscard]] std::string schedule_for(const PairwiseEnergy& energy, bool on_grid) const;
  /// grid_near_seeds (when set) on a pixel grid, else near_seeds.
  [[nodiscard]] NearSeeds near_seeds_on(bool on_grid) const {
    return on_grid && grid_near_seeds ? *grid_near_seeds : near_seeds;
  }
  /// grid_plateau_tolerance (when set) on a pixel grid, else plateau_tolerance.
  [[nodiscard]] double plateau_tolerance_on(bool on_grid) const {
    return on_grid && grid_plateau_tolerance ? *grid_plateau_tolerance : plateau_tolerance;
  }
  /// A RunConfig with these moves and rules for an energy on a pixel grid or not: expansion on
  /// our max-flow with near and shift moves on the original problem only, no time or step
  /// limit, no budget set (the run's default).
  [[nodiscard]] RunConfig config(bool on_grid) const;
};

/// A pairwise energy's defaults (c2f-solve, c2f.solve): aggregated best labels split into
/// connected regions (on a grid agg:2,8,0.15/cc: unaries summed over 5x5 windows, or wider ones
/// up to 17x17 while the level keeps more than 15% of the variables as groups; on another graph
/// whose edges are local agg:2,3,0.15/cc, over two rounds of graph neighbours or three while
/// two keep more than 15%; on any other graph agg:2/cc, where wider rounds mix what differs);
/// expansion moves, with shift moves on energies where some expansion move is not submodular
/// (e.g. truncated quadratic); on the original problem near moves of radius 3 from their label
/// (on a pixel grid of 16 labels or more without shift moves also from the labels next to it:
/// NearSeeds::label_and_adjacent) where its edges are local (a grid, a lattice) and it has at
/// least 200000 variables, whole moves elsewhere; a coarse level ends after 4 moves that
/// together lower the energy by no more than 1e-4 of it (on a pixel grid: by nothing), or
/// sooner, after its first sweep, once it gains per variable moved no more than the original
/// problem is expected to (progress_rate).
[[nodiscard]] RunDefaults pairwise_defaults();

}  // namespace c2f

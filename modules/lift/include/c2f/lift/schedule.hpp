#pragma once
// Schedules: the coarse levels of a coarse-to-fine run written as text.
//
// Grammar (levels separated by spaces, coarsest first; `flat`, the original problem, may end
// the list and is implied):
//   cp:N_L,N_iter        colour passing CP(N_L, N_iter)
//   local:N_L,N_iter     the reference implementation's local grouping (local_grouping.hpp)
//   threshold:TAU[,R]    threshold partition with L1 distance TAU, window radius R (default 1)
//   slic:S               SLIC superpixels of region size S, nested into the previous level
//   agg:R                pixels of equal best label after summing unaries over a (2R+1) x
//                        (2R+1) window, or without a grid R times over graph neighbours
//                        (aggregated_best_labels.hpp)
//   agg:R,MAX,SHARE      agg with the smallest radius from R to MAX (> R) whose level (after
//                        /cc when given) keeps at most SHARE of the variables as groups; MAX
//                        when none does
//   blocks:S             S x S pixel blocks
//   auto:F1,F2,...       colour-passing levels whose group counts are closest to the fractions
//                        F1 < F2 < ... of the number of pixels (alone, optionally + flat)
//   flat                 no coarse level (alone: the flat run)
//   NAME                 a preset the application offers (alone), e.g. stereo's `paper`
// Any level may end in /cc: its groups are split into 4-connected components, or without a
// grid into components along the energy's edges (connected_components.hpp), e.g. cp:1,1/cc.
// Without a grid only cp, agg and auto levels can be built.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/core/grid.hpp"
#include "c2f/lift/level_spec.hpp"

namespace c2f {

/// A named schedule an application offers: `name` stands alone in a schedule text and reads
/// as `levels` (itself in the grammar above, without presets).
struct SchedulePreset {
  std::string name;
  std::string levels;
};

/// The presets of any pairwise energy (no image needed): "paper", the paper's colour-passing
/// levels cp:1,1 cp:2,1 cp:3,1. c2f-solve and c2f.solve offer them; applications add their own.
[[nodiscard]] std::span<const SchedulePreset> pairwise_schedule_presets();

struct Schedule {
  std::vector<LevelSpec> levels;       ///< coarse levels, coarsest first
  std::vector<double> auto_fractions;  ///< non-empty for auto:...; levels is then empty

  /// Parses the grammar above with the application's presets. Throws std::invalid_argument
  /// naming the offending token (for an unknown word, the presets there are).
  static Schedule parse(std::string_view text, std::span<const SchedulePreset> presets = {});
  /// Canonical text ("flat" for no levels); presets are printed as their levels.
  [[nodiscard]] std::string to_string() const;
  /// Whether a run has coarse levels (reduced energies beside the original), i.e. is not flat.
  [[nodiscard]] bool has_coarse_levels() const noexcept {
    return !levels.empty() || !auto_fractions.empty();
  }
  /// Empty when every level can be built for an energy with num_labels labels, else a message
  /// naming the first level that cannot (N_L above the label count).
  [[nodiscard]] std::string validate(int num_labels) const;
  /// Empty when every level can be built on an image of this size, else a message naming the
  /// first level that cannot (a SLIC region larger than the image's shorter side).
  [[nodiscard]] std::string validate_image(GridShape image) const;
  /// Empty when every level can be built for an energy that is no pixel grid (colour passing,
  /// aggregated best labels, auto levels; /cc along the energy's edges), else "level L needs a
  /// pixel grid" for the first that cannot (local, threshold, slic, blocks).
  [[nodiscard]] std::string validate_without_grid() const;
};

}  // namespace c2f

#pragma once
// One coarse level of a schedule: which partition to build, in the schedule syntax.

#include <string>
#include <variant>

namespace c2f {

/// cp:N_L,N_iter: colour passing CP(N_L, N_iter) (colour_passing.hpp).
struct ColourPassingLevel {
  int labels = 1;
  int iterations = 1;
  friend bool operator==(const ColourPassingLevel&, const ColourPassingLevel&) = default;
};

/// local:N_L,N_iter: the reference implementation's local grouping (local_grouping.hpp).
struct LocalGroupingLevel {
  int labels = 1;
  int iterations = 1;
  friend bool operator==(const LocalGroupingLevel&, const LocalGroupingLevel&) = default;
};

/// threshold:TAU[,R]: threshold partition with L1 distance TAU and window radius R.
struct ThresholdLevel {
  double tau = 0.0;
  int radius = 1;
  friend bool operator==(const ThresholdLevel&, const ThresholdLevel&) = default;
};

/// slic:S: SLIC superpixels of region size S, intersected with the previous level.
struct SlicLevel {
  int region_size = 2;
  friend bool operator==(const SlicLevel&, const SlicLevel&) = default;
};

/// agg:R: pixels of equal best label after summing unaries over a (2R+1) x (2R+1) window
/// (aggregated_best_labels.hpp).
/// agg:R,MAX,SHARE (MAX > R, SHARE in (0, 1]): the radius that builds itself, the smallest
/// from R to MAX whose level (after /cc when given) keeps at most SHARE of the variables as
/// groups; MAX when none does. Wider windows give fewer groups where noisy unaries leave many
/// (e.g. 128 labels).
struct AggregatedLevel {
  int radius = 1;
  int max_radius = 0;      ///< above radius: the radius builds itself (else the radius is fixed)
  double max_share = 1.0;  ///< the groups over the variables a level may keep (when it builds)
  friend bool operator==(const AggregatedLevel&, const AggregatedLevel&) = default;
};

/// blocks:S: S x S pixel blocks.
struct BlockLevel {
  int size = 1;
  friend bool operator==(const BlockLevel&, const BlockLevel&) = default;
};

using LevelPartition = std::variant<ColourPassingLevel, LocalGroupingLevel, ThresholdLevel,
                                    SlicLevel, AggregatedLevel, BlockLevel>;

struct LevelSpec {
  LevelPartition partition;
  bool connected = false;  ///< /cc: split every group into its 4-connected components

  /// N_L for cp and local levels (the labels the level needs), 0 for the others.
  [[nodiscard]] int labels_needed() const;
  /// The level in schedule syntax, e.g. "cp:2,1" or "cp:2,1/cc".
  [[nodiscard]] std::string to_string() const;
  friend bool operator==(const LevelSpec&, const LevelSpec&) = default;
};

}  // namespace c2f

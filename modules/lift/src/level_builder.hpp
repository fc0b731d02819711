#pragma once
// Internal to ScheduleProvider: builds the partition of one schedule level, keeping the
// colour-passing state that consecutive cp levels advance.

#include <optional>

#include "c2f/core/grid.hpp"
#include "c2f/lift/colour_passing.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/level_spec.hpp"
#include "c2f/lift/lifting_view.hpp"
#include "c2f/lift/schedule_provider.hpp"

namespace c2f::detail {

class LevelBuilder {
 public:
  /// No shape: the energy is no pixel grid, and only levels that read its factor graph (cp,
  /// agg) can be built.
  LevelBuilder(std::optional<GridShape> shape, SuperpixelSource superpixels);

  /// The partition of `spec` for the energy seen through `view` (a grid energy of this shape,
  /// or any energy without one), /cc applied. `previous` is the last level built (SLIC levels
  /// are intersected with it), or null. Throws std::invalid_argument naming the level when it
  /// cannot be built.
  DensePartition build(const LevelSpec& spec, const LiftingView& view,
                       const DensePartition* previous);
  /// The level the last build() made: its spec, or for agg:R,MAX,SHARE the fixed agg:RADIUS
  /// it chose (with its /cc).
  [[nodiscard]] const LevelSpec& last_built() const noexcept { return last_built_; }
  /// The threads the last build() ran on: resolved_threads(threads) for an agg or slic level,
  /// 1 for the others.
  [[nodiscard]] unsigned last_threads() const noexcept;
  /// Builds agg levels (on a grid and off one) and slic levels on up to `threads` threads (0:
  /// the machine's cores); the partitions are the same for every count.
  void set_threads(int threads) noexcept { threads_ = threads; }

 private:
  /// build() of a level with one partition (not a radius that builds itself).
  DensePartition build_one(const LevelSpec& spec, const LiftingView& view,
                           const DensePartition* previous);
  /// build() of agg:R,MAX,SHARE: each radius from R on, until its level keeps at most SHARE of
  /// the variables as groups or the radius is MAX.
  DensePartition aggregated_within_share(const LevelSpec& spec, const AggregatedLevel& level,
                                         const LiftingView& view);
  /// `partition` split into connected components when spec asks for /cc.
  DensePartition connected_if(const LevelSpec& spec, DensePartition partition,
                              const LiftingView& view) const;
  /// build_one() before /cc.
  DensePartition build_groups(const LevelSpec& spec, const LiftingView& view,
                              const DensePartition* previous);
  DensePartition colour_passing(const ColourPassingLevel& level, const LiftingView& view);
  DensePartition superpixels(const LevelSpec& spec, const DensePartition* previous);

  /// The grid shape for a level that needs one; throws naming the level without one.
  GridShape grid_of(const LevelSpec& spec) const;

  std::optional<GridShape> shape_;
  SuperpixelSource superpixels_;
  std::optional<ColourPassing> colour_passing_;
  LevelSpec last_built_;
  int threads_ = 1;
};

}  // namespace c2f::detail

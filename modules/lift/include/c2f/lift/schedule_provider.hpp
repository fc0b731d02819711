#pragma once
// ScheduleProvider: the PartitionProvider that builds a schedule's levels on demand.

#include <chrono>
#include <concepts>
#include <cstddef>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "c2f/core/grid.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/lifting_view.hpp"
#include "c2f/lift/schedule.hpp"

namespace c2f {

/// What one level of a schedule produced.
struct LevelReport {
  /// The level in schedule syntax; for agg:R,MAX,SHARE the agg:RADIUS it chose, then its text
  /// in brackets, e.g. "agg:5/cc (agg:2,8,0.15/cc)".
  std::string level;
  std::size_t num_groups;  ///< groups of the partition produced
  double seconds;          ///< time to build it
  unsigned threads = 1;    ///< threads it was built on (set_threads: agg and slic levels; 1 else)
};

/// Builds SLIC superpixels for a region size on up to `threads` threads (0: the machine's cores;
/// the same partition for every count), supplied by the vision module, which owns the image;
/// returns one group id per pixel as a partition.
using SuperpixelSource = std::function<DensePartition(int region_size, int threads)>;

namespace detail {
class LevelBuilder;
}

/// A PartitionProvider that builds the schedule's levels on demand (on the caller's clock), for
/// an energy on a width x height pixel grid or on any graph. Without a grid, agg levels sum over
/// graph neighbourhoods and /cc follows the energy's factors; image levels (local, threshold,
/// slic, blocks) need a grid. Colour-passing levels advance one colour-passing
/// state (first raising N_L, then iterating), so consecutive cp levels with non-decreasing N_L
/// and N_iter refine each other; a cp level that goes back starts a fresh state. SLIC levels
/// are intersected with the previous level. Whether consecutive levels refine each other is the
/// driver's check (coarse_to_fine, Options::level_transfer), not the provider's. Variables
/// of different classes (keep_apart) never share a group.
class ScheduleProvider {
 public:
  /// Throws std::invalid_argument for an empty grid, or a slic level without a superpixel
  /// source.
  ScheduleProvider(Schedule schedule, GridShape shape, SuperpixelSource superpixels = {});
  /// For an energy that is no pixel grid. Throws std::invalid_argument naming the first level
  /// that needs a grid (Schedule::validate_without_grid).
  explicit ScheduleProvider(Schedule schedule);
  ~ScheduleProvider();
  ScheduleProvider(ScheduleProvider&&) noexcept;
  ScheduleProvider& operator=(ScheduleProvider&&) noexcept;

  /// From the next level on, every level is intersected with the partition of the variables by
  /// `classes` (one non-negative value per variable), so variables of different classes never
  /// share a group. Levels that refine each other still do, since both are intersected with the
  /// same partition. Segmentation keeps the seeds of different labels apart with it, so a run
  /// stopped on a coarse level keeps every seed. Throws std::invalid_argument for a negative
  /// class or a size other than the grid's; next() checks the size against the energy.
  void keep_apart(std::span<const int> classes);

  /// The next level's partition, or std::nullopt after the last coarse level, for an energy
  /// of any kind seen through its LiftingView (which must describe the same energy on every
  /// call). The first call resolves auto levels from it. Throws std::invalid_argument naming
  /// the level when it cannot be built for this energy (grid size, N_L above the label count).
  std::optional<DensePartition> next(const LiftingView& energy);
  /// The same for any energy with a `lifting_view(energy)` (a PairwiseEnergy here, the
  /// cooperative-cut energy beside its type): the view is built on the first call for an
  /// energy and kept, its cost counted in that level's report.
  template <class E>
  requires requires(const E& e) {
    { lifting_view(e) } -> std::same_as<LiftingView>;
  }
  std::optional<DensePartition> next(const E& energy) {
    const auto start = std::chrono::steady_clock::now();
    if (viewed_ != static_cast<const void*>(&energy)) {
      view_ = lifting_view(energy);
      viewed_ = &energy;
    }
    std::optional<DensePartition> partition = next(*view_);
    if (partition) {
      reports_.back().seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    }
    return partition;
  }

  /// Builds the levels that can be split among threads (agg and slic levels) on up to
  /// `threads` threads (0: the machine's cores; 1 until set); the partitions are the same for
  /// every count. run() sets the solve's threads.
  void set_threads(int threads) noexcept;

  /// One report per level built so far.
  [[nodiscard]] const std::vector<LevelReport>& reports() const noexcept { return reports_; }
  /// The schedule as given.
  [[nodiscard]] const Schedule& schedule() const noexcept { return schedule_; }
  /// The coarse levels this provider builds: the schedule's, or for auto:... the colour-passing
  /// levels chosen by the first next() (empty before it).
  [[nodiscard]] const std::vector<LevelSpec>& levels() const noexcept { return levels_; }

 private:
  Schedule schedule_;
  std::optional<GridShape> shape_;  ///< none: the energy is no pixel grid
  std::unique_ptr<detail::LevelBuilder> builder_;
  const void* viewed_ = nullptr;  ///< the energy view_ shows
  std::optional<LiftingView> view_;
  bool started_ = false;
  std::vector<LevelSpec> levels_;
  std::size_t position_ = 0;
  std::optional<DensePartition> previous_;
  std::optional<DensePartition> apart_;  ///< keep_apart's classes
  std::vector<LevelReport> reports_;
};

}  // namespace c2f

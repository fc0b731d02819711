#pragma once
// Schedules: the levels of a coarse-to-fine run as text, and the provider that builds them.
//
// Grammar (levels separated by spaces, coarsest first; `flat`, the original problem, may end
// the list and is implied):
//   cp:N_L,N_iter        colour passing CP(N_L, N_iter)
//   local:N_L,N_iter     the reference's local grouping (see local_grouping.hpp)
//   threshold:TAU[,R]    threshold partition with L1 distance TAU, window radius R (default 1)
//   slic:S               SLIC superpixels of region size S, nested into the previous level
//   blocks:S             S x S pixel blocks
//   auto:F1,F2,...       colour-passing levels whose group counts are closest to the fractions
//                        F1 < F2 < ... of the number of pixels (alone, optionally + flat)
//   flat                 no coarse level (alone: the flat run)
//   paper                the paper's stereo schedule: cp:1,1 cp:2,1 cp:3,1 flat
//   paper-cc             the same levels split into connected components (see below)
//   regions              local:1,1/cc local:2,1/cc local:3,1/cc flat: connected regions of
//                        equal best-label tuples (docs/results.md)
// Any level may end in /cc: its groups are split into 4-connected components
// (connected_components.hpp), e.g. cp:1,1/cc.

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/core/grid.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/colour_passing.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f {

enum class LevelKind { colour_passing, local_grouping, threshold, slic, blocks };

struct LevelSpec {
  LevelKind kind = LevelKind::colour_passing;
  int labels = 1;          ///< N_L (colour passing, local grouping)
  int iterations = 1;      ///< N_iter (colour passing, local grouping)
  double tau = 0.0;        ///< threshold
  int radius = 1;          ///< threshold window
  int size = 0;            ///< SLIC region size or block size
  bool connected = false;  ///< split groups into 4-connected components (/cc)

  /// The level in schedule syntax, e.g. "cp:2,1" or "cp:2,1/cc".
  [[nodiscard]] std::string to_string() const;
  /// The level without the /cc modifier.
  [[nodiscard]] std::string base_string() const;
  friend bool operator==(const LevelSpec&, const LevelSpec&) = default;
};

struct Schedule {
  std::vector<LevelSpec> levels;       ///< coarse levels, coarsest first
  std::vector<double> auto_fractions;  ///< non-empty for auto:...; levels is then empty

  /// Parses the grammar above. Throws std::invalid_argument naming the offending token.
  static Schedule parse(std::string_view text);
  /// Canonical text ("flat" for no levels).
  [[nodiscard]] std::string to_string() const;
};

/// What one level of a schedule produced.
struct LevelReport {
  std::string level;       ///< the level in schedule syntax
  std::size_t num_groups;  ///< groups of the partition produced
  double seconds;          ///< time to build it
};

/// Builds SLIC superpixels for a region size (supplied by the vision module, which owns the
/// image); returns one group id per pixel as a partition.
using SuperpixelSource = std::function<DensePartition(int region_size)>;

/// A PartitionProvider for PairwiseEnergy on a width x height grid that builds the schedule's
/// levels on demand (on the caller's clock). Colour-passing levels advance one colour-passing
/// state (first raising N_L, then iterating), so consecutive cp levels with non-decreasing N_L
/// and N_iter refine each other; a cp level that goes back starts a fresh state. SLIC levels
/// are intersected with the previous level. Every level is checked to refine the previous one;
/// one that does not is rejected with std::invalid_argument unless allow_non_refining is set.
class ScheduleProvider {
 public:
  ScheduleProvider(Schedule schedule, GridShape shape, SuperpixelSource superpixels = {},
                   bool allow_non_refining = false);

  /// The next level's partition, or std::nullopt after the last coarse level. Throws
  /// std::invalid_argument naming the level when it cannot be built for this energy.
  std::optional<DensePartition> next(const PairwiseEnergy& energy);

  /// One report per level built so far (auto levels show the cp level they resolved to).
  [[nodiscard]] const std::vector<LevelReport>& reports() const noexcept { return reports_; }
  [[nodiscard]] const Schedule& schedule() const noexcept { return schedule_; }

 private:
  DensePartition build(const LevelSpec& spec, const PairwiseEnergy& energy);
  void resolve_auto(const PairwiseEnergy& energy);

  Schedule schedule_;
  GridShape shape_;
  SuperpixelSource superpixels_;
  bool allow_non_refining_;
  std::size_t position_ = 0;
  bool resolved_ = false;
  std::optional<ColourPassing> colour_passing_;
  std::optional<DensePartition> previous_;
  std::vector<LevelReport> reports_;
};

}  // namespace c2f

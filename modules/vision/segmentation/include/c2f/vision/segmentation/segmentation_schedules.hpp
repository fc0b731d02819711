#pragma once
// Schedules for segmentation: the application's presets, and a provider that builds schedule
// levels for the cooperative-cut energy (through its LiftingView) and for the Potts baseline.

#include <optional>
#include <string_view>
#include <vector>

#include "c2f/core/grid.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/vision/segmentation/coop_energy.hpp"

namespace c2f::vision {

/// With k = ceil(L / 2):
///   paper     cp:k,1 cp:k,2 flat   the paper's CP(k, 2) -> CP(k, 3) (our first colour-passing
///                                  iteration already brings in the incident edge classes,
///                                  what the paper counts as its second)
///   paper-cc  the same split into connected components
///   superpixels  slic:16 slic:8 flat: SLIC superpixels of the image, then their intersection
///            with finer ones (the levels our benchmark found fastest, docs/results.md)
std::vector<SchedulePreset> segmentation_schedule_presets(int num_labels);

/// Schedule::parse with the segmentation presets for num_labels labels.
Schedule parse_segmentation_schedule(std::string_view text, int num_labels);

/// ScheduleProvider for segmentation energies: the cooperative-cut energy is seen through
/// lifting_view(CoopEnergy) (built once per energy), a PairwiseEnergy as usual.
class SegmentationLevels {
 public:
  SegmentationLevels(Schedule schedule, GridShape shape, SuperpixelSource superpixels = {})
      : levels_(std::move(schedule), shape, std::move(superpixels)) {}

  std::optional<DensePartition> next(const CoopEnergy& energy) {
    if (viewed_ != &energy) {
      view_ = lifting_view(energy);
      viewed_ = &energy;
    }
    return levels_.next(*view_);
  }
  std::optional<DensePartition> next(const PairwiseEnergy& energy) { return levels_.next(energy); }

  [[nodiscard]] const ScheduleProvider& schedule() const noexcept { return levels_; }

 private:
  ScheduleProvider levels_;
  const CoopEnergy* viewed_ = nullptr;
  std::optional<LiftingView> view_;
};

}  // namespace c2f::vision

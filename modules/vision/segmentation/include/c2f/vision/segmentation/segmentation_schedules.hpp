#pragma once
// Schedules for segmentation: the application's presets. ScheduleProvider builds their levels
// for the cooperative-cut energy (through lifting_view(CoopEnergy)) and the Potts baseline.

#include <string_view>
#include <vector>

#include "c2f/lift/schedule.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace c2f::vision {

/// With k = ceil(L / 2):
///   paper     cp:k,1 cp:k,2 flat   the paper's CP(k, 2) -> CP(k, 3) (our first colour-passing
///                                  iteration already brings in the incident edge classes,
///                                  what the paper counts as its second)
///   paper-cc  the same split into connected components
///   superpixels  slic:16 slic:8 flat: SLIC superpixels of the image, then their intersection
///            with finer ones (the levels our benchmark found fastest,
///            docs/history/results-2026-11.md)
std::vector<SchedulePreset> segmentation_schedule_presets(int num_labels);

/// SLIC iterations of segmentation's superpixel levels. Five, not OpenCV's customary ten: the
/// levels cost half as much and the suite's segmentation family reached flat's energy sooner
/// with them, at no higher error at deadlines (docs/results.md, 2026-11-29).
inline constexpr int kSegmentationSlicIterations = 5;

/// The provider of `schedule`'s levels for `scene`, as c2f-segment, c2f.segment and the
/// segmentation benchmarks build them: slic:S levels are SLICO superpixels of the image with
/// kSegmentationSlicIterations iterations, and every level keeps seeded pixels apart from
/// pixels with another seed or none (ScheduleProvider::keep_apart), so no group holds seeds
/// of two labels and a run stopped on a coarse level keeps every seed.
ScheduleProvider segmentation_levels(Schedule schedule, const SegmentationScene& scene);

/// Schedule::parse with the segmentation presets for num_labels labels.
Schedule parse_segmentation_schedule(std::string_view text, int num_labels);

/// Steps without decrease that end a coarse level of a segmentation run whose solver's sweep
/// (quiet_steps_to_converge) is `sweep` steps: the reference's window of num_labels trials, or
/// the sweep when that is shorter (a majorise-minimise step without decrease is already a fixed
/// point); the whole sweep when `whole_sweep` (c2f-segment's --plateau sweep).
int coarse_plateau_steps(std::size_t sweep, int num_labels, bool whole_sweep);

}  // namespace c2f::vision

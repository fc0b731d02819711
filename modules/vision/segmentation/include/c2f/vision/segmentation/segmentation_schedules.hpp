#pragma once
// Schedules for segmentation: the application's presets. ScheduleProvider builds their levels
// for the cooperative-cut energy (through lifting_view(CoopEnergy)) and the Potts baseline.

#include <string_view>
#include <vector>

#include "c2f/lift/schedule.hpp"

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

/// Schedule::parse with the segmentation presets for num_labels labels.
Schedule parse_segmentation_schedule(std::string_view text, int num_labels);

/// Steps without decrease that end a coarse level of a segmentation run whose solver's sweep
/// (quiet_steps_to_converge) is `sweep` steps: the reference's window of num_labels trials, or
/// the sweep when that is shorter (a majorise-minimise step without decrease is already a fixed
/// point); the whole sweep when `whole_sweep` (c2f-segment's --plateau sweep).
int coarse_plateau_steps(std::size_t sweep, int num_labels, bool whole_sweep);

}  // namespace c2f::vision

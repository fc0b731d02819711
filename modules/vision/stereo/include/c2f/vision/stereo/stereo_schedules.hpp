#pragma once
// The stereo application's named schedules (presets of the schedule grammar, schedule.hpp).

#include <span>
#include <string_view>

#include "c2f/lift/schedule.hpp"

namespace c2f::vision {

/// paper            cp:1,1 cp:2,1 cp:3,1 flat (the paper's C2F-TSGO levels)
/// paper-local      local:1,1 local:2,1 local:3,1 flat (the reference's local grouping)
/// paper-threshold  threshold:50 threshold:5 threshold:1 flat
/// paper-slic       slic:32 slic:16 slic:8 flat
/// paper-cc         cp:1,1/cc cp:2,1/cc cp:3,1/cc flat (split into connected components)
/// regions          local:1,1/cc local:2,1/cc local:3,1/cc flat (connected regions of equal
///                  best-label tuples; docs/history/results-2026-11.md)
/// aggregated       agg:1/cc flat (connected regions of equal best label of the unaries
///                  summed over 3 x 3 windows; with --plateau-tolerance 3e-5 and near and
///                  shift moves on the original problem, the fastest to flat's final energy
///                  and the best labeling at deadlines: docs/history/results-2026-11.md)
std::span<const SchedulePreset> stereo_schedule_presets();

/// Schedule::parse with the stereo presets.
Schedule parse_stereo_schedule(std::string_view text);

}  // namespace c2f::vision

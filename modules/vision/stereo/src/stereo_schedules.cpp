#include "c2f/vision/stereo/stereo_schedules.hpp"

#include <array>

namespace c2f::vision {

std::span<const SchedulePreset> stereo_schedule_presets() {
  static const std::array<SchedulePreset, 7> presets{{
      {"paper", "cp:1,1 cp:2,1 cp:3,1 flat"},
      {"paper-local", "local:1,1 local:2,1 local:3,1 flat"},
      {"paper-threshold", "threshold:50 threshold:5 threshold:1 flat"},
      {"paper-slic", "slic:32 slic:16 slic:8 flat"},
      {"paper-cc", "cp:1,1/cc cp:2,1/cc cp:3,1/cc flat"},
      {"regions", "local:1,1/cc local:2,1/cc local:3,1/cc flat"},
      {"aggregated", "agg:1/cc flat"},
  }};
  return presets;
}

Schedule parse_stereo_schedule(std::string_view text) {
  return Schedule::parse(text, stereo_schedule_presets());
}

}  // namespace c2f::vision

#include "c2f/vision/segmentation/segmentation_schedules.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "c2f/vision/superpixels.hpp"

namespace c2f::vision {

std::vector<SchedulePreset> segmentation_schedule_presets(int num_labels) {
  const std::string k = std::to_string((num_labels + 1) / 2);
  return {{"paper", "cp:" + k + ",1 cp:" + k + ",2 flat"},
          {"paper-cc", "cp:" + k + ",1/cc cp:" + k + ",2/cc flat"},
          {"superpixels", "slic:16 slic:8 flat"}};
}

ScheduleProvider segmentation_levels(Schedule schedule, const SegmentationScene& scene) {
  SlicOptions options;
  options.iterations = kSegmentationSlicIterations;
  SuperpixelSource superpixels = slic_source(scene.image, options);
  ScheduleProvider levels(std::move(schedule), scene.shape(), std::move(superpixels));
  // Class 0 for unseeded pixels, 1 + l for the seeds of label l.
  std::vector<int> classes(scene.seeds.size());
  for (std::size_t v = 0; v < classes.size(); ++v) classes[v] = scene.seeds[v] + 1;
  levels.keep_apart(classes);
  return levels;
}

Schedule parse_segmentation_schedule(std::string_view text, int num_labels) {
  const std::vector<SchedulePreset> presets = segmentation_schedule_presets(num_labels);
  return Schedule::parse(text, presets);
}

int coarse_plateau_steps(std::size_t sweep, int num_labels, bool whole_sweep) {
  const std::size_t window = static_cast<std::size_t>(num_labels);
  return static_cast<int>(whole_sweep ? sweep : std::min(sweep, window));
}

}  // namespace c2f::vision

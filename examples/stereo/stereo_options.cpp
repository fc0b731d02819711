#include "stereo_options.hpp"

#include "run_flags.hpp"
#include "tool_options.hpp"

#include <cmath>
#include <filesystem>
#include <iostream>
#include <stdexcept>

#include "c2f/run/stereo_run.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"

namespace c2f::examples {

std::optional<StereoCommand> parse_stereo_command(int argc, char** argv) {
  StereoCommand command;
  const RunDefaults defaults = vision::stereo_defaults();
  std::string schedule = defaults.grid_schedule, smoothness = "tsgo_step";
  RunFlags run(defaults);
  ToolOptions options(
      "c2f-stereo: TSGO stereo matching solved flat or coarse to fine (C2F-TSGO).\n\n"
      "Usage: c2f-stereo LEFT RIGHT -o OUTDIR [options]\n"
      "       c2f-stereo --scene NAME [--data DIR] -o OUTDIR [options]\n\n"
      "Writes disparity.pfm, disparity.png (16-bit, value x 256), disparity-colour.png, "
      "trace.csv,\n"
      "summary.txt and, with ground truth, error.png. Progress goes to stderr.\n\nOptions");
  command.data = "../shared/data";
  options.path("out,o", &command.out_dir, "output directory (created)")
      .text("scene", &command.scene,
            "scene name from DATA/scenes.csv, or middlebury2014/NAME, kitti2015/ID or "
            "opencv-doc/aloe (loads views, GT and masks; scored by the dataset's own measure)")
      .path("data", &command.data, "data root for --scene")
      .integer("labels", &command.labels, {0, 256},
               "number of disparity labels, 2-256 (0: the scene's own range, ndisp of a Middlebury "
               "2014 calib.txt or 128 for KITTI, else 85; disparity.png holds disparities below "
               "256)")
      .text("schedule", &schedule,
            "aggregated (agg:1/cc flat: connected regions of equal best label of 3x3-summed "
            "unaries; with the default moves and tolerance the fastest measured, docs/results.md), "
            "flat (the original problem only, with the same moves: the fair baseline), paper "
            "(CP(1,1) CP(2,1) CP(3,1) flat), paper-local, paper-threshold, paper-slic (the same "
            "three levels with another partition kind), paper-cc (split into connected "
            "components), regions (local:1,1/cc), or levels such as \"cp:2,2 cp:2,3 flat\" (see "
            "docs/stereo.md)")
      .flag("allow-non-refining", &command.allow_non_refining,
            "accept levels that do not refine each other (labels handed down by majority vote)")
      .text("smoothness", &smoothness, "tsgo_step or truncated_linear (the paper's wording)")
      .path("trace", &command.trace, "trace CSV (default OUTDIR/trace.csv)")
      .path("export-uai", &command.export_uai,
            "also write the TSGO energy it solves as a UAI MARKOV model (for c2f-solve, toulbar2; "
            "L^2 potentials per edge: meant for small or downscaled pairs)")
      .file("gt", &command.pair.gt,
            "ground-truth disparities: a PFM (Middlebury 2014, scored by bad 2.0), a 16-bit PNG "
            "(KITTI 2015: disparity x 256, scored by D1) or an 8-bit PNG (0 = unknown)")
      .real("gt-divisor", &command.pair.gt_divisor, {0.0, 65536.0},
            "GT PNG value per disparity pixel (default: by the file, 256 for a 16-bit PNG, 1 "
            "for an 8-bit one; a PNG given a divisor is scored by bad 1)")
      .file("gt-right", &command.pair.gt_right,
            "right-view GT PNG, for a left-right occlusion mask")
      .file("mask", &command.pair.mask, "non-occluded mask PNG (255 = evaluate)")
      .integer("downscale", &command.downscale, {1, 1024},
               "shrink images by this integer factor (GT divided by it)")
      .flag("save-partitions", &command.save_partitions, "write pictures of each level's partition")
      .flag("quiet,q", &command.quiet, "no progress on stderr");
  run.declare(options);
  const auto images = options.parse(argc, argv, {"LEFT RIGHT", 2});
  if (!images) return std::nullopt;
  if (command.scene.empty()) {
    if (images->size() != 2)
      throw std::invalid_argument("give LEFT and RIGHT images, or --scene NAME (see --help)");
    command.pair.left = (*images)[0];
    command.pair.right = (*images)[1];
    require_file(command.pair.left, "LEFT");
    require_file(command.pair.right, "RIGHT");
  } else if (!images->empty()) {
    throw std::invalid_argument("--scene replaces LEFT RIGHT; give one or the other");
  } else if (!command.pair.gt.empty() || !command.pair.gt_right.empty() ||
             !command.pair.mask.empty()) {
    throw std::invalid_argument(
        "--scene loads the scene's own GT and masks; --gt, --gt-right and --mask go with LEFT "
        "RIGHT");
  }
  if (command.pair.gt_divisor > 0.0 && command.pair.gt_divisor < 1.0 / 1024) {
    throw std::invalid_argument(
        "--gt-divisor: expected 0 (by the file) or a number in [1/1024, "
        "65536], got " +
        format_real(command.pair.gt_divisor));
  }
  if (command.out_dir.empty())
    throw std::invalid_argument("-o/--out: an output directory is required");
  command.run = run.config(/*on_grid=*/true);
  command.tsgo.threads = run.threads();
  if (command.allow_non_refining) command.run.limits.level_transfer = LevelTransfer::majority;
  command.tsgo.smoothness =
      with_flag("--smoothness", [&] { return vision::stereo_smoothness_from_string(smoothness); });
  command.schedule =
      with_flag("--schedule", [&] { return vision::parse_stereo_schedule(schedule); });
  if (command.labels == 1) throw std::invalid_argument("--labels: expected 0 or 2-256, got 1");
  // Without --labels the count comes from the scene (its calib.txt, or the default).
  if (command.labels != 0) set_labels(command, command.labels);
  if (command.trace.empty())
    command.trace = (std::filesystem::path(command.out_dir) / "trace.csv").string();
  return command;
}

void set_labels(StereoCommand& command, int labels) {
  command.tsgo.labels = labels;
  if (const std::string problem = command.schedule.validate(labels); !problem.empty()) {
    throw std::invalid_argument("--schedule: " + problem + " (--labels " + std::to_string(labels) +
                                ")");
  }
}

void set_labels_from_scene(StereoCommand& command, const vision::StereoScene& scene) {
  if (command.labels != 0) return;
  if (scene.disparity_range > 256) {
    throw std::invalid_argument(
        (command.scene.empty() ? "LEFT's calib.txt" : "--scene " + command.scene) +
        ": its disparity range is " + std::to_string(scene.disparity_range) +
        " labels, more than 256: give --labels (or --downscale)");
  }
  set_labels(command, vision::label_count(scene, kDefaultLabels));
}

}  // namespace c2f::examples

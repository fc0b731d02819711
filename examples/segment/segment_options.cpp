#include "segment_options.hpp"

#include "coop_flags.hpp"
#include "tool_options.hpp"

#include "c2f/support/number_text.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <stdexcept>
#include <vector>

#include "c2f/support/enum_names.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/vision/segmentation/segmentation_schedules.hpp"

namespace c2f::examples {

std::optional<SegmentCommand> parse_segment_command(int argc, char** argv) {
  // The flags' defaults are the library's (segmentation_defaults()).
  const vision::SegmentationDefaults defaults = vision::segmentation_defaults();
  SegmentCommand command;
  command.schedule = defaults.schedule;
  command.parameters = defaults.parameters;
  double memory_gib = 0.0;  // 0: default_memory_budget()
  std::string method(vision::to_string(defaults.method)), aux(to_string(defaults.strategy));
  std::string start = "zero", plateau = "auto", near_radius = "auto";
  const std::string near_radius_help =
      "near moves in each step's alpha-expansion of the cooperative cut, on the original problem "
      "only: each move to a label frees the pixels within this many edges of that label's "
      "pixels (whole moves where they stall); a number (0: whole moves only) or auto (" +
      std::to_string(defaults.mm_near_radius) +
      " with --aux mm, whole moves with greedy and ceres, docs/segmentation.md)";
  bool labels_from_gt = false, binary = false;
  ToolOptions options(
      "c2f-segment: interactive multi-label segmentation from seed scribbles with cooperative\n"
      "graph cuts (or the Potts baseline), flat or coarse to fine.\n\n"
      "Usage: c2f-segment IMAGE SEEDS -o OUTDIR [options]\n\n"
      "SEEDS is a PNG of the image's size: white = no seed, every other colour one label (labels\n"
      "in ascending (R,G,B) order). Writes labels.png (label colours), overlay.png, trace.csv and\n"
      "summary.txt (with --gt also the pixel error). Progress goes to stderr.\n\nOptions");
  options.path("out,o", &command.out_dir, "output directory (created)")
      .file("gt", &command.files.gt,
            "ground-truth labeling: an image in the seed colours (with --labels-from-gt: any "
            "colours; with --binary: grey 255 object, 0 background, 128 not scored)")
      .flag("labels-from-gt", &labels_from_gt,
            "the coopCuts convention: the labels are the GT's colours and a seeded pixel takes "
            "the GT label under it")
      .flag("binary", &binary, "the binary set's convention: red seeds object, blue background")
      .text("method", &method,
            "coop (cooperative cut) or potts (alpha-expansion of the Potts energy of the same "
            "data)")
      .text("aux", &aux,
            "how the cooperative cut's auxiliary variables move: greedy (the reference's flips), "
            "mm (majorise-minimise) or ceres (continuous relaxation)")
      .text("near-radius", &near_radius, near_radius_help.c_str())
      .text("start", &start,
            "greedy's alpha-expansion start: zero (every trial from the all-zero labeling, the "
            "reference) or current")
      .text("schedule", &command.schedule,
            "flat, superpixels (slic:16 slic:8 flat: with --aux mm the fastest measured, "
            "docs/results.md), paper (the paper's CP(k,2) CP(k,3), k = ceil(L/2): cp:k,1 "
            "cp:k,2), paper-cc, or levels such as \"cp:2,1/cc slic:16 flat\"");
  PreparationFlags preparation;
  declare_coop_parameters(options, command.parameters);
  declare_data_preparation(options, preparation)
      .integer("downscale", &command.downscale, {1, 1024},
               "shrink the image, seeds and GT by this integer factor first")
      .real("time-limit", &command.run.time_limit_seconds, kTimeLimitRange,
            "seconds on the run clock (0: none)")
      .integer("max-steps", &command.run.max_total_steps, {0, kMaxSteps},
               "solver steps in the whole run (0: none)")
      .text("plateau", &plateau,
            "refine a coarse level after this many steps without decrease: a number, auto (the "
            "number of labels, the reference's window, or one sweep when shorter) or sweep (a "
            "whole sweep: L*K+1 flips for greedy)")
      .integer("final-plateau", &command.run.final_plateau, {0, kMaxSteps},
               "stop after this many steps without decrease on the original problem (0: one "
               "sweep: L*K+1 flips for greedy, 1 step for mm, 2 for ceres, L moves for potts)")
      .path("trace", &command.trace, "trace CSV (default OUTDIR/trace.csv)")
      .path("export-uai", &command.export_uai,
            "also write the Potts energy of the same data (the alpha-expansion baseline; a "
            "cooperative cut is not pairwise) as a UAI MARKOV model, for c2f-solve or toulbar2")
      .flag("save-partitions", &command.save_partitions, "write pictures of each level's partition")
      .integer("threads", &preparation.threads, {0, 1024},
               "threads of the run (0: the machine's cores): preparing the data (the labels' "
               "colour models and the edge classes' k-means) and the solve (each step's "
               "max-flow in parts); the result is the same for every count")
      .real("memory", &memory_gib, {0.0, 65536.0},
            "GiB the whole run may take (0: a quarter of this machine's memory, growing to "
            "the run's needs up to half, at most what is available); the Potts method's recycled "
            "move graphs get what the data leave, and a "
            "run whose data do not fit is refused before it allocates")
      .flag("quiet,q", &command.quiet, "no progress on stderr");
  const auto parsed = options.parse(argc, argv, {"IMAGE SEEDS", 2});
  if (!parsed) return std::nullopt;
  const std::vector<std::string>& inputs = *parsed;
  if (inputs.size() != 2)
    throw std::invalid_argument("give IMAGE and SEEDS (got " + std::to_string(inputs.size()) +
                                " positional arguments; see --help)");
  command.files.image = inputs[0];
  command.files.seeds = inputs[1];
  require_file(command.files.image, "IMAGE");
  require_file(command.files.seeds, "SEEDS");
  if (command.out_dir.empty())
    throw std::invalid_argument("-o/--out: an output directory is required");
  if (labels_from_gt && binary)
    throw std::invalid_argument("--labels-from-gt and --binary are two conventions; pick one");
  command.files.convention = labels_from_gt ? vision::SeedConvention::labels_from_gt
                             : binary       ? vision::SeedConvention::binary
                                            : vision::SeedConvention::colours;
  if (labels_from_gt && command.files.gt.empty())
    throw std::invalid_argument("--labels-from-gt needs --gt");
  command.preparation = preparation.resolved();
  command.run.threads = preparation.threads;
  command.run.method =
      with_flag("--method", [&] { return vision::segmentation_method_from_string(method); });
  command.run.coop.strategy = with_flag("--aux", [&] { return aux_strategy_from_string(aux); });
  command.run.coop.start = with_flag("--start", [&] { return expansion_start_from_string(start); });
  command.run.coop.near_radius =
      near_radius == "auto"
          ? defaults.near_radius_for(command.run.coop.strategy)
          : static_cast<int>(parse_integer_option("--near-radius", near_radius, {0, 1'000'000}));
  if (command.run.method != vision::SegmentationMethod::coop && near_radius != "auto")
    throw std::invalid_argument("--near-radius: applies to --method coop only");
  if (plateau == "sweep") {
    command.run.plateau = -1;
  } else if (plateau != "auto") {
    if (!parse_integer(plateau))
      throw std::invalid_argument("--plateau: expected auto, sweep or a number, got '" + plateau +
                                  "'");
    command.run.plateau =
        static_cast<int>(parse_integer_option("--plateau", plateau, {1, kMaxSteps}));
  }
  // The schedule's grammar is checked now; presets and N_L once the labels are known.
  with_flag("--schedule", [&] { return vision::parse_segmentation_schedule(command.schedule, 2); });
  if (command.trace.empty())
    command.trace = (std::filesystem::path(command.out_dir) / "trace.csv").string();
  command.run.memory =
      memory_gib == 0.0 ? default_memory_budget()
                        : memory_budget_of_gib(memory_gib, "--memory " + format_real(memory_gib));
  return command;
}

}  // namespace c2f::examples

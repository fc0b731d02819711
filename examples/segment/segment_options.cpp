#include "segment_options.hpp"

#include "command_line.hpp"

#include <algorithm>
#include <boost/program_options.hpp>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <stdexcept>
#include <vector>

#include "c2f/core/enum_names.hpp"
#include "c2f/core/number_text.hpp"
#include "c2f/vision/segmentation/segmentation_schedules.hpp"

namespace po = boost::program_options;

namespace c2f::examples {

std::string_view to_string(SegmentMethod method) {
  return method == SegmentMethod::coop ? "coop" : "potts";
}

SegmentMethod segment_method_from_string(std::string_view text) {
  constexpr SegmentMethod kAll[] = {SegmentMethod::coop, SegmentMethod::potts};
  return enum_from_string(text, kAll, "method");
}

std::optional<SegmentCommand> parse_segment_command(int argc, char** argv) {
  SegmentCommand command;
  std::string method = "coop", aux = "mm", start = "zero", plateau = "auto";
  bool labels_from_gt = false, binary = false;
  po::options_description visible(
      "c2f-segment: interactive multi-label segmentation from seed scribbles with cooperative\n"
      "graph cuts (or the Potts baseline), flat or coarse to fine.\n\n"
      "Usage: c2f-segment IMAGE SEEDS -o OUTDIR [options]\n\n"
      "SEEDS is a PNG of the image's size: white = no seed, every other colour one label (labels\n"
      "in ascending (R,G,B) order). Writes labels.png (label colours), overlay.png, trace.csv and\n"
      "summary.txt (with --gt also the pixel error). Progress goes to stderr.\n\nOptions");
  visible.add_options()("help,h", "show this help")("out,o", po::value(&command.out_dir),
                                                    "output directory (created)")(
      "gt", po::value(&command.files.gt),
      "ground-truth labeling: an image in the seed colours (with --labels-from-gt: any colours; "
      "with --binary: grey 255 object, 0 background, 128 not scored)")(
      "labels-from-gt", po::bool_switch(&labels_from_gt),
      "the coopCuts convention: the labels are the GT's colours and a seeded pixel takes the GT "
      "label under it")("binary", po::bool_switch(&binary),
                        "the binary set's convention: red seeds object, blue background")(
      "method", po::value(&method)->default_value("coop"),
      "coop (cooperative cut) or potts (alpha-expansion of the Potts energy of the same data)")(
      "aux", po::value(&aux)->default_value("mm"),
      "how the cooperative cut's auxiliary variables move: greedy (the reference's flips), mm "
      "(majorise-minimise) or ceres (continuous relaxation)")(
      "start", po::value(&start)->default_value("zero"),
      "greedy's alpha-expansion start: zero (every trial from the all-zero labeling, the "
      "reference) or current")("schedule",
                               po::value(&command.schedule)->default_value("superpixels"),
                               "flat, superpixels (slic:16 slic:8 flat: with --aux mm the fastest "
                               "measured, docs/results.md), paper (the paper's CP(k,2) CP(k,3), k "
                               "= ceil(L/2): cp:k,1 cp:k,2), paper-cc, or "
                               "levels such as \"cp:2,1/cc slic:16 flat\"")(
      "lambda", po::value(&command.parameters.lambda)->default_value(1.5),
      "weight of the pairwise part")(
      "theta", po::value(&command.parameters.theta)->default_value(0.005),
      "breakpoint of the concave costs, fraction of a class's weight")(
      "alpha", po::value(&command.parameters.alpha)->default_value(0.0),
      "slope of the concave costs after the breakpoint, in [0, 1)")(
      "classes", po::value(&command.classes)->default_value(10), "edge classes K (k-means)")(
      "downscale", po::value(&command.downscale)->default_value(1),
      "shrink the image, seeds and GT by this integer factor first")(
      "time-limit", po::value(&command.time_limit)->default_value(0.0),
      "seconds on the run clock (0: none)")("max-steps",
                                            po::value(&command.max_steps)->default_value(0),
                                            "solver steps in the whole run (0: none)")(
      "plateau", po::value(&plateau)->default_value("auto"),
      "refine a coarse level after this many steps without decrease: a number, auto (the number "
      "of labels, the reference's window, or one sweep when shorter) or sweep (a whole sweep: "
      "L*K+1 flips for greedy)")(
      "final-plateau", po::value(&command.final_plateau)->default_value(0),
      "stop after this many steps without decrease on the original problem (0: one sweep: "
      "L*K+1 flips for greedy, 1 step for mm, 2 for ceres, L moves for potts)")(
      "trace", po::value(&command.trace), "trace CSV (default OUTDIR/trace.csv)")(
      "save-partitions", po::bool_switch(&command.save_partitions),
      "write pictures of each level's partition")("quiet,q", po::bool_switch(&command.quiet),
                                                  "no progress on stderr");
  const auto parsed = parse_command_line(argc, argv, visible);
  if (!parsed) return std::nullopt;
  const std::vector<std::string>& inputs = *parsed;
  if (inputs.size() != 2)
    throw std::invalid_argument("give IMAGE and SEEDS (got " + std::to_string(inputs.size()) +
                                " positional arguments; see --help)");
  command.files.image = inputs[0];
  command.files.seeds = inputs[1];
  require_file(command.files.image, "IMAGE");
  require_file(command.files.seeds, "SEEDS");
  require_file(command.files.gt, "--gt");
  if (command.out_dir.empty())
    throw std::invalid_argument("-o/--out: an output directory is required");
  if (labels_from_gt && binary)
    throw std::invalid_argument("--labels-from-gt and --binary are two conventions; pick one");
  command.files.convention = labels_from_gt ? vision::SeedConvention::labels_from_gt
                             : binary       ? vision::SeedConvention::binary
                                            : vision::SeedConvention::colours;
  if (labels_from_gt && command.files.gt.empty())
    throw std::invalid_argument("--labels-from-gt needs --gt");
  command.method = with_flag("--method", [&] { return segment_method_from_string(method); });
  command.coop.strategy = with_flag("--aux", [&] { return aux_strategy_from_string(aux); });
  command.coop.start = with_flag("--start", [&] { return expansion_start_from_string(start); });
  if (const std::string problem = command.parameters.validate(); !problem.empty())
    throw std::invalid_argument("--lambda/--theta/--alpha: " + problem);
  if (command.classes < 1) throw std::invalid_argument("--classes: must be >= 1");
  if (command.downscale < 1) throw std::invalid_argument("--downscale: must be >= 1");
  if (!(command.time_limit >= 0.0) || !std::isfinite(command.time_limit))
    throw std::invalid_argument("--time-limit: must be finite and >= 0");
  if (command.max_steps < 0) throw std::invalid_argument("--max-steps: must be >= 0");
  if (plateau == "sweep") {
    command.plateau = -1;
  } else if (plateau != "auto") {
    const auto value = parse_integer(plateau);
    if (!value || *value < 1 || *value > 1'000'000)
      throw std::invalid_argument("--plateau: '" + plateau +
                                  "' is not auto, sweep or a number >= 1");
    command.plateau = static_cast<int>(*value);
  }
  if (command.final_plateau < 0) throw std::invalid_argument("--final-plateau: must be >= 0");
  // The schedule's grammar is checked now; presets and N_L once the labels are known.
  with_flag("--schedule", [&] { return vision::parse_segmentation_schedule(command.schedule, 2); });
  if (command.trace.empty())
    command.trace = (std::filesystem::path(command.out_dir) / "trace.csv").string();
  return command;
}

Options run_options(const SegmentCommand& command, int num_labels, int num_classes) {
  Options options;
  const std::size_t sweep =
      command.method == SegmentMethod::potts
          ? static_cast<std::size_t>(num_labels)
          : CoopSolver::steps_per_sweep(command.coop.strategy, num_labels, num_classes);
  // Coarse levels: the reference's window of L trials, or one sweep when that is shorter (a
  // majorise-minimise step without decrease is already a fixed point).
  options.plateau_steps = {
      command.plateau > 0 ? command.plateau
      : command.plateau < 0
          ? static_cast<int>(sweep)
          : static_cast<int>(std::min<std::size_t>(sweep, static_cast<std::size_t>(num_labels)))};
  options.plateau_steps_at_original =
      command.final_plateau > 0 ? command.final_plateau : static_cast<int>(sweep);
  options.time_limit_seconds = command.time_limit;
  options.max_total_steps = command.max_steps;
  return options;
}

}  // namespace c2f::examples

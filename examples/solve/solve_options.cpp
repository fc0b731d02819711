#include "solve_options.hpp"

#include <filesystem>
#include <stdexcept>

#include "c2f/support/number_text.hpp"
#include "run_flags.hpp"
#include "tool_options.hpp"

namespace c2f::examples {

namespace {

/// "WxH" with both sides in [1, 2^20].
GridShape parse_grid(const std::string& text) {
  const std::size_t x = text.find('x');
  const auto side = [&](std::string_view part) { return parse_integer(part); };
  const auto width =
      x == std::string::npos ? std::nullopt : side(std::string_view(text).substr(0, x));
  const auto height =
      x == std::string::npos ? std::nullopt : side(std::string_view(text).substr(x + 1));
  if (!width || !height || *width < 1 || *height < 1 || *width > (1 << 20) || *height > (1 << 20))
    throw std::invalid_argument("--grid: expected WIDTHxHEIGHT with sides in [1, 1048576], got '" +
                                text + "'");
  return {static_cast<std::size_t>(*width), static_cast<std::size_t>(*height)};
}

}  // namespace

std::optional<SolveCommand> parse_solve_command(int argc, char** argv) {
  SolveCommand command;
  std::string grid;
  const RunDefaults defaults = pairwise_defaults();
  RunFlags run(defaults);
  const std::string default_schedule =
      defaults.grid_schedule + " with --grid; without, " + defaults.local_schedule +
      " where the model's edges are local in its variables' order (a lattice), else " +
      defaults.general_schedule;
  const std::string schedule_help =
      "default: " + default_schedule +
      " (the measured best, docs/results.md); flat (the original problem only, the fair "
      "baseline), paper (cp:1,1 cp:2,1 cp:3,1 flat), auto:F1,F2,..., colour-passing levels "
      "such as \"cp:2,1 cp:2,2 flat\", agg:R (unaries summed over (2R+1)^2 windows with --grid, "
      "R times over graph neighbours without) and /cc; with --grid also local, threshold and "
      "blocks levels (see docs/solve.md)";
  ToolOptions options(
      "c2f-solve: minimises any pairwise model in the UAI MARKOV format (as toulbar2, OpenGM's\n"
      "converters and the UAI competitions write it), flat or coarse to fine.\n\n"
      "Usage: c2f-solve MODEL.uai -o OUTDIR [options]\n\n"
      "All variables must have one cardinality, factors one or two variables and potentials\n"
      "> 0 (cost = -ln potential). Writes labeling.mpe (the UAI MPE result format), trace.csv\n"
      "and summary.txt. Progress goes to stderr.\n\nOptions");
  options.path("out,o", &command.out_dir, "output directory (created)")
      .text("schedule", &command.schedule_text, schedule_help.c_str())
      .text("grid", &grid,
            "WIDTHxHEIGHT: the model's variables are a row-major pixel grid (enables grid levels)")
      .path("trace", &command.trace, "trace CSV (default OUTDIR/trace.csv)")
      .flag("quiet,q", &command.quiet, "no progress on stderr");
  run.declare(options);
  const auto models = options.parse(argc, argv, {"MODEL.uai", 1});
  if (!models) return std::nullopt;
  if (models->empty()) throw std::invalid_argument("give MODEL.uai (see --help)");
  command.model = models->front();
  require_file(command.model, "MODEL");
  if (command.out_dir.empty())
    throw std::invalid_argument("-o/--out: an output directory is required");
  if (!grid.empty()) command.grid = parse_grid(grid);
  command.run = run.config(command.grid.has_value());
  // The grammar now; the label count and the grid once the model is read (the default, which
  // depends on the model's edges, then too).
  if (!command.schedule_text.empty()) {
    with_flag("--schedule",
              [&] { return Schedule::parse(command.schedule_text, pairwise_schedule_presets()); });
  }
  if (command.trace.empty())
    command.trace = (std::filesystem::path(command.out_dir) / "trace.csv").string();
  return command;
}

Schedule solve_schedule(const SolveCommand& command, const PairwiseEnergy& energy) {
  const std::size_t num_variables = energy.num_variables();
  const int num_labels = energy.num_labels();
  const std::string text = command.schedule_text.empty()
                               ? pairwise_defaults().schedule_for(energy, command.grid.has_value())
                               : command.schedule_text;
  const Schedule schedule =
      with_flag("--schedule", [&] { return Schedule::parse(text, pairwise_schedule_presets()); });
  if (const std::string problem = schedule.validate(num_labels); !problem.empty())
    throw std::invalid_argument(option_message("--schedule", problem) + " (the model has " +
                                std::to_string(num_labels) + " labels)");
  if (command.grid) {
    if (command.grid->size() != num_variables) {
      throw std::invalid_argument("--grid: " + std::to_string(command.grid->width) + "x" +
                                  std::to_string(command.grid->height) + " is " +
                                  std::to_string(command.grid->size()) + " pixels, the model has " +
                                  std::to_string(num_variables) + " variables");
    }
    return schedule;
  }
  if (const std::string problem = schedule.validate_without_grid(); !problem.empty()) {
    throw std::invalid_argument("--schedule: " + problem +
                                "; give --grid WIDTHxHEIGHT or use cp, agg and auto levels");
  }
  return schedule;
}

}  // namespace c2f::examples

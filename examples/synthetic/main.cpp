// c2f-synthetic: solves a synthetic labeling problem (piecewise-constant image under noise)
// flat and coarse to fine with the same solver and clock, and prints both traces. The options
// become library calls in named steps: make the problem, solve flat, solve coarse to fine,
// report, write.

#include <filesystem>
#include <fstream>
#include <iostream>
#include <optional>
#include <sstream>
#include <string>

#include "c2f/c2f.hpp"
#include "c2f/support/output_file.hpp"
#include "interrupt_watch.hpp"
#include "output_folder.hpp"
#include "synthetic_options.hpp"
#include "tool_options.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

/// The run of both solves: ICM within the command's memory budget.
RunConfig run_config(const examples::SyntheticCommand& command) {
  RunConfig config;
  config.solver.original = IcmOptions{};
  config.limits = command.options;
  config.memory = command.memory;
  config.energy_name = "the synthetic problem";
  return config;
}

/// One ICM run over `levels`, stopped early by `interrupts`; prints its trace and summary, and
/// writes the trace to `trace_path` unless that is empty.
template <class Provider>
Summary solve(const char* name, const SyntheticProblem& problem, Provider& levels,
              const RunConfig& config, const examples::InterruptWatch& interrupts,
              const std::filesystem::path& trace_path) {
  std::ostringstream trace;
  TraceWriter writer(
      trace, [&](std::span<const Label> ground) { return pixel_error(ground, problem.truth); });
  const Summary summary =
      run(problem.energy, levels, config, observe_all({std::ref(writer), interrupts.observer()}))
          .summary;
  std::cout << "# trace: " << name << "\n"
            << trace.str() << "# summary: " << name << "\n"
            << summary.report() << "\n";
  if (!trace_path.empty()) {
    std::ofstream file = open_trace_file(trace_path.string());
    file << trace.str();
    close_checked(file, trace_path.string());
  }
  return summary;
}

void report(const char* name, const Summary& summary, const SyntheticProblem& problem) {
  std::cout << name << " energy " << summary.energy << ", error "
            << pixel_error(summary.labeling, problem.truth) << ", " << summary.seconds << " s\n";
}

/// Before the problem is made: it and the run's floor (ICM, coarse levels) must fit the budget.
void require_memory_for(const examples::SyntheticCommand& command) {
  command.memory.require("the synthetic problem of " + std::to_string(command.spec.shape.width) +
                             "x" + std::to_string(command.spec.shape.height) + " pixels with " +
                             std::to_string(command.spec.num_labels) + " labels",
                         grid_run_memory_need(run_config(command).solver, command.spec.shape.width,
                                              command.spec.shape.height, command.spec.num_labels,
                                              CostStorage::double_precision, 0));
}

/// With -o, the run's files are staged and land together at the end (an earlier run's files
/// stay as they were when this run fails); without it, nothing is written.
std::optional<examples::OutputFolder> open_outputs(const std::string& out_dir) {
  if (out_dir.empty()) return std::nullopt;
  return std::optional<examples::OutputFolder>(
      std::in_place, out_dir, "c2f-synthetic",
      std::vector<std::string>{"trace-flat.csv", "trace-c2f.csv", "truth.pgm", "flat.pgm",
                               "c2f.pgm"});
}

/// Where a file of the run goes: staged with -o, nowhere (empty) without.
std::filesystem::path staged(const std::optional<examples::OutputFolder>& output,
                             const char* name) {
  return output ? output->staging() / name : std::filesystem::path();
}

/// The truth and both results as pictures, then every file into place.
void write_outputs(std::optional<examples::OutputFolder>& output, const std::string& out_dir,
                   const SyntheticProblem& problem, const vision::SyntheticSpec& spec,
                   const Summary& flat, const Summary& c2f) {
  if (!output) return;
  const std::filesystem::path folder = output->staging();
  write_label_pgm((folder / "truth.pgm").string(), problem.truth, spec.shape, spec.num_labels);
  write_label_pgm((folder / "flat.pgm").string(), flat.labeling, spec.shape, spec.num_labels);
  write_label_pgm((folder / "c2f.pgm").string(), c2f.labeling, spec.shape, spec.num_labels);
  output->commit();
  std::cerr << "c2f-synthetic: wrote traces and images to " << out_dir << "\n";
}

}  // namespace

int main(int argc, char** argv) {
  // Ctrl-C or SIGTERM: the running solve stops at its next step, and what was found is still
  // reported and written.
  const examples::InterruptWatch interrupts;
  return examples::run_tool("c2f-synthetic", [&] {
    const auto parsed = examples::parse_synthetic_command(argc, argv);
    if (!parsed) return 0;
    const examples::SyntheticCommand& command = *parsed;

    BlockHierarchy hierarchy = examples::with_flag("--blocks", [&] {  // checks the sizes first
      return BlockHierarchy(command.spec.shape, command.block_sizes);
    });
    require_memory_for(command);
    const SyntheticProblem problem = make_synthetic_problem(command.spec);
    std::optional<examples::OutputFolder> output = open_outputs(command.out_dir);
    std::cerr << "c2f-synthetic: " << command.spec.shape.width << "x" << command.spec.shape.height
              << " pixels, " << command.spec.num_labels << " labels, "
              << problem.energy.edges().size() << " edges\n";

    PartitionList flat_levels;
    const RunConfig config = run_config(command);
    const Summary flat =
        solve("flat", problem, flat_levels, config, interrupts, staged(output, "trace-flat.csv"));
    // After an interrupt the coarse-to-fine run stops at its first step.
    const Summary c2f =
        solve("c2f", problem, hierarchy, config, interrupts, staged(output, "trace-c2f.csv"));

    report("flat:", flat, problem);
    report("c2f: ", c2f, problem);
    write_outputs(output, command.out_dir, problem, command.spec, flat, c2f);
    if (interrupts.interrupted()) {
      std::cerr << "c2f-synthetic: interrupted by " << interrupts.signal_name()
                << ": reported the best labelings found so far\n";
    }
    return interrupts.exit_code();
  });
}

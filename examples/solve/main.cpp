// c2f-solve: any pairwise model in the UAI MARKOV format, minimised flat or coarse to fine with
// the partitions that need no image. The options become library calls in named steps: read the
// model, choose its schedule, solve, write the labeling, trace and summary.

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>

#include "c2f/c2f.hpp"
#include "c2f/support/input_file.hpp"
#include "c2f/support/memory_need.hpp"
#include "c2f/support/output_file.hpp"
#include "interrupt_watch.hpp"
#include "output_paths.hpp"
#include "run_record.hpp"
#include "run_report.hpp"
#include "solve_options.hpp"
#include "tool_options.hpp"

using namespace c2f;
using Clock = std::chrono::steady_clock;

namespace {

struct TimedModel {
  PairwiseEnergy energy;
  double seconds;
};

TimedModel read_model(const examples::SolveCommand& command) {
  const auto start = Clock::now();
  PairwiseEnergy energy = read_uai_file(command.model, *command.run.memory);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!command.quiet) {
    std::fprintf(stderr, "c2f-solve: %s: %zu variables, %d labels, %zu pairwise factors (%.2f s)\n",
                 command.model.c_str(), energy.num_variables(), energy.num_labels(),
                 energy.edges().size(), seconds);
  }
  return {std::move(energy), seconds};
}

void write_summary(const std::filesystem::path& folder, const examples::SolveCommand& command,
                   const TimedModel& model, const Schedule& schedule,
                   const ScheduleProvider& levels, const RunReport& run,
                   const examples::InterruptWatch& interrupts) {
  std::ofstream report(folder / "summary.txt");
  report << "model " << command.model << ": " << model.energy.num_variables() << " variables, "
         << model.energy.num_labels() << " labels, " << model.energy.edges().size()
         << " pairwise factors\n"
         << "schedule " << schedule.to_string() << ", solver "
         << to_string(command.run.solver.kind()) << "\n"
         << "reading the model: " << model.seconds << " s (not on the run clock)\n"
         << run.memory_line() << "\n"
         << run.threads_line() << "\n";
  examples::write_run_report(report, levels.reports(), run.summary, interrupts);
  report << "energy = sum of -ln(potential) over the factors; log10 of the unnormalised "
         << "probability: " << -run.summary.energy / std::log(10.0) << "\n";
  close_checked(report, "summary.txt");
}

/// The files a run writes into its output folder.
const std::vector<std::string> kOutputs = {"labeling.mpe", "trace.csv", "summary.txt"};

/// The run's configuration for `model`, checked before any output is staged: the model and the
/// run's floor must fit the budget (recycled move graphs get the rest); says so on stderr.
RunConfig planned_config(const examples::SolveCommand& command, const TimedModel& model) {
  RunConfig config = command.run;
  config.energy_name = "MODEL '" + command.model + "' solved by " +
                       std::string(to_string(command.run.solver.kind()));
  const MemoryPlan plan = plan_run(model.energy, config);
  if (!command.quiet) {
    std::fprintf(stderr, "c2f-solve: memory budget %s, floor %s\n",
                 command.run.memory->describe().c_str(),
                 format_bytes(static_cast<double>(plan.floor)).c_str());
  }
  return config;
}

}  // namespace

int main(int argc, char** argv) {
  // Ctrl-C or SIGTERM: the run stops at its next step and the best labeling is written.
  const examples::InterruptWatch interrupts;
  return examples::run_tool("c2f-solve", [&] {
    const auto parsed = examples::parse_solve_command(argc, argv);
    if (!parsed) return 0;
    const examples::SolveCommand& command = *parsed;
    set_input_memory_limit(command.run.memory->ceiling());  // no input may take more to read

    examples::check_output_paths(
        {command.out_dir, kOutputs, {{"--trace", command.trace, "trace.csv"}}},
        {{"MODEL", command.model}});
    const TimedModel model = read_model(command);
    const Schedule schedule = examples::solve_schedule(command, model.energy);
    ScheduleProvider levels =
        command.grid ? ScheduleProvider(schedule, *command.grid) : ScheduleProvider(schedule);
    const RunConfig config = planned_config(command, model);
    // Outputs are staged and moved into place together at the end.
    examples::RunRecord record(command.out_dir, kOutputs, command.trace, "c2f-solve",
                               command.quiet);
    const RunReport run = c2f::run(model.energy, levels, config,
                                   record.observer(TraceWriter::ErrorFunction{}, interrupts));

    write_uai_mpe_file(run.summary.labeling, (record.staging() / "labeling.mpe").string());
    write_summary(record.staging(), command, model, schedule, levels, run, interrupts);
    record.commit();
    examples::print_run_end("c2f-solve", run.summary, interrupts, command.out_dir, command.quiet);
    return interrupts.exit_code();
  });
}

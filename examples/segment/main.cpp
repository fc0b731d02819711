// c2f-segment: interactive segmentation with cooperative graph cuts (or the Potts baseline),
// flat or coarse to fine. The options become library calls in named steps: load the scene,
// build the energies, solve, write the outputs.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>

#include "c2f/c2f.hpp"
#include "c2f/support/input_file.hpp"
#include "c2f/support/output_file.hpp"
#include "interrupt_watch.hpp"
#include "model_export.hpp"
#include "output_paths.hpp"
#include "run_record.hpp"
#include "run_report.hpp"
#include "segment_options.hpp"
#include "tool_options.hpp"

using namespace c2f;
using namespace c2f::vision;
using Clock = std::chrono::steady_clock;

namespace {

/// The energies, built once (off the run clock: the same for flat and coarse-to-fine runs).
struct TimedProblem {
  SegmentationProblem problem;
  double seconds;
};

TimedProblem build_problem(const SegmentationScene& scene,
                           const examples::SegmentCommand& command) {
  command.run.memory->require(
      "segmenting " + std::to_string(scene.image.cols) + "x" + std::to_string(scene.image.rows) +
          " pixels into " + std::to_string(scene.num_labels()) + " labels",
      segmentation_memory_estimate(scene.image.total(), scene.num_labels()));
  const auto start = Clock::now();
  SegmentationProblem problem =
      segmentation_problem(scene, command.parameters, command.preparation);
  const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
  if (!command.quiet) {
    std::fprintf(stderr, "c2f-segment: GMM unaries and %zu edges in %d classes in %.2f s\n",
                 problem.coop.edges().size(), command.preparation.num_classes, seconds);
  }
  return {std::move(problem), seconds};
}

/// The files a run writes into its output folder ('*' matches any run of characters).
const std::vector<std::string> kOutputs = {"labels.png", "overlay.png", "trace.csv", "summary.txt",
                                           "partition-level*.png"};

/// Before anything is read: no output over an input or over another output.
void check_paths(const examples::SegmentCommand& command) {
  examples::check_output_paths(
      {command.out_dir,
       kOutputs,
       {{"--trace", command.trace, "trace.csv"}, {"--export-uai", command.export_uai}}},
      {{"IMAGE", command.files.image}, {"SEEDS", command.files.seeds}, {"--gt", command.files.gt}});
}

Schedule schedule_for(const examples::SegmentCommand& command, const SegmentationScene& scene) {
  const int num_labels = scene.num_labels();
  try {
    Schedule schedule = parse_segmentation_schedule(command.schedule, num_labels);
    if (const std::string problem = schedule.validate(num_labels); !problem.empty())
      throw std::invalid_argument(problem);
    const GridShape shape{static_cast<std::size_t>(scene.image.cols),
                          static_cast<std::size_t>(scene.image.rows)};
    if (const std::string problem = schedule.validate_image(shape); !problem.empty()) {
      // Named with its levels: the schedule may be the default, which the user never wrote.
      throw std::invalid_argument(command.schedule + " (" + schedule.to_string() + "): " + problem);
    }
    return schedule;
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string("--schedule: ") + error.what());
  }
}

/// How the k-means ran, e.g. "sample start, batch and online phases".
std::string kmeans_text(const KMeansOptions& kmeans) {
  return std::string(to_string(kmeans.start)) + " start" +
         (kmeans.online_phase ? ", batch and online phases" : ", batch rounds only");
}

void write_summary(const std::filesystem::path& out, const examples::SegmentCommand& command,
                   const SegmentationScene& scene, const TimedProblem& built,
                   const ScheduleProvider& levels, const RunReport& run,
                   const std::optional<double>& error, const examples::InterruptWatch& interrupts) {
  const Summary& summary = run.summary;
  std::ofstream report((out / "summary.txt").string());
  if (!report) throw std::runtime_error("cannot write '" + (out / "summary.txt").string() + "'");
  report << "image " << scene.name << " " << scene.shape().width << "x" << scene.shape().height
         << ", " << scene.num_labels() << " labels (seeds: " << to_string(command.files.convention)
         << ")\nmethod " << to_string(command.run.method);
  if (command.run.method == SegmentationMethod::coop) {
    report << ", auxiliary variables " << to_string(command.run.coop.strategy);
    if (command.run.coop.strategy == AuxStrategy::greedy)
      report << " (expansion from " << to_string(command.run.coop.start) << ")";
  }
  report << ", schedule " << levels.schedule().to_string() << "\nlambda "
         << command.parameters.lambda << ", theta " << command.parameters.theta << ", alpha "
         << command.parameters.alpha << ", " << command.preparation.num_classes
         << " edge classes, k-means " << kmeans_text(command.preparation.gmm_kmeans) << ", seeds "
         << command.preparation.gmm_kmeans.seed << " (GMMs) and "
         << command.preparation.edge_kmeans.seed << " (edge classes)\n"
         << "data preparation: " << built.seconds << " s (not on the run clock)\n"
         << run.memory_line() << "\n"
         << run.threads_line() << "\n";
  examples::write_run_report(report, levels.reports(), summary, interrupts);
  report << "cooperative-cut energy of the result: "
         << built.problem.coop.evaluate(summary.labeling)
         << "\nPotts energy of the result: " << built.problem.potts.evaluate(summary.labeling)
         << "\n";
  if (error) report << "pixel error: " << 100.0 * *error << "%\n";
  close_checked(report, "summary.txt");
}

/// The run's last lines on stderr: the pixel error (with GT), then the common end.
void report_end(const examples::SegmentCommand& command, const Summary& summary,
                const std::optional<double>& error, const examples::InterruptWatch& interrupts) {
  if (error && !command.quiet)
    std::fprintf(stderr, "c2f-segment: pixel error %.2f%%\n", 100.0 * *error);
  examples::print_run_end("c2f-segment", summary, interrupts, command.out_dir, command.quiet);
}

/// The run: the method's solver on the schedule's levels within the budget (the recycled move
/// graphs get what it leaves; a cooperative run keeps the Potts energy beside it), every step
/// traced (with its pixel error when there is GT) and each level's partition kept.
RunReport solve(const examples::SegmentCommand& command, const SegmentationScene& scene,
                const TimedProblem& built, ScheduleProvider& levels, examples::RunRecord& record,
                LevelPartitionRecorder& partitions, const examples::InterruptWatch& interrupts) {
  return run_segmentation(built.problem, levels, command.run,
                          record.observer(scene.truth.empty() ? TraceWriter::ErrorFunction{}
                                                              : pixel_error_function(scene),
                                          interrupts, {std::ref(partitions)}));
}

/// Stages the label image, overlay, summary.txt and the saved partitions; returns the pixel
/// error (with GT).
std::optional<double> write_outputs(const examples::RunRecord& record,
                                    const examples::SegmentCommand& command,
                                    const SegmentationScene& scene, const TimedProblem& built,
                                    const ScheduleProvider& levels,
                                    const LevelPartitionRecorder& partitions, const RunReport& run,
                                    const examples::InterruptWatch& interrupts) {
  const auto error =
      write_segmentation_outputs(record.staging().string(), run.summary.labeling, scene);
  write_summary(record.staging(), command, scene, built, levels, run, error, interrupts);
  partitions.write(record.staging().string(), scene.shape());
  return error;
}

}  // namespace

int main(int argc, char** argv) {
  // Ctrl-C or SIGTERM: the run stops at its next step and the best labeling is written.
  const examples::InterruptWatch interrupts;
  return examples::run_tool("c2f-segment", [&] {
    const auto parsed = examples::parse_segment_command(argc, argv);
    if (!parsed) return 0;
    const examples::SegmentCommand& command = *parsed;

    set_input_memory_limit(command.run.memory->ceiling());  // no input may take more to read
    check_paths(command);
    const SegmentationScene scene =
        downscale(load_segmentation_scene(command.files), command.downscale);
    const Schedule schedule = schedule_for(command, scene);
    // Outputs are staged and moved into place together at the end: a failed or crashed run
    // leaves an earlier run's files as they were.
    examples::RunRecord record(command.out_dir, kOutputs, command.trace, "c2f-segment",
                               command.quiet);
    const TimedProblem built = build_problem(scene, command);
    // The Potts model as UAI, staged with the other outputs (it lands only if the run does).
    if (!examples::export_uai(built.problem.potts, command.export_uai, record, interrupts))
      return interrupts.exit_code();

    ScheduleProvider levels = segmentation_levels(schedule, scene);
    LevelPartitionRecorder partitions(command.save_partitions);
    const RunReport run = solve(command, scene, built, levels, record, partitions, interrupts);

    const auto error =
        write_outputs(record, command, scene, built, levels, partitions, run, interrupts);
    record.commit();
    report_end(command, run.summary, error, interrupts);
    return interrupts.exit_code();
  });
}

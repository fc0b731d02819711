// c2f-stereo: TSGO stereo matching, flat or coarse to fine. The options become library calls
// in named steps: load the scene, build the TSGO energy, solve, write the outputs.

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "c2f/c2f.hpp"
#include "c2f/support/input_file.hpp"
#include "c2f/support/output_file.hpp"
#include "interrupt_watch.hpp"
#include "model_export.hpp"
#include "output_paths.hpp"
#include "run_flags.hpp"
#include "run_record.hpp"
#include "run_report.hpp"
#include "stereo_options.hpp"
#include "tool_options.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {

/// The files a run writes into its output folder ('*' matches any run of characters).
const std::vector<std::string> kOutputs = {
    "disparity.pfm", "disparity.png", "disparity-colour.png", "error.png",
    "trace.csv",     "summary.txt",   "partition-level*.png"};

/// Before anything is read: no output over an input or over another output.
void check_paths(const examples::StereoCommand& command) {
  examples::check_output_paths(
      {command.out_dir,
       kOutputs,
       {{"--trace", command.trace, "trace.csv"}, {"--export-uai", command.export_uai}}},
      {{"LEFT", command.pair.left},
       {"RIGHT", command.pair.right},
       {"--gt", command.pair.gt},
       {"--gt-right", command.pair.gt_right},
       {"--mask", command.pair.mask}});
}

/// The scene the command names, downscaled, with the label count set (--labels or the scene's
/// range) and the schedule checked against both.
StereoScene load_input(examples::StereoCommand& command) {
  StereoScene scene;
  if (command.scene.empty()) {
    scene = downscale(load_stereo_pair(command.pair), command.downscale);
  } else {
    try {
      scene = downscale(load_named_scene(command.data, command.scene), command.downscale);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(std::string("--scene: ") + error.what());
    }
  }
  if (const std::string problem = command.schedule.validate_image(scene.shape()); !problem.empty())
    throw std::invalid_argument("--schedule: " + command.schedule.to_string() + ": " + problem);
  examples::set_labels_from_scene(command, scene);
  return scene;
}

/// Before anything is allocated: TSGO step 1 and the run's floor must fit the budget and the
/// machine, else "needs N GiB".
void require_memory_for(const examples::StereoCommand& command, const StereoScene& scene) {
  const GridShape shape = scene.shape();
  const std::string what = "the TSGO energy of " + std::to_string(shape.width) + "x" +
                           std::to_string(shape.height) + " pixels and " +
                           std::to_string(command.tsgo.labels) + " labels solved by " +
                           std::string(to_string(command.run.solver.kind()));
  command.run.memory->require((command.scene.empty() ? "LEFT '" + command.pair.left + "': "
                                                     : "--scene " + command.scene + ": ") +
                                  what,
                              stereo_memory_need(shape, command.tsgo, command.run.solver));
}

/// TSGO step 1 (the cost volume) and step 2 (the energy), timed apart from the run clock: it is
/// the same for flat and coarse-to-fine runs. Errors name the views.
PreparedStereo prepare(const examples::StereoCommand& command, const StereoScene& scene) {
  PreparedStereo prepared = [&] {
    try {
      return prepare_stereo(scene, command.tsgo);
    } catch (const std::invalid_argument& error) {  // a problem of these views: name them
      throw std::invalid_argument(
          (command.scene.empty()
               ? "LEFT '" + command.pair.left + "', RIGHT '" + command.pair.right + "'"
               : "--scene " + command.scene) +
          ": " + error.what());
    }
  }();
  if (!command.quiet)
    std::fprintf(stderr, "c2f-stereo: TSGO step 1 (cost volume) %.2f s on %u threads\n",
                 prepared.seconds, prepared.threads);
  return prepared;
}

/// The run: the configured solver on the schedule's levels within the budget (the recycled
/// move graphs get what it leaves above the run's floor on the built energy), every step traced
/// (with its error when there is GT) and each level's partition kept for --save-partitions.
StereoRunReport solve(const examples::StereoCommand& command, const StereoScene& scene,
                      const PreparedStereo& problem, examples::RunRecord& record,
                      LevelPartitionRecorder& partitions,
                      const examples::InterruptWatch& interrupts) {
  RunConfig config = command.run;
  config.energy_name = "the run on the TSGO energy";
  return run_stereo(
      problem.problem, command.schedule, config,
      record.observer(scene.gt.empty() ? TraceWriter::ErrorFunction{} : bad_pixel_error(scene),
                      interrupts, {std::ref(partitions)}));
}

void write_summary(const std::filesystem::path& out, const examples::StereoCommand& command,
                   const StereoScene& scene, const PreparedStereo& problem,
                   const StereoRunReport& stereo_run, const std::optional<BadPixelRates>& rates,
                   const std::string& dataset_error, const examples::InterruptWatch& interrupts) {
  const GridShape shape = scene.shape();
  std::ofstream report((out / "summary.txt").string());
  if (!report) throw std::runtime_error("cannot write '" + (out / "summary.txt").string() + "'");
  report << "scene " << scene.name << " " << shape.width << "x" << shape.height << ", "
         << command.tsgo.labels << " labels\nschedule " << command.schedule.to_string()
         << ", solver " << to_string(command.run.solver.kind()) << ", max-flow "
         << to_string(command.run.solver.maxflow)
         << examples::near_and_shift_moves_text(command.run.solver) << "\n"
         << "TSGO step 1: " << problem.seconds << " s on " << problem.threads
         << " threads (not on the run clock, same for every schedule)\n"
         << stereo_run.run.memory_line() << "\n"
         << stereo_run.run.threads_line() << "\n";
  examples::write_run_report(report, stereo_run.levels, stereo_run.run.summary, interrupts);
  if (!scene.gt_convention.empty()) report << "GT read as " << scene.gt_convention << "\n";
  if (!dataset_error.empty()) report << dataset_error << "\n";
  if (rates) {
    report << rates->brief() << "\nnon-occluded pixels from: " << scene.nonoccluded_source
           << "\nreference variant (bad>1 over all pixels): " << 100 * rates->reference_variant
           << "%\n";
  }
  close_checked(report, "summary.txt");
}

void announce(const examples::StereoCommand& command, const StereoScene& scene) {
  if (command.quiet) return;
  std::fprintf(stderr,
               "c2f-stereo: %s %zux%zu, %d labels, schedule %s, solver %s, memory budget %s\n",
               scene.name.c_str(), scene.shape().width, scene.shape().height, command.tsgo.labels,
               command.schedule.to_string().c_str(),
               std::string(to_string(command.run.solver.kind())).c_str(),
               command.run.memory->describe().c_str());
}

/// How the run's labeling scores against the GT: the fixed bad-pixel rates (std::nullopt without
/// GT) and the dataset's own error line ("" when it has none besides them).
struct RunScores {
  std::optional<BadPixelRates> rates;
  std::string dataset_error;
};

/// Stages the disparity maps, summary.txt and the saved partitions, and returns the scores.
RunScores write_outputs(const examples::RunRecord& record, const examples::StereoCommand& command,
                        const StereoScene& scene, const PreparedStereo& problem,
                        const LevelPartitionRecorder& partitions, const StereoRunReport& stereo_run,
                        const examples::InterruptWatch& interrupts) {
  const Labeling& labeling = stereo_run.run.summary.labeling;
  RunScores scores{
      write_disparity_outputs(record.staging().string(), labeling, scene, command.tsgo.labels),
      scene_error_line(labeling, scene)};
  write_summary(record.staging(), command, scene, problem, stereo_run, scores.rates,
                scores.dataset_error, interrupts);
  partitions.write(record.staging().string(), scene.shape());
  return scores;
}

/// The run's last lines on stderr: the error rates (with GT), then the common end.
void report_end(const examples::StereoCommand& command, const Summary& summary,
                const RunScores& scores, const examples::InterruptWatch& interrupts) {
  if (!scores.dataset_error.empty() && !command.quiet)
    std::fprintf(stderr, "c2f-stereo: %s\n", scores.dataset_error.c_str());
  if (scores.rates && !command.quiet)
    std::fprintf(stderr, "c2f-stereo: %s\n", scores.rates->brief().c_str());
  examples::print_run_end("c2f-stereo", summary, interrupts, command.out_dir, command.quiet);
}

}  // namespace

int main(int argc, char** argv) {
  // Ctrl-C or SIGTERM: the run stops at its next step and the best labeling is written.
  const examples::InterruptWatch interrupts;
  return examples::run_tool("c2f-stereo", [&] {
    const auto parsed = examples::parse_stereo_command(argc, argv);
    if (!parsed) return 0;
    examples::StereoCommand command = *parsed;

    set_input_memory_limit(command.run.memory->ceiling());  // no input may take more to read
    check_paths(command);
    const StereoScene scene = load_input(command);
    // Outputs are staged and moved into place together at the end: a failed or crashed run
    // leaves an earlier run's files as they were.
    examples::RunRecord record(command.out_dir, kOutputs, command.trace, "c2f-stereo",
                               command.quiet);
    announce(command, scene);
    require_memory_for(command, scene);
    const PreparedStereo problem = prepare(command, scene);
    // The model as UAI, staged with the other outputs (it lands only if the run does).
    if (!examples::export_uai(problem.problem.energy, command.export_uai, record, interrupts))
      return interrupts.exit_code();

    LevelPartitionRecorder partitions(command.save_partitions);
    const StereoRunReport run = solve(command, scene, problem, record, partitions, interrupts);

    const RunScores scores =
        write_outputs(record, command, scene, problem, partitions, run, interrupts);
    record.commit();
    report_end(command, run.run.summary, scores, interrupts);
    return interrupts.exit_code();
  });
}

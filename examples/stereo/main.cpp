// c2f-stereo: TSGO stereo matching, flat or coarse to fine. Parses, calls the library, writes.

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <opencv2/imgproc.hpp>

#include "c2f/c2f.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/evaluation.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"
#include "stereo_options.hpp"

using namespace c2f;
using namespace c2f::vision;
using Clock = std::chrono::steady_clock;

namespace {

double seconds_since(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

StereoScene load_input(const examples::StereoCommand& command) {
  StereoScene scene;
  if (!command.scene.empty()) {
    try {
      return load_named_scene(command.data, command.scene);
    } catch (const std::invalid_argument& error) {
      throw std::invalid_argument(std::string("--scene: ") + error.what());
    }
  }
  scene.name = std::filesystem::path(command.left).stem().string();
  scene.left = load_colour_image(command.left);
  scene.right = load_colour_image(command.right);
  if (scene.left.size() != scene.right.size()) {
    throw std::invalid_argument(
        "LEFT is " + std::to_string(scene.left.cols) + "x" + std::to_string(scene.left.rows) +
        ", RIGHT is " + std::to_string(scene.right.cols) + "x" + std::to_string(scene.right.rows) +
        ": the views must have one size");
  }
  scene.nonoccluded_source = "none";
  if (!command.gt.empty()) {
    scene.gt = load_gt_disparity(command.gt, command.gt_divisor);
    if (scene.gt.size() != scene.left.size()) {
      throw std::invalid_argument("--gt: '" + command.gt + "' is " + std::to_string(scene.gt.cols) +
                                  "x" + std::to_string(scene.gt.rows) + ", the views are " +
                                  std::to_string(scene.left.cols) + "x" +
                                  std::to_string(scene.left.rows));
    }
    if (!command.mask.empty()) {
      scene.nonoccluded = load_mask(command.mask);
      scene.nonoccluded_source = "official mask";
    } else if (!command.gt_right.empty()) {
      scene.nonoccluded =
          left_right_nonoccluded(scene.gt, load_gt_disparity(command.gt_right, command.gt_divisor));
      scene.nonoccluded_source = "left-right check";
    }
    if (!scene.nonoccluded.empty() && scene.nonoccluded.size() != scene.gt.size()) {
      throw std::invalid_argument("the non-occluded mask does not have the views' size");
    }
  }
  return scene;
}

void downscale(StereoScene& scene, int factor) {
  if (factor == 1) return;
  const cv::Size size(scene.left.cols / factor, scene.left.rows / factor);
  if (size.width < 2 || size.height < 2)
    throw std::invalid_argument("--downscale: the images would be too small");
  cv::resize(scene.left, scene.left, size, 0, 0, cv::INTER_AREA);
  cv::resize(scene.right, scene.right, size, 0, 0, cv::INTER_AREA);
  if (!scene.gt.empty()) {
    cv::resize(scene.gt, scene.gt, size, 0, 0, cv::INTER_NEAREST);
    scene.gt /= factor;
  }
  if (!scene.nonoccluded.empty())
    cv::resize(scene.nonoccluded, scene.nonoccluded, size, 0, 0, cv::INTER_NEAREST);
}

/// Progress on stderr: every level start, then at most every two seconds.
class ProgressPrinter {
 public:
  explicit ProgressPrinter(bool quiet) : quiet_(quiet) {}
  ObserverDecision operator()(const StepEvent& event) {
    if (quiet_) return ObserverDecision::continue_run;
    const auto now = Clock::now();
    if (event.step == 0 || now - last_ > std::chrono::seconds(2)) {
      std::fprintf(stderr,
                   "c2f-stereo: level %d (%s, %zu variables) step %ld energy %.4f at %.2f s\n",
                   event.level, event.at_original ? "original" : "lifted", event.num_variables,
                   event.step, event.energy, event.time_s);
      last_ = now;
    }
    return ObserverDecision::continue_run;
  }

 private:
  bool quiet_;
  Clock::time_point last_ = Clock::now();
};

template <class Solver>
Summary solve(const PairwiseEnergy& energy, ScheduleProvider& provider, Solver solver,
              const Options& options, const Observer& observer) {
  return coarse_to_fine(energy, provider, solver, options, observer);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    const auto parsed = examples::parse_stereo_command(argc, argv);
    if (!parsed) return 0;
    const examples::StereoCommand& command = *parsed;
    StereoScene scene = load_input(command);
    downscale(scene, command.downscale);
    std::filesystem::create_directories(command.out_dir);
    const std::filesystem::path out(command.out_dir);
    const GridShape shape{static_cast<std::size_t>(scene.left.cols),
                          static_cast<std::size_t>(scene.left.rows)};
    if (!command.quiet) {
      std::fprintf(stderr, "c2f-stereo: %s %zux%zu, %d labels, schedule %s, solver %s\n",
                   scene.name.c_str(), shape.width, shape.height, command.tsgo.labels,
                   command.schedule.to_string().c_str(), command.solver.c_str());
    }

    // TSGO step 1: the same for flat and coarse-to-fine runs, reported apart from the MRF clock.
    const auto step1_start = Clock::now();
    TsgoCost cost = tsgo_cost(scene.left, scene.right, command.tsgo);
    const cv::Mat guide = cost.left.clone();
    const PairwiseEnergy energy = tsgo_energy(std::move(cost), command.tsgo);
    const double step1_seconds = seconds_since(step1_start);
    if (!command.quiet)
      std::fprintf(stderr, "c2f-stereo: TSGO step 1 (cost volume) %.2f s\n", step1_seconds);

    ScheduleProvider provider(command.schedule, shape, slic_source(guide),
                              command.allow_non_refining);
    Options options;
    options.plateau_steps = {command.plateau};
    options.plateau_tolerance = command.plateau_tolerance;
    const int sweep = command.solver == "expansion" ? command.tsgo.labels
                      : command.solver == "swap"
                          ? command.tsgo.labels * (command.tsgo.labels - 1) / 2
                          : 4;
    options.plateau_steps_at_original = command.final_plateau > 0 ? command.final_plateau : sweep;
    options.time_limit_seconds = command.time_limit;
    options.max_total_steps = command.max_steps;
    options.level_transfer =
        command.allow_non_refining ? LevelTransfer::majority : LevelTransfer::exact;

    std::ofstream trace_file = open_trace_file(command.trace);
    const bool with_gt = !scene.gt.empty();
    TraceWriter trace(
        trace_file, with_gt ? TraceWriter::ErrorFunction([&](std::span<const Label> ground) {
          const BadPixelRates rates =
              bad_pixel_rates(labels_to_disparity(ground, shape), scene.gt, scene.nonoccluded);
          return scene.nonoccluded.empty() ? rates.all[1] : rates.nonoccluded[1];
        })
                            : TraceWriter::ErrorFunction{});
    std::vector<DensePartition> partitions;
    const Observer observer = observe_all(
        {std::ref(trace), ProgressPrinter(command.quiet), [&](const StepEvent& event) {
           if (command.save_partitions && event.step == 0 && !event.at_original) {
             std::vector<std::int64_t> ids(event.group_of.begin(), event.group_of.end());
             partitions.push_back(DensePartition::from_ids(ids));
           }
           return ObserverDecision::continue_run;
         }});
    Summary summary;
    if (command.solver == "expansion") {
      summary = solve(energy, provider, ExpansionSolver<>(ExpansionOptions{command.label_order}),
                      options, observer);
    } else if (command.solver == "swap") {
      summary = solve(energy, provider, SwapSolver<>(SwapOptions{command.label_order}), options,
                      observer);
    } else {
      summary = solve(energy, provider, LbpSolver(), options, observer);
    }

    const cv::Mat disparity = labels_to_disparity(summary.labeling, shape);
    write_pfm((out / "disparity.pfm").string(), disparity);
    write_disparity_png16((out / "disparity.png").string(), disparity);
    write_image((out / "disparity-colour.png").string(),
                colourise_disparity(disparity, command.tsgo.labels - 1));
    std::ofstream report((out / "summary.txt").string());
    report << "scene " << scene.name << " " << shape.width << "x" << shape.height << ", "
           << command.tsgo.labels << " labels\nschedule " << command.schedule.to_string()
           << ", solver " << command.solver << "\n"
           << "TSGO step 1: " << step1_seconds
           << " s (not on the run clock, same for every schedule)\n";
    for (const LevelReport& level : provider.reports()) {
      report << "partition " << level.level << ": " << level.num_groups << " groups in "
             << level.seconds << " s\n";
    }
    report << summary.report() << "observer (trace error, progress): " << summary.observer_seconds
           << " s off the run clock\n";
    if (with_gt) {
      const BadPixelRates rates = bad_pixel_rates(disparity, scene.gt, scene.nonoccluded);
      write_image((out / "error.png").string(), error_map(disparity, scene.gt, scene.nonoccluded));
      report << rates.brief() << "\nnon-occluded pixels from: " << scene.nonoccluded_source
             << "\nreference variant (bad>1 over all pixels): " << 100 * rates.reference_variant
             << "%\n";
      if (!command.quiet) std::fprintf(stderr, "c2f-stereo: %s\n", rates.brief().c_str());
    }
    for (std::size_t i = 0; i < partitions.size(); ++i) {
      write_image((out / ("partition-level" + std::to_string(i) + ".png")).string(),
                  render_largest_groups(partitions[i], shape, 10));
    }
    if (!command.quiet) {
      std::fprintf(stderr,
                   "c2f-stereo: final energy %.4f after %ld steps in %.2f s (%s); wrote %s\n",
                   summary.energy, summary.total_steps, summary.seconds,
                   std::string(to_string(summary.reason)).c_str(), command.out_dir.c_str());
    }
  } catch (const std::invalid_argument& error) {
    std::cerr << "c2f-stereo: error: " << error.what() << "\n";
    return 2;
  } catch (const std::exception& error) {
    std::cerr << "c2f-stereo: error: " << error.what() << "\n";
    return 1;
  }
  return 0;
}

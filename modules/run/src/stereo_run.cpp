#include "c2f/run/stereo_run.hpp"

#include <chrono>

#include "c2f/run/memory_plan.hpp"
#include "c2f/run/run.hpp"
#include "c2f/support/parallel_for.hpp"
#include "c2f/vision/superpixels.hpp"

namespace c2f::vision {

std::optional<std::size_t> stereo_memory_need(GridShape shape, const TsgoOptions& tsgo,
                                              const SolverSpec& solver) {
  return grid_run_memory_need(
      solver, shape.width, shape.height, tsgo.labels, CostStorage::single_precision,
      tsgo_memory_estimate(shape.width, shape.height, tsgo.labels, tsgo.threads));
}

RunDefaults stereo_defaults() {
  RunDefaults defaults;
  defaults.grid_schedule = defaults.general_schedule = "aggregated";
  defaults.near_radius = 5;
  defaults.shift_moves = true;
  return defaults;
}

PreparedStereo prepare_stereo(const StereoScene& scene, const TsgoOptions& tsgo) {
  const auto start = std::chrono::steady_clock::now();
  TsgoProblem problem = tsgo_problem(scene.left, scene.right, tsgo);
  const std::chrono::duration<double> seconds = std::chrono::steady_clock::now() - start;
  return {std::move(problem), seconds.count(), resolved_threads(tsgo.threads)};
}

StereoRunReport run_stereo(const TsgoProblem& problem, const Schedule& schedule,
                           const RunConfig& config, const Observer& observer) {
  const GridShape shape{static_cast<std::size_t>(problem.guide.cols),
                        static_cast<std::size_t>(problem.guide.rows)};
  ScheduleProvider levels(schedule, shape, slic_source(problem.guide));
  RunReport report = run(problem.energy, levels, config, observer);
  return {std::move(report), levels.reports()};
}

}  // namespace c2f::vision

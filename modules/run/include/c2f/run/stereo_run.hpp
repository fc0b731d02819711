#pragma once
// The stereo application's recipe, scene -> report in two steps: prepare_stereo builds the TSGO
// energy of a scene (timed apart from the run clock: it is the same for every schedule), and
// run_stereo minimises it over a stereo schedule's levels (slic levels segment the energy's guide
// image) with the run layer, within one memory budget. c2f-stereo and the stereo bench use both;
// the bench prepares a scene once for all its schedules.

#include <cstddef>
#include <optional>
#include <vector>

#include "c2f/core/grid.hpp"
#include "c2f/driver/observer.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/run/defaults.hpp"
#include "c2f/run/run_config.hpp"
#include "c2f/vision/stereo/stereo_scene.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"

namespace c2f::vision {

/// What a stereo run of `solver` on a scene of `shape` needs before anything is built: the
/// larger of TSGO step 1's peak (tsgo_memory_estimate with tsgo's labels and threads) and the
/// run's floor on the TSGO energy (float unaries). std::nullopt when either overflows. Give it
/// to MemoryBudget::require.
[[nodiscard]] std::optional<std::size_t> stereo_memory_need(GridShape shape,
                                                            const TsgoOptions& tsgo,
                                                            const SolverSpec& solver);

/// The stereo application's defaults (c2f-stereo, c2f.stereo): the `aggregated` schedule
/// (connected regions of equal best label of 3x3-summed unaries, solved to convergence, then
/// the original problem) with near moves of radius 5 and shift moves on the original problem:
/// measured fastest to flat's final energy from third size to full-size Aloe
/// (docs/results.md).
[[nodiscard]] RunDefaults stereo_defaults();

/// A scene's TSGO problem and what preparing it took.
struct PreparedStereo {
  TsgoProblem problem;
  double seconds = 0.0;  ///< wall time of TSGO steps 1 and 2
  unsigned threads = 1;  ///< the threads they ran on (tsgo.threads resolved)
};

/// TSGO steps 1 and 2 on the scene's views with `tsgo` (tsgo_problem), timed. Throws as
/// tsgo_problem does (std::invalid_argument for views it cannot use).
PreparedStereo prepare_stereo(const StereoScene& scene, const TsgoOptions& tsgo);

/// A stereo run's report: the run layer's, and one line per level of the schedule (its
/// partition and how long building it took).
struct StereoRunReport {
  RunReport run;
  std::vector<LevelReport> levels;
};

/// Minimises problem.energy over `schedule`'s levels (none: flat; slic levels segment
/// problem.guide) as `config` says. Throws as run() does (RunConfigError naming the field).
StereoRunReport run_stereo(const TsgoProblem& problem, const Schedule& schedule,
                           const RunConfig& config, const Observer& observer = {});

}  // namespace c2f::vision

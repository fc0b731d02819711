#include "c2f/run/segmentation_run.hpp"

#include <algorithm>
#include <cmath>

#include "c2f/run/coop_run.hpp"
#include "c2f/run/run.hpp"
#include "c2f/run/run_error.hpp"
#include "c2f/support/enum_names.hpp"
#include "c2f/vision/segmentation/segmentation_schedules.hpp"

namespace c2f::vision {

std::string_view to_string(SegmentationMethod method) {
  return method == SegmentationMethod::coop ? "coop" : "potts";
}

SegmentationMethod segmentation_method_from_string(std::string_view text) {
  constexpr SegmentationMethod kAll[] = {SegmentationMethod::coop, SegmentationMethod::potts};
  return enum_from_string(text, kAll, "method");
}

std::string SegmentationRunConfig::validate() const {
  if (std::string problem = coop.validate(); !problem.empty()) return "coop: " + problem;
  if (plateau < -1) return "plateau: expected -1 (one sweep), 0 (the default) or k > 0";
  if (final_plateau < 0) return "final_plateau: expected >= 0 (0: the solver's convergence)";
  if (!std::isfinite(time_limit_seconds) || time_limit_seconds < 0.0)
    return "time_limit_seconds: expected a finite number >= 0 (0: no limit)";
  if (max_total_steps < 0) return "max_total_steps: expected >= 0 (0: no limit)";
  if (threads < 0) return "threads: expected >= 0 (0: the machine's cores)";
  return {};
}

namespace {

/// The driver's rules for a solver whose sweep is `sweep` steps.
Options limits(const SegmentationRunConfig& config, int num_labels, std::size_t sweep) {
  Options options;
  options.plateau_steps = {config.plateau > 0
                               ? config.plateau
                               : coarse_plateau_steps(sweep, num_labels, config.plateau < 0)};
  options.plateau_steps_at_original = config.final_plateau;
  options.time_limit_seconds = config.time_limit_seconds;
  options.max_total_steps = config.max_total_steps;
  return options;
}

}  // namespace

SegmentationRunConfig SegmentationDefaults::config(AuxStrategy aux) const {
  SegmentationRunConfig config;
  config.method = method;
  config.coop.strategy = aux;
  config.coop.near_radius = near_radius_for(aux);
  return config;
}

SegmentationDefaults segmentation_defaults() {
  SegmentationDefaults defaults;
  defaults.schedule = "superpixels";
  defaults.mm_near_radius = 6;
  return defaults;
}

RunReport run_segmentation(const SegmentationProblem& problem, ScheduleProvider& levels,
                           const SegmentationRunConfig& config, const Observer& observer) {
  RunConfigError::throw_if(config.validate());
  const int num_labels = problem.coop.num_labels();
  if (config.method == SegmentationMethod::potts) {
    RunConfig run_config;
    std::get<ExpansionOptions>(run_config.solver.original).threads = config.threads;
    run_config.memory = config.memory;
    run_config.energy_name = "the Potts energy";
    run_config.limits = limits(config, num_labels, sweep_steps(run_config.solver, problem.potts));
    return run(problem.potts, levels, run_config, observer);
  }
  // The cooperative energy, with the Potts one kept beside it.
  CoopRunConfig run_config;
  run_config.solver = config.coop;
  run_config.solver.threads = config.threads;
  if (config.coop.near_radius > 0) {
    // Near moves on the original problem only; any coarse level is smaller.
    run_config.solver.near_moves_min_variables =
        std::max(config.coop.near_moves_min_variables, problem.coop.num_variables());
  }
  run_config.memory = config.memory;
  run_config.kept_bytes = energy_memory_bytes(problem.potts);
  run_config.limits = limits(config, num_labels, sweep_steps(config.coop, problem.coop));
  return run(problem.coop, levels, run_config, observer);
}

}  // namespace c2f::vision

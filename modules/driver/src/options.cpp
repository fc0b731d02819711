#include "c2f/driver/options.hpp"
#include "c2f/support/enum_names.hpp"

#include <cmath>
#include <stdexcept>

namespace c2f {

std::string_view to_string(InitialLabeling init) {
  switch (init) {
    case InitialLabeling::unary_argmin:
      return "unary_argmin";
    case InitialLabeling::zero:
      return "zero";
  }
  return "unknown";
}

InitialLabeling initial_labeling_from_string(std::string_view text) {
  constexpr InitialLabeling kAll[] = {InitialLabeling::unary_argmin, InitialLabeling::zero};
  return enum_from_string(text, kAll, "initial labeling");
}

std::string Options::validate() const {
  for (std::size_t i = 0; i < plateau_steps.size(); ++i) {
    if (plateau_steps[i] < 1) {
      return "plateau_steps[" + std::to_string(i) + "] must be >= 1, got " +
             std::to_string(plateau_steps[i]);
    }
  }
  if (plateau_steps_at_original < 0)
    return "plateau_steps_at_original must be >= 0 (0: plateau_steps applies)";
  if (!std::isfinite(plateau_tolerance) || plateau_tolerance < 0.0) {
    return "plateau_tolerance must be finite and >= 0";
  }
  if (!std::isfinite(plateau_tolerance_at_original) || plateau_tolerance_at_original < 0.0) {
    return "plateau_tolerance_at_original must be finite and >= 0";
  }
  if (max_steps_per_level < 0) return "max_steps_per_level must be >= 0 (0: no limit)";
  if (progress_sweep_steps < 0)
    return "progress_sweep_steps must be >= 0 (0: no progress-rate rule)";
  if (max_total_steps < 0) return "max_total_steps must be >= 0 (0: no limit)";
  if (!std::isfinite(time_limit_seconds) || time_limit_seconds < 0.0) {
    return "time_limit_seconds must be finite and >= 0 (0: no limit)";
  }
  if (target_energy && !std::isfinite(*target_energy)) return "target_energy must be finite";
  for (std::size_t i = 0; i < extra_rules.size(); ++i) {
    if (!extra_rules[i]) return "extra_rules[" + std::to_string(i) + "] is empty";
  }
  if (plateau_steps.empty() && max_steps_per_level == 0) {
    return "no rule ends a level: set plateau_steps or max_steps_per_level";
  }
  return {};
}

Rules Options::rules() const {
  if (const std::string problem = validate(); !problem.empty()) {
    throw std::invalid_argument("coarse-to-fine options: " + problem);
  }
  Rules rules;
  if (!plateau_steps.empty()) {
    rules.add(no_decrease(plateau_steps, plateau_tolerance, plateau_steps_at_original,
                          plateau_tolerance_at_original));
  } else if (plateau_steps_at_original > 0) {
    rules.add(no_decrease({plateau_steps_at_original}, plateau_tolerance, 0,
                          plateau_tolerance_at_original));
  }
  if (progress_sweep_steps > 0)
    rules.add(progress_rate({progress_sweep_steps}, next_level_gain));
  if (max_steps_per_level > 0) rules.add(level_step_limit(max_steps_per_level));
  if (max_total_steps > 0) rules.add(total_step_limit(max_total_steps));
  if (time_limit_seconds > 0.0) rules.add(time_limit(time_limit_seconds));
  if (target_energy) rules.add(c2f::target_energy(*target_energy));
  for (const Rule& rule : extra_rules) rules.add(rule);
  return rules;
}

}  // namespace c2f

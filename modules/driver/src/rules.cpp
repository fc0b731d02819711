#include "c2f/driver/rules.hpp"
#include "c2f/support/enum_names.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

namespace c2f {

namespace {

/// Steps over which progress_rate measures a level's current progress per unit of work.
constexpr std::size_t kProgressRateWindow = 4;

}  // namespace

std::string_view to_string(TerminationReason reason) {
  switch (reason) {
    case TerminationReason::converged:
      return "converged";
    case TerminationReason::step_limit:
      return "step_limit";
    case TerminationReason::time_limit:
      return "time_limit";
    case TerminationReason::target_energy:
      return "target_energy";
    case TerminationReason::observer:
      return "observer";
  }
  return "unknown";
}

TerminationReason termination_reason_from_string(std::string_view text) {
  constexpr TerminationReason kAll[] = {
      TerminationReason::converged, TerminationReason::step_limit, TerminationReason::time_limit,
      TerminationReason::target_energy, TerminationReason::observer};
  return enum_from_string(text, kAll, "termination reason");
}

Rule no_decrease(std::vector<int> steps_per_level, double tolerance, int steps_at_original,
                 double tolerance_at_original) {
  if (steps_at_original < 0)
    throw std::invalid_argument("no_decrease: steps_at_original must be >= 0");
  if (steps_per_level.empty()) {
    throw std::invalid_argument("no_decrease: steps_per_level is empty");
  }
  for (int k : steps_per_level) {
    if (k < 1)
      throw std::invalid_argument("no_decrease: every k must be >= 1, got " + std::to_string(k));
  }
  if (!std::isfinite(tolerance) || tolerance < 0.0) {
    throw std::invalid_argument("no_decrease: tolerance must be finite and >= 0");
  }
  if (!std::isfinite(tolerance_at_original) || tolerance_at_original < 0.0) {
    throw std::invalid_argument("no_decrease: tolerance_at_original must be finite and >= 0");
  }
  return [ks = std::move(steps_per_level), tolerance, steps_at_original,
          tolerance_at_original](const StepEvent& p) -> Verdict {
    const auto index = std::min<std::size_t>(static_cast<std::size_t>(p.level), ks.size() - 1);
    const auto k = static_cast<std::size_t>(
        p.at_original && steps_at_original > 0 ? steps_at_original : ks[index]);
    const auto& history = p.level_energies;
    if (history.size() < k + 1) return {};
    const double before = history[history.size() - 1 - k];
    const double now = history.back();
    const double margin =
        (p.at_original ? tolerance_at_original : tolerance) * std::max(1.0, std::abs(before));
    if (before - now > margin) return {};
    return {Decision::refine, TerminationReason::converged};
  };
}

Rule progress_rate(std::vector<int> sweep_per_level, NextLevelGain next_gain) {
  if (sweep_per_level.empty()) throw std::invalid_argument("progress_rate: no sweep length");
  for (int k : sweep_per_level) {
    if (k < 1) {
      throw std::invalid_argument("progress_rate: every sweep must be >= 1 step, got " +
                                  std::to_string(k));
    }
  }
  // Of the level being solved (rules see every step, from 0): the work done by each step, the
  // next level's expected decrease per unit of work once the first sweep is done, and scratch
  // for the labeling.
  struct LevelState {
    std::vector<double> work;
    std::optional<double> expected_next;
    Labeling ground;
  };
  return [ks = std::move(sweep_per_level), next_gain = std::move(next_gain),
          level = LevelState{}](const StepEvent& p) mutable -> Verdict {
    if (p.at_original || p.group_of.empty()) return {};
    if (p.step == 0) {
      level.work.assign(1, 0.0);
      level.expected_next.reset();
    } else {
      level.work.push_back(level.work.back() + static_cast<double>(p.step_variables));
    }
    const auto index = std::min<std::size_t>(static_cast<std::size_t>(p.level), ks.size() - 1);
    const auto k = static_cast<std::size_t>(ks[index]);
    const auto& energies = p.level_energies;
    const std::size_t now = energies.size() - 1;
    if (now < k || level.work.size() != energies.size()) return {};
    if (!level.expected_next) {
      const double gain =
          next_gain ? next_gain(p.ground_labeling(level.ground)) : energies[0] - energies[k];
      const double next_work = level.work[k] * static_cast<double>(p.group_of.size()) /
                               static_cast<double>(p.num_variables);
      level.expected_next = next_work > 0.0 ? std::max(0.0, gain) / next_work : 0.0;
    }
    const std::size_t window = std::min<std::size_t>(kProgressRateWindow, k);
    const double work = level.work[now] - level.work[now - window];
    const double decrease = energies[now - window] - energies[now];
    const double rate = work > 0.0
                            ? decrease / work
                            : (decrease > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
    if (rate > *level.expected_next) return {};
    return {Decision::refine, TerminationReason::converged};
  };
}

Rule level_step_limit(long max_steps) {
  if (max_steps < 1) throw std::invalid_argument("level_step_limit: max_steps must be >= 1");
  return [max_steps](const StepEvent& p) -> Verdict {
    if (p.step >= max_steps) return {Decision::refine, TerminationReason::step_limit};
    return {};
  };
}

Rule total_step_limit(long max_steps) {
  if (max_steps < 1) throw std::invalid_argument("total_step_limit: max_steps must be >= 1");
  return [max_steps](const StepEvent& p) -> Verdict {
    if (p.total_steps >= max_steps) return {Decision::stop, TerminationReason::step_limit};
    return {};
  };
}

Rule time_limit(double seconds) {
  if (!(seconds > 0.0)) throw std::invalid_argument("time_limit: seconds must be > 0");
  return [seconds](const StepEvent& p) -> Verdict {
    if (p.time_s >= seconds) return {Decision::stop, TerminationReason::time_limit};
    return {};
  };
}

Rule target_energy(double target) {
  if (!std::isfinite(target)) throw std::invalid_argument("target_energy: target must be finite");
  return [target](const StepEvent& p) -> Verdict {
    if (!p.level_energies.empty() && p.level_energies.back() <= target) {
      return {Decision::stop, TerminationReason::target_energy};
    }
    return {};
  };
}

Rules& Rules::add(Rule rule) {
  if (!rule) throw std::invalid_argument("Rules::add: empty rule");
  rules_.push_back(std::move(rule));
  return *this;
}

Verdict Rules::decide(const StepEvent& event) const {
  Verdict strongest;
  for (const Rule& rule : rules_) {
    const Verdict verdict = rule(event);
    if (static_cast<int>(verdict.decision) > static_cast<int>(strongest.decision))
      strongest = verdict;
  }
  return strongest;
}

}  // namespace c2f

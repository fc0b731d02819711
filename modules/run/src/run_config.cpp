#include "c2f/run/run_config.hpp"

#include "c2f/support/memory_need.hpp"

namespace c2f {

MemoryBudget budget_or_default(const std::optional<MemoryBudget>& memory) {
  return memory ? *memory : default_memory_budget();
}

std::string validate_limits_and_memory(const Options& limits,
                                       const std::optional<MemoryBudget>& memory) {
  if (std::string problem = limits.validate(); !problem.empty()) return "limits: " + problem;
  if (limits.coarse_level_fits)
    return "limits: coarse_level_fits is the run layer's to set (from the memory budget)";
  if (memory && memory->bytes == 0) return "memory: a budget of 0 bytes";
  return {};
}

std::string RunConfig::validate() const {
  if (std::string problem = solver.validate(); !problem.empty()) return "solver." + problem;
  return validate_limits_and_memory(limits, memory);
}

namespace {

/// ", recycled move graphs up to N[, kept move problems M]" for a solver that recycles.
std::string optional_memory_text(const RunReport& report) {
  if (!report.recycles) return {};
  std::string text =
      ", recycled move graphs up to " + format_bytes(static_cast<double>(report.plan.graph_memory));
  if (report.plan.problem_memory > 0)
    text += ", kept move problems " + format_bytes(static_cast<double>(report.plan.problem_memory));
  return text;
}

}  // namespace

std::string RunReport::memory_line() const {
  return "memory budget " + budget.describe() + optional_memory_text(*this);
}

std::string RunReport::memory_report() const {
  std::string line = "memory: budget " + budget.describe() + ", floor " +
                     format_bytes(static_cast<double>(plan.floor)) + optional_memory_text(*this);
  if (recycles)
    line += ", " + format_bytes(static_cast<double>(optional_memory_used)) + " used at the end";
  return line;
}

std::string RunReport::threads_line() const {
  const auto on = [](unsigned threads) {
    return " on " + std::to_string(threads) + (threads == 1 ? " thread" : " threads");
  };
  if (bp_schedule) {
    switch (*bp_schedule) {
      case BpSchedule::sequential:
        return "solve: BP messages in variable order on one thread";
      case BpSchedule::parallel:
        return "solve: BP messages from the previous iteration's" + on(solve_threads);
      case BpSchedule::bands:
        return "solve: BP messages by bands of " + std::to_string(bp_band_variables) +
               " variables" + on(solve_threads);
    }
  }
  const std::string near =
      near_radius <= 0 ? "" : near_moves_text(near_radius, near_seeds, SeedsAs::in_use);
  const std::string shifts = shift_moves ? " with shift moves" : "";
  const std::string flow =
      flow_parts < 2 ? ""
                     : ", max-flow in " + std::to_string(flow_parts) + " parts" + on(flow_threads);
  if (regions < 2) {
    const std::string moves =
        near.empty() ? "every move over every variable" : near + " (whole moves where they stall)";
    return "solve: " + moves + (flow.empty() ? " on one thread" : flow) + shifts;
  }
  return "solve: moves by " + std::to_string(regions) + " regions" + on(solve_threads) + flow +
         (near.empty() ? shifts : " with " + near + (shift_moves ? " and shift moves" : ""));
}

}  // namespace c2f

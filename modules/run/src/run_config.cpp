#include "c2f/run/run_config.hpp"

#include "c2f/support/memory_need.hpp"

namespace c2f {

MemoryBudget budget_or_default(const std::optional<MemoryBudget>& memory) {
  return memory ? *memory : default_memory_budget();
}

std::string RunConfig::validate() const {
  if (std::string problem = solver.validate(); !problem.empty()) return "solver." + problem;
  if (std::string problem = limits.validate(); !problem.empty()) return "limits: " + problem;
  if (limits.coarse_level_fits)
    return "limits: coarse_level_fits is the run layer's to set (from the memory budget)";
  if (memory && memory->bytes == 0) return "memory: a budget of 0 bytes";
  return {};
}

std::string RunReport::memory_line() const {
  std::string line = "memory budget " + budget.describe();
  if (recycles) {
    line += ", recycled move graphs up to " + format_bytes(static_cast<double>(plan.graph_memory));
  }
  return line;
}

std::string RunReport::memory_report() const {
  std::string line = "memory: budget " + budget.describe() + ", floor " +
                     format_bytes(static_cast<double>(plan.floor));
  if (recycles) {
    line += ", recycled move graphs up to " + format_bytes(static_cast<double>(plan.graph_memory)) +
            ", " + format_bytes(static_cast<double>(graph_memory_used)) + " used at the end";
  }
  return line;
}

}  // namespace c2f

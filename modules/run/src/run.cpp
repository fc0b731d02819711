#include "c2f/run/run.hpp"

#include <algorithm>

#include "c2f/support/parallel_for.hpp"

namespace c2f {

namespace detail {

unsigned solve_threads(const SolverOptions& options, std::size_t regions) {
  const auto* expansion = std::get_if<ExpansionOptions>(&options);
  if (expansion == nullptr || regions < 2) return 1;
  return static_cast<unsigned>(
      std::min<std::size_t>(resolved_threads(expansion->threads), (regions + 1) / 2));
}

}  // namespace detail

MemoryPlan plan_run(const PairwiseEnergy& energy, const RunConfig& config) {
  RunConfigError::throw_if(config.validate());
  try {
    return plan_memory(config.solver, problem_size(energy), budget_or_default(config.memory),
                       config.graph_memory, config.energy_name);
  } catch (const std::invalid_argument& error) {
    throw RunConfigError("memory", error.what());
  }
}

std::size_t sweep_steps(const SolverSpec& spec, const PairwiseEnergy& energy) {
  if (const std::string problem = spec.validate(); !problem.empty())
    RunConfigError::throw_if("solver." + problem);
  return std::visit(
      [&]<class Options>(const Options& options) -> std::size_t {
        const typename detail::SolverFor<Options, DynamicMaxFlow>::type solver(options);
        return solver.quiet_steps_to_converge(energy);
      },
      spec.original);
}

}  // namespace c2f

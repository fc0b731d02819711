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

int partition_threads(const SolverOptions& options) {
  if (const auto* expansion = std::get_if<ExpansionOptions>(&options)) return expansion->threads;
  if (const auto* lbp = std::get_if<LbpOptions>(&options)) return lbp->threads;
  return 1;
}

unsigned threads_on_parts(int threads, std::size_t parts) {
  if (parts < 2) return 1;
  return static_cast<unsigned>(std::min<std::size_t>(resolved_threads(threads), parts));
}

unsigned flow_threads(const SolverOptions& options, std::size_t parts) {
  const auto* expansion = std::get_if<ExpansionOptions>(&options);
  return expansion == nullptr ? 1 : threads_on_parts(expansion->threads, parts);
}

SolverSpec with_moves_decided(SolverSpec spec, const PairwiseEnergy& energy) {
  const auto decide = [&energy](SolverOptions& options) {
    if (auto* expansion = std::get_if<ExpansionOptions>(&options)) {
      expansion->near_seeds = near_seeds_in_use(*expansion, energy);  // before shifts are fixed
      expansion->shift_moves = makes_shift_moves(*expansion, energy);
      expansion->shift_moves_unless_submodular = false;
      if (!makes_near_moves(*expansion, energy)) expansion->near_radius = 0;
      expansion->near_moves_only_if_local = false;
      expansion->near_moves_min_variables = 0;
    }
  };
  decide(spec.original);
  if (spec.coarse) decide(*spec.coarse);
  return spec;
}

}  // namespace detail

MemoryPlan plan_run(const PairwiseEnergy& energy, const RunConfig& config) {
  RunConfigError::throw_if(config.validate());
  try {
    return plan_memory(detail::with_moves_decided(config.solver, energy), problem_size(energy),
                       budget_or_default(config.memory), config.graph_memory, config.energy_name);
  } catch (const std::invalid_argument& error) {
    throw RunConfigError("memory", error.what());
  }
}

namespace {

/// quiet_steps_to_converge on `energy` of the solver `options` name (one sweep of its moves).
std::size_t quiet_steps(const SolverSpec& spec, const SolverOptions& options,
                        const PairwiseEnergy& energy) {
  if (const std::string problem = spec.validate(); !problem.empty())
    RunConfigError::throw_if("solver." + problem);
  return std::visit(
      [&]<class Options>(const Options& o) -> std::size_t {
        const typename detail::SolverFor<Options, DynamicMaxFlow>::type solver(o);
        return solver.quiet_steps_to_converge(energy);
      },
      options);
}

}  // namespace

std::size_t sweep_steps(const SolverSpec& spec, const PairwiseEnergy& energy) {
  return quiet_steps(spec, spec.original, energy);
}

std::size_t coarse_sweep_steps(const SolverSpec& spec, const PairwiseEnergy& energy) {
  return quiet_steps(spec, spec.coarse_options(), energy);
}

}  // namespace c2f

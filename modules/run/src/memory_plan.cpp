#include "c2f/run/memory_plan.hpp"

#include <algorithm>

#include "c2f/support/memory_need.hpp"

namespace c2f {

namespace {

constexpr std::size_t kProcessBytes = std::size_t{128} << 20;
constexpr std::size_t kPerVariableBytes = 64;
constexpr std::size_t kUnlimited = static_cast<std::size_t>(-1);

/// The move problems a level of `size` keeps within `limit` (expansion: all of them or none).
std::size_t kept_problems(const SolverOptions& options, const ProblemSize& size,
                          std::size_t limit) {
  const auto* expansion = std::get_if<ExpansionOptions>(&options);
  if (expansion == nullptr) return 0;
  const std::optional<std::size_t> bytes = kept_problem_bytes(*expansion, size);
  return bytes && *bytes <= limit ? *bytes : 0;
}

/// The recycled graphs a level of `size` would keep with no limit (expansion: one per label;
/// swap: one per pair of labels); 0 for solvers that keep none.
std::optional<std::size_t> wanted_graphs(const SolverOptions& options, MaxFlowKind maxflow,
                                         const ProblemSize& size) {
  return std::visit(
      [&]<class Options>(const Options& o) -> std::optional<std::size_t> {
        if constexpr (std::is_base_of_v<MoveOptions, Options>) {
          return wanted_graph_bytes(o, size, graph_storage(maxflow));
        } else {
          return std::size_t{0};
        }
      },
      options);
}

}  // namespace

std::optional<std::size_t> working_memory_bytes(const SolverOptions& options, MaxFlowKind maxflow,
                                                const ProblemSize& size) {
  return std::visit(
      [&]<class Options>(const Options& o) -> std::optional<std::size_t> {
        if constexpr (std::is_base_of_v<MoveOptions, Options>) {
          return working_memory_bytes(o, size, graph_storage(maxflow));
        } else {
          return working_memory_bytes(o, size);
        }
      },
      options);
}

std::optional<std::size_t> run_memory_floor(const SolverSpec& spec, const ProblemSize& size) {
  const auto per_variable = checked_product({size.variables, kPerVariableBytes});
  const auto solver = working_memory_bytes(spec.original, spec.maxflow, size);
  if (!per_variable || !solver) return std::nullopt;
  return checked_sum({kProcessBytes, size.energy_bytes, *per_variable, *solver});
}

MemoryPlan plan_memory(const SolverSpec& spec, const ProblemSize& size, const MemoryBudget& budget,
                       std::optional<std::size_t> graph_memory, const std::string& what) {
  const std::optional<std::size_t> floor = run_memory_floor(spec, size);
  budget.require_within(what, floor);
  MemoryPlan plan;
  plan.floor = *floor;
  plan.budget = budget.for_need(*floor);  // a default budget grows to the floor
  const std::size_t above_floor = plan.budget - plan.floor;
  plan.problem_memory = kept_problems(spec.original, size, above_floor);
  plan.graph_memory =
      std::min(graph_memory.value_or(kUnlimited), above_floor - plan.problem_memory);
  // What the budget leaves above the floor, and the original problem's solver's share of the
  // floor: coarse levels run before that solver is built.
  plan.coarse_level_room = above_floor + *working_memory_bytes(spec.original, spec.maxflow, size);
  return plan;
}

SolverSpec with_memory_plan(SolverSpec spec, const MemoryPlan& plan) {
  const auto set = [&plan](SolverOptions& options) {
    std::visit(
        [&plan]<class Options>(Options& o) {
          if constexpr (std::is_base_of_v<MoveOptions, Options>)
            o.graph_memory_limit = plan.graph_memory;
          if constexpr (std::is_same_v<Options, ExpansionOptions>)
            o.problem_memory_limit = plan.problem_memory;
        },
        options);
  };
  set(spec.original);
  if (spec.coarse) set(*spec.coarse);
  return spec;
}

std::optional<std::size_t> coarse_level_memory(const SolverSpec& spec, const ProblemSize& size,
                                               std::size_t groups, std::size_t graph_memory,
                                               std::size_t problem_memory) {
  const ProblemSize level{groups, size.labels, size.edges, 0};
  const auto labels = static_cast<std::size_t>(std::max(size.labels, 0));
  const auto unaries = checked_product({groups, labels, sizeof(double)});
  const auto edges = checked_product({size.edges, sizeof(Edge)});
  const auto solver = working_memory_bytes(spec.coarse_options(), spec.maxflow, level);
  if (!unaries || !edges || !solver) return std::nullopt;
  // Its recycled move graphs: one per move, each at most a solver's working memory, and never
  // more than the limit.
  const auto wanted = wanted_graphs(spec.coarse_options(), spec.maxflow, level);
  const std::size_t graphs = std::min(wanted.value_or(kUnlimited), graph_memory);
  const std::size_t problems = kept_problems(spec.coarse_options(), level, problem_memory);
  return checked_sum({*unaries, *edges, *solver, graphs, problems});
}

CoarseLevelFits coarse_level_admission(const SolverSpec& spec, const ProblemSize& size,
                                       const MemoryPlan& plan) {
  return [spec, size, plan](std::size_t groups) {
    const std::optional<std::size_t> need =
        coarse_level_memory(spec, size, groups, 0, plan.problem_memory);
    return need && *need <= plan.coarse_level_room;
  };
}

std::optional<ProblemSize> grid_problem_size(std::size_t width, std::size_t height, int labels,
                                             CostStorage storage) {
  const auto variables = checked_product({width, height});
  const auto l = static_cast<std::size_t>(std::max(labels, 0));
  const std::size_t cost_bytes =
      storage == CostStorage::single_precision ? sizeof(float) : sizeof(double);
  const auto unaries = variables ? checked_product({*variables, l, cost_bytes}) : variables;
  const auto edge_bytes = variables ? checked_product({*variables, 2, sizeof(Edge)}) : variables;
  const auto table = checked_product({l, l, sizeof(double)});
  if (!unaries || !edge_bytes || !table || *unaries > kUnlimited / 2) return std::nullopt;
  const std::size_t edges = width > 0 && height > 0 ? 2 * *variables - width - height : 0;
  return ProblemSize{*variables, labels, edges, *unaries + *edge_bytes + *table};
}

std::optional<std::size_t> grid_run_memory_need(const SolverSpec& spec, std::size_t width,
                                                std::size_t height, int labels, CostStorage storage,
                                                std::optional<std::size_t> preparation) {
  const std::optional<ProblemSize> size = grid_problem_size(width, height, labels, storage);
  const std::optional<std::size_t> floor = size ? run_memory_floor(spec, *size) : std::nullopt;
  if (!floor || !preparation) return std::nullopt;
  return std::max(*floor, *preparation);
}

}  // namespace c2f

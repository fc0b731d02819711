#include "c2f/adapters/run_memory.hpp"

#include <algorithm>

#include "c2f/core/memory_need.hpp"

namespace c2f {

namespace {

constexpr std::size_t kProcessBytes = std::size_t{128} << 20;
constexpr std::size_t kPerVariableBytes = 64;

/// One graph-cut solver's working memory: per variable and per edge, for the plain and the
/// doubled QPBO graph with their capacities and problems, the move's d and p and its outputs
/// (300 and 240 bytes: a flat Teddy run without recycling peaks at 344 MiB, which this floor
/// puts at 380; Boost's adjacency lists are counted at twice that, 453 MiB against 505).
std::optional<std::size_t> graph_cut_bytes(MaxFlowKind backend, const ProblemSize& size) {
  const std::size_t scale = backend == MaxFlowKind::boost ? 2 : 1;
  const auto nodes = checked_product({size.variables, 300 * scale});
  const auto arcs = checked_product({size.edges, 240 * scale});
  if (!nodes || !arcs) return std::nullopt;
  return *nodes + *arcs;
}

std::optional<std::size_t> solver_bytes(const SolverChoice& choice, const ProblemSize& size) {
  switch (choice.kind) {
    case SolverKind::expansion: {
      const auto one = graph_cut_bytes(choice.maxflow, size);
      const bool second = choice.near_radius > 0 || choice.shift_moves;
      return one ? checked_product({*one, second ? std::size_t{2} : std::size_t{1}}) : one;
    }
    case SolverKind::swap:
      return graph_cut_bytes(choice.maxflow, size);
    case SolverKind::lbp:  // two message arrays of 2 per edge and label, beliefs and scratch
      return checked_product({size.edges * 4 + size.variables * 3,
                              static_cast<std::size_t>(std::max(size.labels, 1)), sizeof(double)});
    case SolverKind::icm:
      return checked_product({size.variables, 16});
  }
  return std::nullopt;
}

}  // namespace

ProblemSize problem_size(const PairwiseEnergy& energy) {
  return {energy.num_variables(), energy.num_labels(), energy.edges().size(),
          energy_memory_bytes(energy)};
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
  if (!unaries || !edge_bytes || !table || *unaries > static_cast<std::size_t>(-1) / 2)
    return std::nullopt;
  const std::size_t edges = width > 0 && height > 0 ? 2 * *variables - width - height : 0;
  return ProblemSize{*variables, labels, edges, *unaries + *edge_bytes + *table};
}

std::optional<std::size_t> run_memory_floor(const SolverChoice& choice, const ProblemSize& size) {
  const auto per_variable = checked_product({size.variables, kPerVariableBytes});
  const auto solver = solver_bytes(choice, size);
  if (!per_variable || !solver) return std::nullopt;
  return checked_sum({kProcessBytes, size.energy_bytes, *per_variable, *solver});
}

std::optional<std::size_t> coarse_level_memory(const SolverChoice& choice, const ProblemSize& size,
                                               std::size_t groups) {
  const SolverChoice coarse = choice.coarse_levels_choice();
  const ProblemSize level{groups, size.labels, size.edges, 0};
  const auto labels = static_cast<std::size_t>(std::max(size.labels, 0));
  const auto unaries = checked_product({groups, labels, sizeof(double)});
  const auto edges = checked_product({size.edges, sizeof(Edge)});
  const auto solver = solver_bytes(coarse, level);
  if (!unaries || !edges || !solver) return std::nullopt;
  // Its recycled move graphs: one per label (expansion) or pair of labels (swap), each at most
  // a solver's working memory, and never more than the limit.
  std::size_t graphs = 0;
  if (choice.kind == SolverKind::expansion || choice.kind == SolverKind::swap) {
    const std::size_t moves =
        choice.kind == SolverKind::expansion ? labels : labels * (labels + 1) / 2;
    const auto one = graph_cut_bytes(choice.maxflow, level);
    const auto all = one ? checked_product({*one, moves}) : one;
    graphs = std::min(all.value_or(static_cast<std::size_t>(-1)), choice.graph_memory_bytes());
  }
  return checked_sum({*unaries, *edges, *solver, graphs});
}

CoarseLevelFits coarse_level_admission(const SolverChoice& choice, const ProblemSize& size) {
  return [choice, size](std::size_t groups) {
    const std::optional<std::size_t> need = coarse_level_memory(choice, size, groups);
    return need && *need <= choice.coarse_level_room;
  };
}

std::optional<std::size_t> grid_run_memory_need(const SolverChoice& choice, std::size_t width,
                                                std::size_t height, int labels, CostStorage storage,
                                                std::optional<std::size_t> preparation) {
  const std::optional<ProblemSize> size = grid_problem_size(width, height, labels, storage);
  const std::optional<std::size_t> floor = size ? run_memory_floor(choice, *size) : std::nullopt;
  if (!floor || !preparation) return std::nullopt;
  return std::max(*floor, *preparation);
}

SolverChoice fit_to_budget(SolverChoice choice, const ProblemSize& size, const MemoryBudget& budget,
                           const std::string& what) {
  const std::optional<std::size_t> floor = run_memory_floor(choice, size);
  budget.require_within(what, floor);
  // A default budget grows to the floor when that is more.
  const std::size_t bytes = budget.for_need(*floor);
  choice.graph_memory_limit =
      std::min(choice.graph_memory_limit.value_or(static_cast<std::size_t>(-1)), bytes - *floor);
  // What the budget leaves above the floor, and the original problem's solver's share of the
  // floor: coarse levels run before that solver is built.
  choice.coarse_level_room = bytes - *floor + *solver_bytes(choice, size);
  return choice;
}

}  // namespace c2f

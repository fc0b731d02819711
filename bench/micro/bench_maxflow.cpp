// Max-flow backends on 4-connected grids (64x64, 512x512, 1024x1024): building the graph once
// and solving it (capacities reset each time, every solve from zero flow) are measured
// separately, and so are re-solves after changing 1% or 10% of the nodes' terminal capacities
// (the graph alternates between two capacity sets; DynamicMaxFlow changes what differs and
// resumes from its flow, resolve_with, the others solve from zero), and DynamicMaxFlow's solves
// and re-solves in parts (bands of rows) on 1 and 2 threads. The problem is a segmentation-like
// cut: terminal capacities from a smooth random field plus noise, neighbour capacities 1.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/maxflow/boost_maxflow.hpp"
#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#include "c2f/core/grid.hpp"
#include "support/stereo_sized_energy.hpp"
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
#include "c2f/adapters/maxflow/kolmogorov_maxflow.hpp"
#endif

namespace {

using namespace c2f;

struct GridFlow {
  std::size_t nodes;
  std::vector<FlowEdge> edges;
  FlowCapacities caps;
  FlowCapacities changed_1, changed_10;  ///< caps with 1% / 10% of the terminal pairs redrawn
};

FlowCapacities with_changed_terminals(const FlowCapacities& caps, double share,
                                      std::uint64_t seed) {
  FlowCapacities changed = caps;
  std::mt19937_64 rng(seed);
  std::bernoulli_distribution pick(share);
  std::normal_distribution<double> field(0.0, 3.0);
  for (std::size_t i = 0; i < changed.source.size(); ++i) {
    if (!pick(rng)) continue;
    const double value = field(rng);
    changed.source[i] = std::max(value, 0.0);
    changed.sink[i] = std::max(-value, 0.0);
  }
  return changed;
}

const GridFlow& grid_flow(std::size_t side) {
  static std::map<std::size_t, GridFlow> cache;
  auto [it, inserted] = cache.try_emplace(side);
  if (!inserted) return it->second;
  GridFlow& flow = it->second;
  flow.nodes = side * side;
  for (const auto& [u, v] : grid_neighbour_pairs({side, side}, Connectivity::four))
    flow.edges.push_back({u, v});
  flow.caps.resize(flow.nodes, flow.edges.size());
  std::mt19937_64 rng(side);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (std::size_t y = 0; y < side; ++y) {
    for (std::size_t x = 0; x < side; ++x) {
      const double field = std::sin(6.0 * x / side) * std::cos(5.0 * y / side) * 3.0 + noise(rng);
      flow.caps.source[y * side + x] = std::max(field, 0.0);
      flow.caps.sink[y * side + x] = std::max(-field, 0.0);
    }
  }
  std::fill(flow.caps.forward.begin(), flow.caps.forward.end(), 1.0);
  std::fill(flow.caps.backward.begin(), flow.caps.backward.end(), 1.0);
  flow.changed_1 = with_changed_terminals(flow.caps, 0.01, side + 1);
  flow.changed_10 = with_changed_terminals(flow.caps, 0.10, side + 2);
  return flow;
}

template <class Backend>
void BM_Build(benchmark::State& state) {
  const GridFlow& flow = grid_flow(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) {
    Backend backend;
    backend.build(flow.nodes, flow.edges);
    benchmark::DoNotOptimize(backend);
  }
}

template <class Backend>
void BM_Solve(benchmark::State& state) {
  const GridFlow& flow = grid_flow(static_cast<std::size_t>(state.range(0)));
  Backend backend;
  backend.build(flow.nodes, flow.edges);
  double value = 0.0;
  for (auto _ : state) benchmark::DoNotOptimize(value = backend.solve(flow.caps));
  state.counters["flow"] = value;
}

/// Node i's part when n nodes are cut into `parts` bands of consecutive indices (of rows).
std::vector<std::uint8_t> row_bands(std::size_t n, std::size_t parts) {
  std::vector<std::uint8_t> part(n);
  for (std::size_t i = 0; i < n; ++i) part[i] = static_cast<std::uint8_t>(i * parts / n);
  return part;
}

/// DynamicMaxFlow::solve_cut_in_parts in state.range(1) bands of rows on state.range(2) threads
/// (one band: the serial solve_cut).
void BM_SolveInParts(benchmark::State& state) {
  const GridFlow& flow = grid_flow(static_cast<std::size_t>(state.range(0)));
  const std::vector<std::uint8_t> part =
      row_bands(flow.nodes, static_cast<std::size_t>(state.range(1)));
  DynamicMaxFlow backend;
  backend.build(flow.nodes, flow.edges);
  backend.cut_into_parts(part);
  for (auto _ : state) backend.solve_cut_in_parts(flow.caps, static_cast<int>(state.range(2)));
  state.counters["augmentations"] = static_cast<double>(backend.last_solve().augmentations);
}

/// BM_Resolve's re-solves (1024 x 1024, state.range(0)% of the terminal pairs changed) by
/// DynamicMaxFlow::resolve_in_parts in state.range(1) bands of rows on state.range(2) threads.
void BM_ResolveInParts(benchmark::State& state) {
  const GridFlow& flow = grid_flow(1024);
  const FlowCapacities& changed = state.range(0) == 1 ? flow.changed_1 : flow.changed_10;
  const std::vector<std::uint8_t> part =
      row_bands(flow.nodes, static_cast<std::size_t>(state.range(1)));
  DynamicMaxFlow backend;
  backend.build(flow.nodes, flow.edges);
  backend.cut_into_parts(part);
  backend.solve(flow.caps);
  bool use_changed = true;
  for (auto _ : state) {
    const FlowCapacities& before = use_changed ? flow.caps : changed;
    const FlowCapacities& after = use_changed ? changed : flow.caps;
    apply_capacity_changes(backend, before, after);
    backend.resolve_in_parts(static_cast<int>(state.range(2)));
    use_changed = !use_changed;
  }
}

/// One re-solve per iteration, alternating between the base capacities and a copy with
/// state.range(1)% of the terminal pairs changed.
template <class Backend>
void BM_Resolve(benchmark::State& state) {
  const GridFlow& flow = grid_flow(static_cast<std::size_t>(state.range(0)));
  const FlowCapacities& changed = state.range(1) == 1 ? flow.changed_1 : flow.changed_10;
  Backend backend;
  backend.build(flow.nodes, flow.edges);
  backend.solve(flow.caps);
  bool use_changed = true;
  for (auto _ : state) {
    const FlowCapacities& before = use_changed ? flow.caps : changed;
    const FlowCapacities& after = use_changed ? changed : flow.caps;
    if constexpr (ReusingMaxFlow<Backend>) {
      resolve_with(backend, before, after);
    } else {
      backend.solve(after);
    }
    use_changed = !use_changed;
  }
}

/// The binary problem (d, p) of the expansion move to alpha from `labeling` (as ExpansionSolver
/// builds it).
void expansion_problem(const PairwiseEnergy& energy, const Labeling& labeling, Label alpha,
                       std::vector<double>& d, std::vector<double>& p) {
  d.assign(energy.num_variables(), 0.0);
  p.assign(energy.edges().size(), 0.0);
  for (std::size_t i = 0; i < d.size(); ++i)
    d[i] = energy.unary(i, alpha) - energy.unary(i, labeling[i]);
  const auto edges = energy.edges();
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Edge& edge = edges[e];
    const Label xu = labeling[edge.u], xv = labeling[edge.v];
    add_binary_term(d, p, e, edge.u, edge.v, energy.pairwise_cost(edge, xu, xv),
                    energy.pairwise_cost(edge, xu, alpha), energy.pairwise_cost(edge, alpha, xv),
                    energy.pairwise_cost(edge, alpha, alpha));
  }
}

/// One expansion move per iteration, alternating between the unary argmin labeling and a copy
/// with state.range(0)% of the pixels relabelled at random; the move is keyed, so DynamicMaxFlow
/// re-solves its own graph.
template <class Backend>
void BM_ExpansionMove(benchmark::State& state) {
  const PairwiseEnergy& energy = bench::stereo_sized_energy();
  Labeling base(energy.num_variables());
  for (std::size_t i = 0; i < base.size(); ++i) {
    Label best = 0;
    for (Label l = 1; l < energy.num_labels(); ++l)
      if (energy.unary(i, l) < energy.unary(i, best)) best = l;
    base[i] = best;
  }
  Labeling changed = base;
  std::mt19937_64 rng(7);
  std::bernoulli_distribution pick(static_cast<double>(state.range(0)) / 100.0);
  std::uniform_int_distribution<Label> label(0, static_cast<Label>(energy.num_labels() - 1));
  for (Label& l : changed)
    if (pick(rng)) l = label(rng);
  constexpr Label kAlpha = 40;
  std::vector<double> d_base, p_base, d_changed, p_changed;
  expansion_problem(energy, base, kAlpha, d_base, p_base);
  expansion_problem(energy, changed, kAlpha, d_changed, p_changed);
  BinaryMoveSolver<Backend> moves;
  moves.bind(energy);
  moves.recycle(1, std::size_t{1} << 32);
  std::vector<MoveLabel> out(energy.num_variables());
  moves.solve(d_base, p_base, out, 0);
  moves.solve(d_changed, p_changed, out, 0);  // the key's own graph from here on
  bool use_changed = false;
  bool qpbo = false;
  for (auto _ : state) {
    qpbo = moves.solve(use_changed ? d_changed : d_base, use_changed ? p_changed : p_base, out, 0)
               .used_qpbo;
    use_changed = !use_changed;
  }
  state.counters["qpbo"] = qpbo;
}

#define C2F_RESOLVE_ARGS ->Args({512, 1})->Args({512, 10})->Args({1024, 1})->Args({1024, 10})

BENCHMARK(BM_SolveInParts)
    ->ArgsProduct({{512, 1024}, {1, 2, 4, 8}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK(BM_ResolveInParts)
    ->ArgsProduct({{1, 10}, {1, 4, 8}, {1, 2}})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();
BENCHMARK_TEMPLATE(BM_Build, DynamicMaxFlow)
    ->Arg(64)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Solve, DynamicMaxFlow)
    ->Arg(64)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Resolve, DynamicMaxFlow) C2F_RESOLVE_ARGS->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Resolve, BoostMaxFlow) C2F_RESOLVE_ARGS->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_ExpansionMove, DynamicMaxFlow)
    ->Arg(1)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_ExpansionMove, BoostMaxFlow)->Arg(1)->Arg(10)->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Build, BoostMaxFlow)
    ->Arg(64)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Solve, BoostMaxFlow)
    ->Arg(64)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
BENCHMARK_TEMPLATE(BM_Build, KolmogorovMaxFlow)
    ->Arg(64)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Solve, KolmogorovMaxFlow)
    ->Arg(64)
    ->Arg(512)
    ->Arg(1024)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_Resolve, KolmogorovMaxFlow) C2F_RESOLVE_ARGS->Unit(benchmark::kMillisecond);
BENCHMARK_TEMPLATE(BM_ExpansionMove, KolmogorovMaxFlow)
    ->Arg(1)
    ->Arg(10)
    ->Unit(benchmark::kMillisecond);
#endif

}  // namespace

BENCHMARK_MAIN();

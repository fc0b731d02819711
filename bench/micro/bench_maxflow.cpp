// Max-flow backends on 4-connected grids (64x64, 512x512, 1024x1024): building the graph once
// and solving it (capacities reset each time) are measured separately. The problem is a
// segmentation-like cut: terminal capacities from a smooth random field plus noise,
// neighbour capacities 1.

#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <random>

#include "c2f/adapters/maxflow/boost_maxflow.hpp"
#include "c2f/core/grid.hpp"
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
#include "c2f/adapters/maxflow/kolmogorov_maxflow.hpp"
#endif

namespace {

using namespace c2f;

struct GridFlow {
  std::size_t nodes;
  std::vector<FlowEdge> edges;
  FlowCapacities caps;
};

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
#endif

}  // namespace

BENCHMARK_MAIN();

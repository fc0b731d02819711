// Colour passing on the stereo-sized energy (463x370, 85 labels, 4-connected): one iteration,
// and building CP(1,1), CP(2,1), CP(3,1) from scratch (the paper's stereo schedule), plus the
// reference's local grouping for comparison. Random unaries make almost every tuple distinct,
// so these are upper bounds on signature work; group counts on real scenes come from
// c2f-bench-partitions.

#include <benchmark/benchmark.h>

#include "c2f/lift/colour_passing.hpp"
#include "c2f/lift/local_grouping.hpp"
#include "support/stereo_sized_energy.hpp"

namespace {

using namespace c2f;

void BM_ColourPassingIteration(benchmark::State& state) {
  const PairwiseEnergy& energy = bench::stereo_sized_energy();
  for (auto _ : state) {
    state.PauseTiming();
    ColourPassing cp(energy, 1);
    state.ResumeTiming();
    cp.iterate();
    benchmark::DoNotOptimize(cp.num_groups());
  }
}
BENCHMARK(BM_ColourPassingIteration)->Unit(benchmark::kMillisecond);

void BM_BuildCp(benchmark::State& state) {
  const PairwiseEnergy& energy = bench::stereo_sized_energy();
  const auto labels = static_cast<int>(state.range(0));
  std::size_t groups = 0;
  for (auto _ : state) {
    ColourPassing cp(energy, 1);
    cp.iterate();
    while (cp.labels() < labels) cp.increase_labels();
    const DensePartition partition = cp.partition();
    groups = partition.num_groups();
    benchmark::DoNotOptimize(groups);
  }
  state.counters["groups"] = static_cast<double>(groups);
}
BENCHMARK(BM_BuildCp)->Arg(1)->Arg(2)->Arg(3)->ArgName("N_L")->Unit(benchmark::kMillisecond);

void BM_LocalGrouping(benchmark::State& state) {
  const PairwiseEnergy& energy = bench::stereo_sized_energy();
  std::size_t groups = 0;
  for (auto _ : state) {
    groups = local_grouping(energy, bench::kStereoShape, static_cast<int>(state.range(0)), 1)
                 .num_groups();
    benchmark::DoNotOptimize(groups);
  }
  state.counters["groups"] = static_cast<double>(groups);
}
BENCHMARK(BM_LocalGrouping)->Arg(1)->Arg(3)->ArgName("N_L")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

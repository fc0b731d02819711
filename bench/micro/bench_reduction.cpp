// Microbenchmarks of evaluate, reduce and transfer_labels on a stereo-sized problem: a
// 463x370 4-connected grid (Middlebury 2005 at third size) with 85 labels and the TSGO step
// term, with partitions of 0.1%, 1% and 10% as many groups as pixels.
//
// Two partition shapes bracket what colour passing produces: "blocks" (spatially compact
// groups: few edges cross groups) and "scattered" (every pixel in a uniformly random group:
// almost every edge crosses groups, the worst case for edge merging).

#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "c2f/c2f.hpp"
#include "support/stereo_sized_energy.hpp"

namespace {

using namespace c2f;

const GridShape kShape = bench::kStereoShape;
constexpr int kLabels = bench::kStereoLabels;
using bench::stereo_sized_energy;

std::size_t groups_for(std::int64_t per_mille) {
  return static_cast<std::size_t>(static_cast<double>(kShape.size()) *
                                  static_cast<double>(per_mille) / 1000.0);
}

DensePartition scattered_partition(std::size_t num_groups, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<std::int64_t> group(0, static_cast<std::int64_t>(num_groups) - 1);
  std::vector<std::int64_t> ids(kShape.size());
  for (auto& id : ids) id = group(rng);
  return DensePartition::from_ids(ids);
}

DensePartition compact_partition(std::size_t num_groups) {
  const auto block = static_cast<std::size_t>(std::max(
      1.0,
      std::round(std::sqrt(static_cast<double>(kShape.size()) / static_cast<double>(num_groups)))));
  return block_partition(kShape, block);
}

void BM_Evaluate(benchmark::State& state) {
  const PairwiseEnergy& energy = stereo_sized_energy();
  std::mt19937_64 rng(2);
  std::uniform_int_distribution<Label> label(0, kLabels - 1);
  Labeling x(energy.num_variables());
  for (Label& l : x) l = label(rng);
  for (auto _ : state) benchmark::DoNotOptimize(energy.evaluate(x));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(energy.num_variables()));
}
BENCHMARK(BM_Evaluate)->Unit(benchmark::kMillisecond);

void BM_Reduce(benchmark::State& state) {
  const PairwiseEnergy& energy = stereo_sized_energy();
  const bool scattered = state.range(1) == 1;
  const DensePartition partition = scattered ? scattered_partition(groups_for(state.range(0)), 3)
                                             : compact_partition(groups_for(state.range(0)));
  std::size_t edges = 0;
  for (auto _ : state) {
    const PairwiseEnergy reduced = reduce(energy, partition);
    edges = reduced.edges().size();
    benchmark::DoNotOptimize(edges);
  }
  state.SetLabel(std::string(scattered ? "scattered" : "blocks") + ", " +
                 std::to_string(partition.num_groups()) + " groups, " + std::to_string(edges) +
                 " merged edges");
}
BENCHMARK(BM_Reduce)
    ->ArgsProduct({{1, 10, 100}, {0, 1}})
    ->ArgNames({"groups_per_mille", "scattered"})
    ->Unit(benchmark::kMillisecond);

void BM_TransferLabels(benchmark::State& state) {
  // From a 1% partition to a refinement of it (every group split in up to 10 parts).
  const DensePartition coarse = scattered_partition(groups_for(10), 4);
  std::mt19937_64 rng(5);
  std::uniform_int_distribution<std::int64_t> part(0, 9);
  std::vector<std::int64_t> ids(kShape.size());
  for (std::size_t v = 0; v < ids.size(); ++v)
    ids[v] = static_cast<std::int64_t>(coarse.group_of(v)) * 10 + part(rng);
  const DensePartition fine = DensePartition::from_ids(ids);
  std::uniform_int_distribution<Label> label(0, kLabels - 1);
  Labeling y(coarse.num_groups());
  for (Label& l : y) l = label(rng);
  for (auto _ : state) benchmark::DoNotOptimize(transfer_labels(y, coarse, fine));
  state.SetLabel(std::to_string(coarse.num_groups()) + " -> " + std::to_string(fine.num_groups()) +
                 " groups");
}
BENCHMARK(BM_TransferLabels)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();

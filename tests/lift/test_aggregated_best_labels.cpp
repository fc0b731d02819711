// Aggregated best labels (agg:R): groups of equal best label after summing unaries over a
// window, against the sums taken pixel by pixel.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <variant>
#include <vector>

#include "c2f/lift/aggregated_best_labels.hpp"
#include "c2f/lift/connected_components.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// The partition by the definition: every pixel's window sums, one pixel at a time.
DensePartition window_minimum_by_hand(const PairwiseEnergy& energy, GridShape shape, int radius) {
  const auto w = static_cast<long>(shape.width), h = static_cast<long>(shape.height);
  std::vector<std::int64_t> best(shape.size());
  for (long y = 0; y < h; ++y) {
    for (long x = 0; x < w; ++x) {
      std::vector<double> sums(static_cast<std::size_t>(energy.num_labels()), 0.0);
      for (long y2 = std::max(0L, y - radius); y2 <= std::min(h - 1, y + radius); ++y2)
        for (long x2 = std::max(0L, x - radius); x2 <= std::min(w - 1, x + radius); ++x2)
          for (std::size_t l = 0; l < sums.size(); ++l)
            sums[l] += energy.unary(static_cast<std::size_t>(y2 * w + x2), static_cast<Label>(l));
      best[static_cast<std::size_t>(y * w + x)] =
          std::min_element(sums.begin(), sums.end()) - sums.begin();
    }
  }
  return DensePartition::from_ids(best);
}

/// The graph version by the definition: the sums of each round as a whole table, taken edge by
/// edge (each edge adds to both ends).
DensePartition graph_minimum_by_hand(const PairwiseEnergy& energy, int radius) {
  const std::size_t n = energy.num_variables();
  const auto L = static_cast<std::size_t>(energy.num_labels());
  std::vector<double> sums(n * L);
  for (std::size_t v = 0; v < n; ++v)
    for (std::size_t l = 0; l < L; ++l) sums[v * L + l] = energy.unary(v, static_cast<Label>(l));
  for (int round = 0; round < radius; ++round) {
    std::vector<double> next = sums;
    for (const Edge& e : energy.edges()) {
      for (std::size_t l = 0; l < L; ++l) {
        next[e.u * L + l] += sums[e.v * L + l];
        next[e.v * L + l] += sums[e.u * L + l];
      }
    }
    sums.swap(next);
  }
  std::vector<std::int64_t> best(n);
  for (std::size_t v = 0; v < n; ++v)
    best[v] =
        std::min_element(sums.begin() + v * L, sums.begin() + (v + 1) * L) - (sums.begin() + v * L);
  return DensePartition::from_ids(best);
}

}  // namespace

TEST_CASE("aggregated best labels group pixels by their window's cheapest label",
          "[lift][aggregated]") {
  // A 5x1 row, 2 labels: label 1 is 4 cheaper than label 0 at pixel 2 and 1 dearer at every
  // other pixel, so it wins the windows that hold pixel 2 and fewer than four others.
  const std::vector<double> unaries{0, 1, 0, 1, 4, 0, 0, 1, 0, 1};
  const PairwiseEnergy row(5, 2, unaries, {}, {});
  auto groups = [&](int radius) {
    const DensePartition p = aggregated_best_labels(lifting_view(row), {5, 1}, radius);
    return std::vector<VariableIndex>(p.group_ids().begin(), p.group_ids().end());
  };
  CHECK(groups(0) == std::vector<VariableIndex>{0, 0, 1, 0, 0});
  CHECK(groups(1) == std::vector<VariableIndex>{0, 1, 1, 1, 0});  // pixels 1-3: 4 against 2
  // Radius 2: label 1 wins every window but pixel 2's, which holds the whole row and ties
  // (4 against 4): the smaller label, 0.
  CHECK(groups(2) == std::vector<VariableIndex>{0, 0, 1, 0, 0});
  CHECK_THROWS_WITH(aggregated_best_labels(lifting_view(row), {5, 1}, -1),
                    Catch::Contains("radius must be >= 0"));
  CHECK_THROWS_WITH(aggregated_best_labels(lifting_view(row), {2, 2}, 1),
                    Catch::Contains("the energy has 5 variables"));
}

TEST_CASE("aggregated best labels equal the window sums taken pixel by pixel",
          "[lift][aggregated][property]") {
  Rng rng(31);
  for (int trial = 0; trial < 60; ++trial) {
    const GridShape shape{static_cast<std::size_t>(1 + trial % 7),
                          static_cast<std::size_t>(1 + trial % 5)};
    const int radius = trial % 4;
    const PairwiseEnergy energy = random_grid_energy(rng, shape.width, shape.height, 2 + trial % 4);
    INFO("trial " << trial << ": " << shape.width << "x" << shape.height << ", radius " << radius);
    CHECK(aggregated_best_labels(lifting_view(energy), shape, radius) ==
          window_minimum_by_hand(energy, shape, radius));
  }
  // A window larger than the grid is the whole grid for every pixel, found in O(N * L).
  const PairwiseEnergy energy = random_grid_energy(rng, 300, 200, 3);
  CHECK(aggregated_best_labels(lifting_view(energy), {300, 200}, 1'000'000'000).num_groups() == 1);
}

TEST_CASE("aggregated best labels on a grid are the same bits on any number of threads",
          "[lift][aggregated][threads]") {
  // Wider than a task's columns (64) and taller than a batch's rows (8). Spikes of 1e17 in
  // label 0 swallow the small costs beside them as the window slides over them (added, then
  // subtracted), so the partition follows the one-thread slide's rounding, not the exact sums:
  // it differs from the definition at radius 1 and 2 (at 9 every window holds a spike), and
  // every thread count must reproduce it.
  Rng rng(53);
  const GridShape shape{150, 40};
  const int labels = 3;
  std::uniform_real_distribution<double> cost(0.0, 1.0);
  std::vector<double> unaries(shape.size() * labels);
  for (std::size_t v = 0; v < shape.size(); ++v) {
    for (int l = 0; l < labels; ++l) unaries[v * labels + l] = cost(rng);
    if (rng() % 50 == 0) unaries[v * labels] = 1e17;
  }
  const PairwiseEnergy energy =
      make_grid_energy(shape, Connectivity::four, labels, std::move(unaries), PairwiseTerm::potts(),
                       [](VariableIndex, VariableIndex) { return 1.0; });
  const LiftingView view = lifting_view(energy);
  for (const int radius : {0, 1, 2, 9}) {
    INFO("radius " << radius);
    const DensePartition one_thread = aggregated_best_labels(view, shape, radius, 1);
    if (radius == 1 || radius == 2)
      CHECK(one_thread != window_minimum_by_hand(energy, shape, radius));
    for (const int threads : {2, 3})
      CHECK(aggregated_best_labels(view, shape, radius, threads) == one_thread);
  }
}

TEST_CASE("agg levels parse, print and build through the schedule",
          "[lift][aggregated][schedule]") {
  const Schedule schedule = Schedule::parse("agg:2 agg:1/cc");
  CHECK(schedule.to_string() == "agg:2 agg:1/cc flat");
  CHECK(std::get<AggregatedLevel>(schedule.levels[1].partition) == AggregatedLevel{1});
  CHECK(Schedule::parse("agg:0").levels[0].partition == LevelPartition{AggregatedLevel{0}});
  CHECK_THROWS_WITH(Schedule::parse("agg:-1"), Catch::Contains("'-1' must be a whole number >= 0"));
  CHECK_THROWS_WITH(Schedule::parse("agg:1,2"), Catch::Contains("expected agg:RADIUS"));
  CHECK_THROWS_WITH(Schedule::parse("agg:x"), Catch::Contains("'x' is not a number"));

  Rng rng(8);
  const GridShape shape{16, 12};
  const PairwiseEnergy energy = random_grid_energy(rng, shape.width, shape.height, 4);
  ScheduleProvider provider(Schedule::parse("agg:1/cc"), shape);
  const auto level = provider.next(energy);
  REQUIRE(level);
  CHECK(*level ==
        connected_components(aggregated_best_labels(lifting_view(energy), shape, 1), shape));
  CHECK(provider.reports().back().threads == 1);
  // The threads set are those an agg level reports; a level built on one thread reports 1.
  ScheduleProvider on_two(Schedule::parse("agg:1/cc cp:1,1"), shape);
  on_two.set_threads(2);
  REQUIRE(on_two.next(energy) == level);
  REQUIRE(on_two.next(energy));
  CHECK(on_two.reports()[0].threads == 2);
  CHECK(on_two.reports()[1].threads == 1);
}

TEST_CASE("aggregated best labels on a graph sum over neighbourhoods",
          "[lift][aggregated][graph]") {
  // A path 0-1-2-3-4 given as a graph (edges out of order), the unaries of the row above:
  // radius 1 sums a variable and its path neighbours, as the 3-wide window does on the row.
  const std::vector<double> unaries{0, 1, 0, 1, 4, 0, 0, 1, 0, 1};
  const PairwiseEnergy path(5, 2, unaries, {PairwiseTerm::potts()},
                            {{2, 3, 1.0, 0}, {0, 1, 1.0, 0}, {3, 4, 1.0, 0}, {1, 2, 1.0, 0}});
  auto groups = [&](int radius) {
    const DensePartition p = aggregated_best_labels(lifting_view(path), radius);
    return std::vector<VariableIndex>(p.group_ids().begin(), p.group_ids().end());
  };
  CHECK(groups(0) == std::vector<VariableIndex>{0, 0, 1, 0, 0});
  CHECK(groups(1) == std::vector<VariableIndex>{0, 1, 1, 1, 0});
  CHECK(aggregated_best_labels(lifting_view(path), 1) ==
        aggregated_best_labels(lifting_view(path), {5, 1}, 1));
  CHECK_THROWS_WITH(aggregated_best_labels(lifting_view(path), -1),
                    Catch::Contains("radius must be >= 0"));

  Rng rng(32);
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t n = 2 + static_cast<std::size_t>(trial % 10);
    const int radius = trial % 4;
    const PairwiseEnergy energy = random_energy(rng, n, 2 + trial % 4, 2 * n);
    INFO("trial " << trial << ": " << n << " variables, radius " << radius);
    CHECK(aggregated_best_labels(lifting_view(energy), radius) ==
          graph_minimum_by_hand(energy, radius));
  }
}

TEST_CASE("agg and /cc levels build on an energy that is no pixel grid",
          "[lift][aggregated][graph][schedule]") {
  CHECK(Schedule::parse("agg:2/cc cp:1,1/cc").validate_without_grid().empty());
  CHECK_THROWS_WITH(ScheduleProvider(Schedule::parse("agg:1 blocks:4")),
                    Catch::Contains("level blocks:4 needs a pixel grid"));

  Rng rng(9);
  const PairwiseEnergy energy = random_energy(rng, 60, 3, 70);
  const LiftingView view = lifting_view(energy);
  ScheduleProvider provider(Schedule::parse("agg:2/cc agg:1 cp:1,1/cc"));
  const auto first = provider.next(energy);
  REQUIRE(first);
  CHECK(*first == connected_components_along_edges(aggregated_best_labels(view, 2), view));
  CHECK(provider.next(energy) == aggregated_best_labels(view, 1));
  const auto third = provider.next(energy);
  REQUIRE(third);
  CHECK(*third == connected_components_along_edges(*third, view));  // components along the edges
  CHECK_FALSE(provider.next(energy));
}

TEST_CASE("agg:R,MAX,SHARE takes the smallest radius whose level keeps at most SHARE",
          "[lift][aggregated][schedule]") {
  const Schedule schedule = Schedule::parse("agg:1,4,0.2/cc");
  CHECK(schedule.to_string() == "agg:1,4,0.2/cc flat");
  CHECK(schedule.levels[0].partition == LevelPartition{AggregatedLevel{1, 4, 0.2}});
  CHECK(schedule.levels[0].connected);
  CHECK_THROWS_WITH(Schedule::parse("agg:2,2,0.1"),
                    Catch::Contains("'2' must be a whole number >= 3"));
  CHECK_THROWS_WITH(Schedule::parse("agg:1,3,0"), Catch::Contains("SHARE must be in (0, 1]"));
  CHECK_THROWS_WITH(Schedule::parse("agg:1,3,1.5"), Catch::Contains("SHARE must be in (0, 1]"));
  CHECK_THROWS_WITH(Schedule::parse("agg:1,3"), Catch::Contains("expected agg:RADIUS"));

  // On a grid, the share of the level after /cc: between radius 2's and 3's, radius 3.
  Rng rng(12);
  const GridShape shape{40, 30};
  const PairwiseEnergy energy = random_grid_energy(rng, shape.width, shape.height, 6);
  const LiftingView view = lifting_view(energy);
  auto on_grid = [&](int radius) {
    return connected_components(aggregated_best_labels(view, shape, radius), shape);
  };
  auto share = [](const DensePartition& p) {
    return static_cast<double>(p.num_groups()) / static_cast<double>(p.num_variables());
  };
  REQUIRE(share(on_grid(1)) > share(on_grid(2)));  // so the share decides the radius
  REQUIRE(share(on_grid(2)) > share(on_grid(3)));
  auto grid_level = [&](const std::string& text) {
    INFO(text);
    ScheduleProvider provider(Schedule::parse(text), shape);
    const auto level = provider.next(energy);
    REQUIRE(level);
    return *level;
  };
  const std::string between = std::to_string((share(on_grid(2)) + share(on_grid(3))) / 2.0);
  CHECK(grid_level("agg:1,4," + between + "/cc") == on_grid(3));
  CHECK(grid_level("agg:1,4,1/cc") == on_grid(1));
  CHECK(grid_level("agg:1,4,1e-9/cc") == on_grid(4));  // none keeps so few: the widest
  // The report names the radius chosen, then the level's text.
  ScheduleProvider chosen(Schedule::parse("agg:1,4," + between + "/cc"), shape);
  REQUIRE(chosen.next(energy));
  CHECK_THAT(chosen.reports()[0].level,
             Catch::StartsWith("agg:3/cc (agg:1,4,") && Catch::EndsWith("/cc)"));
  ScheduleProvider fixed(Schedule::parse("agg:1/cc"), shape);
  REQUIRE(fixed.next(energy));
  CHECK(fixed.reports()[0].level == "agg:1/cc");

  // On a graph, over rounds of neighbours, components along the edges.
  const PairwiseEnergy graph = random_energy(rng, 300, 5, 360);
  const LiftingView graph_view = lifting_view(graph);
  auto on_graph = [&](int radius) {
    return connected_components_along_edges(aggregated_best_labels(graph_view, radius), graph_view);
  };
  int expected = 3;
  for (int radius = 0; radius < 3; ++radius) {
    if (share(on_graph(radius)) <= 0.3) {
      expected = radius;
      break;
    }
  }
  INFO("shares: " << share(on_graph(0)) << ", " << share(on_graph(1)) << ", " << share(on_graph(2))
                  << ", " << share(on_graph(3)));
  REQUIRE(expected > 0);  // radius 0 alone would not tell the rule from a fixed radius
  ScheduleProvider provider(Schedule::parse("agg:0,3,0.3/cc"));
  const auto level = provider.next(graph);
  REQUIRE(level);
  CHECK(*level == on_graph(expected));
}

TEST_CASE("graph aggregation: one radius after another, on any number of threads",
          "[lift][aggregated][graph]") {
  Rng rng(41);
  // More variables than one task of the rounds holds (4096), in double and in float.
  const PairwiseEnergy graph = random_energy(rng, 10000, 5, 16000);
  FloatValues floats(graph.num_variables() * 5);
  for (std::size_t v = 0; v < graph.num_variables(); ++v)
    for (Label l = 0; l < 5; ++l)
      floats[v * 5 + static_cast<std::size_t>(l)] = static_cast<float>(graph.unary(v, l));
  const PairwiseEnergy single = PairwiseEnergy::with_float_unaries(
      graph.num_variables(), 5, std::move(floats),
      std::vector<PairwiseTerm>(graph.terms().begin(), graph.terms().end()),
      std::vector<Edge>(graph.edges().begin(), graph.edges().end()));
  for (const PairwiseEnergy* energy : {&graph, &single}) {
    const LiftingView view = lifting_view(*energy);
    for (int radius = 0; radius <= 3; ++radius) {
      INFO("radius " << radius << (energy == &single ? ", float" : ", double"));
      // By the definition in double; the float energy's rounds are kept in float, so its
      // thread counts are held to its one-thread partition.
      const DensePartition expected = energy == &graph ? graph_minimum_by_hand(*energy, radius)
                                                       : aggregated_best_labels(view, radius);
      REQUIRE(expected.num_groups() > 1);
      for (const int threads : {1, 2, 3})
        CHECK(aggregated_best_labels(view, radius, threads) == expected);
    }
    // One radius after another, each going on from the last one's sums, bits included.
    GraphAggregation widening(view, 2);
    for (int radius = 0; radius <= 4; ++radius)
      CHECK(widening.best_labels(radius, true) == aggregated_best_labels(view, radius));
    GraphAggregation skipping(view);
    CHECK(skipping.best_labels(1, true) == aggregated_best_labels(view, 1));
    CHECK(skipping.best_labels(3, true) == aggregated_best_labels(view, 3));
    CHECK(skipping.best_labels(0) == aggregated_best_labels(view, 0));  // the unaries': any time
    CHECK_THROWS_WITH(skipping.best_labels(3), Catch::Contains("those kept are of radius 3"));
    CHECK(skipping.best_labels(5) == aggregated_best_labels(view, 5));
  }
}

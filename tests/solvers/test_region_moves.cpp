// Region moves (ExpansionOptions::regions): the layout keeps every edge within one region or two
// adjacent ones, a phase's move is exact per region against brute force, and expansion with
// regions gives the same bits on 1, 2 and 3 threads, converges where whole moves find nothing,
// and keeps its recycled graphs within the memory limit.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <span>
#include <vector>

#include "c2f/adapters/graphcut/detail/expansion_problems.hpp"
#include "c2f/adapters/graphcut/detail/near_moves.hpp"
#include "c2f/adapters/graphcut/detail/region_layout.hpp"
#include "c2f/adapters/graphcut/detail/region_moves.hpp"
#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/core/grid.hpp"
#include "support/descent.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// A width x height grid energy with random unaries in [0, 1) and a metric term (Potts or
/// truncated linear) with random weights: its expansion moves are submodular, so a region's
/// move is its exact minimum.
PairwiseEnergy metric_grid(Rng& rng, std::size_t width, std::size_t height, int labels,
                           bool potts) {
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<double> unaries(width * height * static_cast<std::size_t>(labels));
  for (double& u : unaries) u = unit(rng);
  return make_grid_energy(GridShape{width, height}, Connectivity::four, labels, std::move(unaries),
                          potts ? PairwiseTerm::potts() : PairwiseTerm::truncated_linear(2.0),
                          [&](VariableIndex, VariableIndex) { return 0.6 * unit(rng); });
}

/// The lowest energy of the labelings that keep x outside `nodes` and give each node its label
/// in x or alpha (every assignment).
double best_restricted(const PairwiseEnergy& energy, const Labeling& x,
                       const std::vector<VariableIndex>& nodes, Label alpha) {
  double best = energy.evaluate(x);
  Labeling y = x;
  for (std::uint32_t b = 0; b < (1u << nodes.size()); ++b) {
    for (std::size_t k = 0; k < nodes.size(); ++k)
      y[nodes[k]] = (b >> k) & 1u ? alpha : x[nodes[k]];
    best = std::min(best, energy.evaluate(y));
  }
  return best;
}

/// What one phase of colour `colour` should leave: the energy before, lowered in every region of
/// that colour by what the best labeling of its `nodes(region)` gains (regions share no edge, so
/// the gains add up).
template <class Nodes>
double expected_after_phase(const PairwiseEnergy& energy, const Labeling& x,
                            const detail::RegionLayout& layout, int colour, Label alpha,
                            const Nodes& nodes) {
  const double before = energy.evaluate(x);
  double expected = before;
  for (std::size_t r = static_cast<std::size_t>(colour); r < layout.count(); r += 2)
    expected += best_restricted(energy, x, nodes(r), alpha) - before;
  return expected;
}

/// The energies after each of the first `steps` steps of expansion with `options` from `start`.
std::vector<double> expansion_trace(const PairwiseEnergy& energy, const Labeling& start,
                                    const ExpansionOptions& options, int steps) {
  ExpansionSolver<> solver(options);
  solver.bind(energy, start);
  std::vector<double> trace;
  for (int step = 0; step < steps; ++step) trace.push_back(solver.step());
  return trace;
}

}  // namespace

TEST_CASE("a region layout keeps every edge within one region or two adjacent ones",
          "[expansion][regions]") {
  Rng rng(17);
  for (int trial = 0; trial < 40; ++trial) {
    const PairwiseEnergy energy =
        trial % 2 == 0 ? random_grid_energy(rng, 5 + trial % 7, 4 + trial % 5, 3)
                       : random_energy(rng, 20 + static_cast<std::size_t>(trial), 3, 30);
    const std::size_t wanted = 2 + static_cast<std::size_t>(trial) % 6;
    const detail::RegionLayout layout = detail::region_layout(energy, wanted, 3);
    INFO("trial " << trial);
    REQUIRE(layout.count() >= 1);
    CHECK(layout.count() <= wanted);
    CHECK(layout.bounds.front() == 0);
    CHECK(layout.bounds.back() == energy.num_variables());
    for (std::size_t r = 0; r < layout.count(); ++r) {
      CHECK(layout.bounds[r] < layout.bounds[r + 1]);
      for (std::size_t i = layout.bounds[r]; i < layout.bounds[r + 1]; ++i)
        CHECK(layout.region_of[i] == r);
    }
    for (const Edge& edge : energy.edges()) {
      const int ru = layout.region_of[edge.u], rv = layout.region_of[edge.v];
      CHECK(std::abs(ru - rv) <= 1);
    }
  }
  // On a row-major grid the regions are bands of whole rows or more, as many as wanted.
  const PairwiseEnergy grid = random_grid_energy(rng, 10, 40, 2);
  const detail::RegionLayout bands = detail::region_layout(grid, 4, 10);
  CHECK(bands.count() == 4);
  // The default keeps regions of at least kMinRegionVariables: a small energy gets one.
  CHECK(detail::region_layout(grid, 16).count() == 1);
}

TEST_CASE("a phase of region moves makes each region's exact move",
          "[expansion][regions]"
          "[brute-force]") {
  Rng rng(99);
  for (int trial = 0; trial < 24; ++trial) {
    const int labels = 2 + trial % 4;
    // 4 x 9 grid in 3 regions of 3 rows (12 variables each).
    const PairwiseEnergy energy = metric_grid(rng, 4, 9, labels, trial % 4 < 2);
    const Labeling start = random_labeling(rng, energy.num_variables(), labels);
    const auto alpha = static_cast<Label>(trial % labels);
    detail::RegionMoves<DynamicMaxFlow> regions;
    regions.bind(energy, 3, static_cast<std::size_t>(labels), 0, 1 + trial % 3, 12);
    REQUIRE(regions.count() == 3);
    const detail::RegionLayout& layout = regions.layout();
    const int colour = trial % 2;
    Labeling labeling = start, candidate = start;
    double value = energy.evaluate(start);
    std::vector<VariableIndex> moved;
    MoveStep step;
    INFO("trial " << trial);
    if (trial % 3 != 2) {
      // A whole move to alpha, phase by phase.
      detail::ExpansionProblems problems;
      problems.bind(energy, 0);
      detail::MoveProblem problem;
      problems.update(alpha, labeling, problem.d, problem.p);
      problem.proposal = [alpha](VariableIndex) { return alpha; };
      regions.phase(colour, problem, static_cast<std::size_t>(alpha), 0.0, labeling, candidate,
                    value, moved, step);
      const double expected =
          expected_after_phase(energy, start, layout, colour, alpha, [&](std::size_t r) {
            std::vector<VariableIndex> nodes;
            for (std::size_t i = layout.bounds[r]; i < layout.bounds[r + 1]; ++i)
              nodes.push_back(static_cast<VariableIndex>(i));
            return nodes;
          });
      CHECK(close_relative(energy.evaluate(labeling), expected, 1e-9));
    } else {
      // A near move to alpha over the variables NearMoves frees.
      detail::NearMoves near;
      near.bind(energy, 1, NearSeeds::label_and_cheapest);
      near.select(alpha, start);
      regions.near_phase(colour, alpha, near, 0.0, labeling, candidate, value, moved, step);
      const double expected =
          expected_after_phase(energy, start, layout, colour, alpha, [&](std::size_t r) {
            std::vector<VariableIndex> nodes;
            for (std::size_t i = layout.bounds[r]; i < layout.bounds[r + 1]; ++i)
              if (near.is_free(static_cast<VariableIndex>(i), alpha, start))
                nodes.push_back(static_cast<VariableIndex>(i));
            return nodes;
          });
      CHECK(close_relative(energy.evaluate(labeling), expected, 1e-9));
    }
    CHECK(candidate == labeling);
    CHECK(close_relative(value, energy.evaluate(labeling), 1e-9));
    CHECK(energy.evaluate(labeling) <= energy.evaluate(start));
    // Only the phase's regions changed, and `moved` names exactly what changed.
    std::vector<VariableIndex> changed;
    for (std::size_t i = 0; i < labeling.size(); ++i) {
      if (labeling[i] == start[i]) continue;
      changed.push_back(static_cast<VariableIndex>(i));
      CHECK(layout.region_of[i] % 2 == colour);
    }
    std::sort(moved.begin(), moved.end());
    CHECK(moved == changed);
  }
}

TEST_CASE("expansion with regions gives the same bits on 1, 2 and 3 threads and converges",
          "[expansion][regions]") {
  Rng rng(7);
  // 130 x 100 pixels: three regions of at least 4096 variables.
  const PairwiseEnergy energy = random_grid_energy(rng, 130, 100, 5);
  const Labeling start = random_labeling(rng, energy.num_variables(), 5);
  std::vector<std::vector<double>> energies;
  std::vector<Labeling> results;
  for (int threads = 1; threads <= 3; ++threads) {
    ExpansionOptions options;
    options.near_radius = 2;
    options.shift_moves = true;
    options.regions = 16;
    options.threads = threads;
    ExpansionSolver<> solver(options);
    solver.bind(energy, start);
    REQUIRE(solver.region_count() == 3);
    // Near, region and whole sweeps: four sweeps without decrease.
    REQUIRE(solver.quiet_steps_to_converge(energy) == 4 * 7);
    std::vector<double> trace;
    double final_energy = 0.0;
    const std::size_t quiet =
        descend(solver, energy, solver.quiet_steps_to_converge(energy), 2000, final_energy,
                [&](const auto& s) { trace.push_back(s.energy()); });
    REQUIRE(quiet == solver.quiet_steps_to_converge(energy));
    energies.push_back(trace);
    results.emplace_back(solver.labeling().begin(), solver.labeling().end());
    // Converged: a sweep of whole moves from the result finds nothing lower.
    ExpansionOptions whole_options;
    whole_options.shift_moves = true;
    ExpansionSolver<> whole(whole_options);
    whole.bind(energy, solver.labeling());
    for (int step = 0; step < 7; ++step) CHECK(whole.step() == final_energy);
  }
  CHECK(energies[1] == energies[0]);
  CHECK(energies[2] == energies[0]);
  CHECK(results[1] == results[0]);
  CHECK(results[2] == results[0]);
}

TEST_CASE("expansion with regions keeps its recycled graphs within the memory limit",
          "[expansion][regions][memory]") {
  // The regions' moves over every variable (here the shift moves of every sweep) recycle
  // graphs of their own, within graph_memory_limit split between the regions; the whole moves'
  // graphs are never held at the same time. So what the solver keeps never exceeds the limit,
  // on any thread count.
  Rng rng(11);
  const PairwiseEnergy energy = random_grid_energy(rng, 130, 100, 5);
  const Labeling start = random_labeling(rng, energy.num_variables(), 5);
  const auto most_kept = [&](std::size_t limit, int threads) {
    ExpansionOptions options;
    options.near_radius = 2;
    options.shift_moves = true;
    options.regions = 16;
    options.threads = threads;
    options.recycle_with_near_moves = true;
    options.problem_memory_limit = 0;  // so that kept_bytes() counts the graphs only
    options.graph_memory_limit = limit;
    ExpansionSolver<> solver(options);
    solver.bind(energy, start);
    REQUIRE(solver.region_count() == 3);
    std::size_t most = 0;
    for (int step = 0; step < 70; ++step) {
      solver.step();
      most = std::max(most, solver.kept_bytes());
    }
    return most;
  };
  const std::size_t unlimited = most_kept(std::size_t{1} << 40, 2);
  REQUIRE(unlimited > 0);
  for (const int threads : {1, 2}) {
    INFO(threads << " threads");
    const std::size_t most = most_kept(unlimited / 2, threads);
    CHECK(most <= unlimited / 2);
    CHECK(most > 0);
  }
}

TEST_CASE("regions and threads are validated", "[expansion][regions][validation]") {
  ExpansionOptions options;
  options.regions = 0;
  CHECK_THROWS_WITH(ExpansionSolver<>(options), Catch::Contains("regions"));
  options.regions = 16;
  options.threads = -1;
  CHECK_THROWS_WITH(ExpansionSolver<>(options), Catch::Contains("threads"));
  // Without near moves, with one region (the default) or with a layout of one, every move is
  // over every variable.
  Rng rng(5);
  const PairwiseEnergy energy = random_grid_energy(rng, 130, 100, 3);
  ExpansionSolver<> whole;
  whole.bind(energy, random_labeling(rng, energy.num_variables(), 3));
  CHECK(whole.region_count() == 1);
  CHECK(whole.quiet_steps_to_converge(energy) == 3);
  options.threads = 0;
  options.near_radius = 1;
  options.regions = 1;
  CHECK(ExpansionOptions{}.regions == 1);
  ExpansionSolver<> one(options);
  one.bind(energy, random_labeling(rng, energy.num_variables(), 3));
  CHECK(one.region_count() == 1);
  CHECK(one.quiet_steps_to_converge(energy) == 3 * 3);
}

TEST_CASE("expansion with its max-flow in parts gives the same bits on 1, 2 and 3 threads",
          "[expansion][flow-parts]") {
  // 130 x 100 pixels: flow_parts 8 gives three parts of at least 4096 variables. A random grid
  // energy's moves include QPBO ones (TSGO step, tables), whose doubled graph is cut alike.
  Rng rng(11);
  for (int trial = 0; trial < 3; ++trial) {
    const PairwiseEnergy energy = random_grid_energy(rng, 130, 100, 5);
    const Labeling start = random_labeling(rng, energy.num_variables(), 5);
    std::vector<std::vector<double>> traces;
    std::vector<Labeling> results;
    for (int threads = 1; threads <= 3; ++threads) {
      ExpansionOptions options;
      options.shift_moves = trial == 1;
      options.near_radius = trial == 2 ? 2 : 0;
      options.flow_parts = 8;
      options.threads = threads;
      ExpansionSolver<> solver(options);
      solver.bind(energy, start);
      REQUIRE(solver.flow_parts(energy.num_variables()) == 3);
      std::vector<double> trace;
      double final_energy = 0.0;
      descend(solver, energy, solver.quiet_steps_to_converge(energy), 2000, final_energy,
              [&](const auto& s) { trace.push_back(s.energy()); });
      traces.push_back(trace);
      results.emplace_back(solver.labeling().begin(), solver.labeling().end());
      // Converged: a sweep of serial whole moves from the result finds nothing lower.
      ExpansionOptions serial_options;
      serial_options.shift_moves = options.shift_moves;
      ExpansionSolver<> serial(serial_options);
      serial.bind(energy, solver.labeling());
      for (std::size_t step = 0; step < serial.quiet_steps_to_converge(energy); ++step)
        CHECK(serial.step() >= final_energy - 1e-9 * std::abs(final_energy));
    }
    INFO("trial " << trial);
    CHECK(traces[1] == traces[0]);
    CHECK(traces[2] == traces[0]);
    CHECK(results[1] == results[0]);
    CHECK(results[2] == results[0]);
  }
  ExpansionOptions options;
  options.flow_parts = -1;
  CHECK_THROWS_WITH(ExpansionSolver<>(options), Catch::Contains("flow_parts must be in [0, 255]"));
  options.flow_parts = 256;
  CHECK_THROWS_WITH(ExpansionSolver<>(options), Catch::Contains("flow_parts must be in [0, 255]"));
}

TEST_CASE("the default solves in parts only where few edges join different parts",
          "[expansion][flow-parts]") {
  Rng rng(5);
  // 130 wide, 128 high: the 4 parts are bands of 32 rows, joined by 3 x 130 of its edges.
  const PairwiseEnergy grid = random_grid_energy(rng, 130, 128, 3);
  const double grid_share = share_of_edges_between_parts(grid, 4);
  CHECK(grid_share == Approx(3.0 * 130 / grid.edges().size()));
  // The same number of variables with random edges: about 3/4 of them join different parts.
  const PairwiseEnergy random = random_energy(rng, 130 * 130, 3, 2 * 130 * 130);
  const double random_share = share_of_edges_between_parts(random, 4);
  CHECK(random_share > 0.7);
  CHECK(random_share < 0.8);
  // The same count by hand.
  std::size_t between = 0;
  for (const Edge& edge : random.edges())
    between += edge.u * 4 / random.num_variables() != edge.v * 4 / random.num_variables();
  CHECK(random_share == Approx(static_cast<double>(between) / random.edges().size()));
  CHECK(share_of_edges_between_parts(random, 1) == 0.0);

  ExpansionOptions options;  // flow_parts 0: the default's choice
  const ExpansionSolver<> by_default(options);
  CHECK(by_default.flow_parts(grid) == 4);
  CHECK(by_default.flow_parts(random) == 1);
  options.flow_parts = 4;  // asked for: kept on any graph
  const ExpansionSolver<> asked(options);
  CHECK(asked.flow_parts(random) == 4);
  // A random graph's run is the one-part run, bit for bit, and near moves follow the choice.
  for (const int radius : {0, 1}) {
    const Labeling start = random_labeling(rng, random.num_variables(), 3);
    std::vector<std::vector<double>> traces;
    for (const int parts : {0, 1}) {
      ExpansionOptions run_options;
      run_options.flow_parts = parts;
      run_options.near_radius = radius;
      traces.push_back(expansion_trace(random, start, run_options, 12));
    }
    INFO("near radius " << radius);
    CHECK(traces[0] == traces[1]);
  }
}

TEST_CASE("the default takes the most parts that keep few edges between them",
          "[expansion][flow-parts]") {
  Rng rng(8);
  // A 130 x 128 grid (4 parts: bands of 32 rows) with 3000 more edges, each from the first
  // band to the second: with 4 parts they join different parts, with 2 parts (bands of 64
  // rows) the same one, as the neighbours of a coarse level's large groups do.
  const PairwiseEnergy grid = random_grid_energy(rng, 130, 128, 3);
  std::vector<Edge> edges(grid.edges().begin(), grid.edges().end());
  std::uniform_int_distribution<VariableIndex> first_band(0, 32 * 130 - 1);
  std::uniform_real_distribution<double> weight(0.0, 3.0);
  for (int k = 0; k < 3000; ++k) {
    const VariableIndex u = first_band(rng);
    edges.push_back(Edge{u, u + 32 * 130, weight(rng), 0});
  }
  const std::size_t n = grid.num_variables();
  std::vector<double> unaries(n * 3);
  for (std::size_t i = 0; i < n; ++i) {
    for (Label l = 0; l < 3; ++l) unaries[i * 3 + static_cast<std::size_t>(l)] = grid.unary(i, l);
  }
  const PairwiseEnergy crossed(n, 3, std::move(unaries),
                               std::vector<PairwiseTerm>(grid.terms().begin(), grid.terms().end()),
                               std::move(edges));
  REQUIRE(share_of_edges_between_parts(crossed, 4) > kMaxShareBetweenParts);
  REQUIRE(share_of_edges_between_parts(crossed, 3) > kMaxShareBetweenParts);
  REQUIRE(share_of_edges_between_parts(crossed, 2) <= kMaxShareBetweenParts);
  const ExpansionSolver<> by_default{ExpansionOptions{}};
  CHECK(by_default.flow_parts(crossed) == 2);
  CHECK(by_default.flow_parts(grid) == 4);
  // The default's run is the run asked for 2 parts, bit for bit.
  const Labeling start = random_labeling(rng, n, 3);
  ExpansionOptions asked_for_two;
  asked_for_two.flow_parts = 2;
  CHECK(expansion_trace(crossed, start, ExpansionOptions{}, 9) ==
        expansion_trace(crossed, start, asked_for_two, 9));
}

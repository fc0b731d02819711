// Near moves (ExpansionOptions::near_radius): the restricted move problem is exact, frees the
// variables it promises, and expansion with near moves converges to labelings no whole
// expansion move improves.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <set>
#include <tuple>
#include <utility>
#include <vector>

#include "c2f/adapters/graphcut/detail/near_moves.hpp"
#include "c2f/adapters/graphcut/expansion.hpp"
#include "support/backends.hpp"
#include "support/descent.hpp"
#include "support/random_models.hpp"
#include "support/tiny_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("a near move's problem is the whole energy over the labelings that keep held variables",
          "[expansion][near]") {
  Rng rng(77);
  for (int trial = 0; trial < 120; ++trial) {
    // label_and_adjacent on 16 labels (its neighbours seed), the labeling over the first 4.
    const bool adjacent = trial % 3 == 2;
    const int num_labels = adjacent ? kMinLabelsForAdjacentSeeds : 2 + trial % 4;
    const PairwiseEnergy energy = random_grid_energy(rng, 4, 3, num_labels);
    const Labeling x = random_labeling(rng, energy.num_variables(), std::min(num_labels, 4));
    const Label alpha = static_cast<Label>(trial % std::min(num_labels, 4));
    detail::NearMoves near;
    constexpr NearSeeds kSeeds[] = {NearSeeds::label_and_cheapest, NearSeeds::label,
                                    NearSeeds::label_and_adjacent};
    near.bind(energy, 1 + trial % 3, kSeeds[trial % 3]);
    near.build(alpha, x);
    const auto free = near.free();
    const auto pairs = near.pairs();
    REQUIRE(free.size() <= 12);
    const double base = energy.evaluate(x);
    // Every assignment b of the free variables: the problem's value plus E(x) is the energy of
    // x with the variables where b = 1 moved to alpha.
    for (std::uint32_t b = 0; b < (1u << free.size()); ++b) {
      Labeling moved = x;
      double value = base;
      for (std::size_t k = 0; k < free.size(); ++k) {
        const bool one = (b >> k) & 1u;
        if (one) moved[free[k]] = alpha;
        value += one ? near.d()[k] : 0.0;
      }
      for (std::size_t e = 0; e < pairs.size(); ++e) {
        const bool u_one = (b >> pairs[e].from) & 1u;
        const bool v_one = (b >> pairs[e].to) & 1u;
        if (!u_one && v_one) value += near.p()[e];
      }
      INFO("trial " << trial << ", assignment " << b);
      CHECK(close_relative(value, energy.evaluate(moved), 1e-9));
    }
  }
}

TEST_CASE("a near move frees exactly the variables near its label", "[expansion][near]") {
  // A chain of 9 variables, 3 labels; label 2 is cheapest only at variable 7.
  const std::size_t n = 9;
  std::vector<double> unaries(n * 3, 1.0);
  unaries[7 * 3 + 2] = 0.0;
  std::vector<Edge> edges;
  for (std::size_t i = 0; i + 1 < n; ++i)
    edges.push_back({static_cast<VariableIndex>(i), static_cast<VariableIndex>(i + 1), 1.0, 0});
  const PairwiseEnergy energy(n, 3, std::move(unaries), {PairwiseTerm::potts()}, std::move(edges));
  //                   0  1  2  3  4  5  6  7  8
  const Labeling x = {0, 0, 2, 0, 1, 1, 1, 1, 1};
  detail::NearMoves near;
  near.bind(energy, 1, NearSeeds::label_and_cheapest);
  near.build(2, x);
  // Within one edge of variable 2 (labelled 2) or of variable 7 (cheapest 2), not labelled 2.
  std::set<VariableIndex> expected = {1, 3, 6, 7, 8};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
  near.bind(energy, 2, NearSeeds::label_and_cheapest);
  near.build(2, x);
  expected = {0, 1, 3, 4, 5, 6, 7, 8};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
  // Seeded by the label only: variable 7's cheap unary frees nothing around it.
  near.bind(energy, 1, NearSeeds::label);
  near.build(2, x);
  expected = {1, 3};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
  near.bind(energy, 2, NearSeeds::label);
  near.build(2, x);
  expected = {0, 1, 3, 4};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
  // A label no variable has frees nothing when seeded by the label only.
  const Labeling no_two = {0, 0, 0, 0, 1, 1, 1, 1, 1};
  near.build(2, no_two);
  CHECK(near.free().empty());
  // With 3 labels (fewer than kMinLabelsForAdjacentSeeds), expansion asked for
  // label_and_adjacent seeds as label (near_seeds_in_use).
  ExpansionOptions asked;
  asked.near_radius = 1;
  asked.near_seeds = NearSeeds::label_and_adjacent;
  REQUIRE(near_seeds_in_use(asked, energy) == NearSeeds::label);
  near.bind(energy, 1, near_seeds_in_use(asked, energy));
  near.build(2, x);
  expected = {1, 3};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
  // On the same chain with 16 labels, seeded by the label and the labels next to it: the move
  // to 2 frees every variable labelled 1 (the run 4..8, however long) and those within the
  // radius of 2's or 1's.
  const int many = kMinLabelsForAdjacentSeeds;
  std::vector<double> many_unaries(n * static_cast<std::size_t>(many), 1.0);
  many_unaries[7 * static_cast<std::size_t>(many) + 2] = 0.0;
  const PairwiseEnergy many_labels(n, many, std::move(many_unaries), {PairwiseTerm::potts()},
                                   std::vector<Edge>(energy.edges().begin(), energy.edges().end()));
  REQUIRE(near_seeds_in_use(asked, many_labels) == NearSeeds::label_and_adjacent);
  near.bind(many_labels, 1, near_seeds_in_use(asked, many_labels));
  near.build(2, x);
  expected = {1, 3, 4, 5, 6, 7, 8};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
  near.build(2, no_two);
  expected = {3, 4, 5, 6, 7, 8};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
  // The move to 0: label 1 is next to it, label 2 is not.
  near.build(0, x);
  expected = {2, 4, 5, 6, 7, 8};
  CHECK(std::set<VariableIndex>(near.free().begin(), near.free().end()) == expected);
}

TEST_CASE("near moves free the same variables on 1, 2 and 3 threads, as far as the radius says",
          "[expansion][near][threads]") {
  // 200 x 150 pixels: each breadth-first level spans several bands of 8192, so bands on
  // different threads race for the variables they reach. The free variables must be those
  // within `radius` grid steps of a variable labelled alpha, (label_and_cheapest) cheapest at
  // alpha or (label_and_adjacent, on 16 labels) labelled alpha - 1 or alpha + 1. The labeling
  // uses 3 labels (0, 1, 2), so that label seeds are dense enough to span bands.
  Rng rng(5);
  for (const int num_labels : {3, kMinLabelsForAdjacentSeeds}) {
    const PairwiseEnergy energy = random_grid_energy(rng, 200, 150, num_labels);
    const Labeling x = random_labeling(rng, energy.num_variables(), 3);
    const std::size_t n = energy.num_variables();
    const bool adjacent_on = num_labels >= kMinLabelsForAdjacentSeeds;
    for (const int radius : {1, 3}) {
      for (const NearSeeds seeds :
           {NearSeeds::label_and_cheapest, NearSeeds::label, NearSeeds::label_and_adjacent}) {
        // Brute force: each variable's grid distance to the nearest seed, by relaxation.
        std::vector<std::vector<VariableIndex>> expected(3);
        for (Label alpha = 0; alpha < 3; ++alpha) {
          std::vector<int> distance(n, 1 << 20);
          for (std::size_t v = 0; v < n; ++v) {
            const bool cheapest =
                seeds == NearSeeds::label_and_cheapest && cheapest_label(energy, v) == alpha;
            const bool adjacent = seeds == NearSeeds::label_and_adjacent && adjacent_on &&
                                  std::abs(x[v] - alpha) == 1;
            if (x[v] == alpha || cheapest || adjacent) distance[v] = 0;
          }
          for (int round = 0; round < radius; ++round) {
            std::vector<int> next = distance;
            for (const Edge& edge : energy.edges()) {
              next[edge.u] = std::min(next[edge.u], distance[edge.v] + 1);
              next[edge.v] = std::min(next[edge.v], distance[edge.u] + 1);
            }
            distance = next;
          }
          for (std::size_t v = 0; v < n; ++v)
            if (distance[v] <= radius && x[v] != alpha)
              expected[alpha].push_back(static_cast<VariableIndex>(v));
          // Several bands of 8192 for the threads to race over (fewer seeds with the label's
          // own variables only).
          const bool label_only =
              seeds == NearSeeds::label || (seeds == NearSeeds::label_and_adjacent && !adjacent_on);
          const std::size_t bands = label_only ? 1 : 2;
          REQUIRE(expected[alpha].size() > bands * detail::kBandSize);
        }
        ExpansionOptions asked;
        asked.near_radius = radius;
        asked.near_seeds = seeds;
        for (int threads = 1; threads <= 3; ++threads) {
          detail::NearMoves near;
          near.bind(energy, radius, near_seeds_in_use(asked, energy), nullptr, threads);
          // Each label twice, in turn: a move's marks must not leak into the next.
          for (const Label alpha : {0, 1, 2, 2, 0, 1}) {
            near.build(alpha, x);
            INFO(num_labels << " labels, radius " << radius << ", seeds " << to_string(seeds)
                            << ", alpha " << alpha << ", " << threads << " threads");
            CHECK(std::vector<VariableIndex>(near.free().begin(), near.free().end()) ==
                  expected[alpha]);
          }
        }
      }
    }
  }
}

TEMPLATE_TEST_CASE("expansion with near moves descends to labelings no whole move improves",
                   "[expansion][near][brute-force]", C2F_MAXFLOW_BACKENDS) {
  Rng rng(4242);
  for (int trial = 0; trial < 60; ++trial) {
    // label_and_adjacent on 16 labels, where its neighbouring labels seed.
    const bool adjacent = trial % 5 == 4;
    const int num_labels = adjacent ? kMinLabelsForAdjacentSeeds : 2 + trial % 4;
    const PairwiseEnergy energy =
        trial % 2 == 0
            ? random_grid_energy(rng, 6, 5, num_labels)
            : tiny_model(rng, trial % 3, num_labels,
                         test_terms(rng, num_labels)[static_cast<std::size_t>(trial) % 4]);
    ExpansionOptions options;
    options.near_radius = 1 + trial % 3;
    options.near_sweep_gain = trial % 3 == 0 ? 0.0 : 1e-3;
    options.near_seeds = adjacent        ? NearSeeds::label_and_adjacent
                         : trial % 5 < 2 ? NearSeeds::label
                                         : NearSeeds::label_and_cheapest;
    options.order = trial % 4 == 1 ? VisitOrder::random : VisitOrder::sequential;
    options.seed = static_cast<std::uint64_t>(trial);
    ExpansionSolver<TestType> solver(options);
    REQUIRE(solver.quiet_steps_to_converge(energy) == 3 * static_cast<std::size_t>(num_labels));
    solver.bind(energy, random_labeling(rng, energy.num_variables(), num_labels));
    double previous = 0.0;
    std::size_t near_steps = 0;
    const std::size_t quiet =
        descend(solver, energy, solver.quiet_steps_to_converge(energy), 3000, previous,
                [&](const auto& s) { near_steps += s.last_step().near; });
    REQUIRE(quiet == solver.quiet_steps_to_converge(energy));
    CHECK(near_steps >= static_cast<std::size_t>(num_labels));
    // Converged: one sweep of whole moves from the result finds nothing lower.
    ExpansionSolver<TestType> whole;
    whole.bind(energy, solver.labeling());
    for (int step = 0; step < num_labels; ++step) CHECK(whole.step() == previous);
    if (energy.num_variables() <= 10 && !adjacent)
      CHECK(previous >= brute_force_minimum(energy).energy - 1e-9);
  }
}

TEST_CASE("near moves are validated and belong to expansion", "[expansion][near][validation]") {
  ExpansionOptions options;
  options.near_radius = -1;
  CHECK_THROWS_WITH(ExpansionSolver<>(options), Catch::Contains("near_radius"));
  options.near_radius = 2;
  options.near_sweep_gain = -1.0;
  CHECK_THROWS_WITH(ExpansionSolver<>(options), Catch::Contains("near_sweep_gain"));
  CHECK(near_seeds_from_string("label") == NearSeeds::label);
  for (const NearSeeds seeds :
       {NearSeeds::label_and_cheapest, NearSeeds::label, NearSeeds::label_and_adjacent})
    CHECK(near_seeds_from_string(to_string(seeds)) == seeds);
  CHECK_THROWS_WITH(near_seeds_from_string("cheapest"), Catch::Contains("cheapest"));
  Rng rng(3);
  CHECK(ExpansionSolver<>().quiet_steps_to_converge(random_grid_energy(rng, 3, 2, 7)) == 7);
}

TEST_CASE("expansion with near moves recycles no move graphs", "[expansion][near][memory]") {
  Rng rng(8);
  const PairwiseEnergy energy = random_grid_energy(rng, 12, 10, 4);
  const Labeling start = random_labeling(rng, energy.num_variables(), 4);
  ExpansionOptions near;
  near.near_radius = 2;
  near.near_sweep_gain = 1.0;  // every near sweep hands over to a whole sweep
  ExpansionOptions whole;
  CHECK(recycled_graph_limit(near) == 0);
  CHECK(recycled_graph_limit(whole) == whole.graph_memory_limit);
  const ProblemSize size = problem_size(energy);
  CHECK(wanted_graph_bytes(near, size, GraphStorage::arrays) == 0);
  CHECK(wanted_graph_bytes(whole, size, GraphStorage::arrays) > 0);
  // Whole moves recycle each label's graph from its second move on; near runs recycle none.
  const auto recycled_steps = [&](const ExpansionOptions& options) {
    ExpansionSolver<> solver(options);
    solver.bind(energy, start);
    int recycled = 0;
    for (int step = 0; step < 6 * 4; ++step) {
      solver.step();
      recycled += solver.last_step().recycled;
    }
    return recycled;
  };
  CHECK(recycled_steps(whole) > 0);
  CHECK(recycled_steps(near) == 0);
  // Asked for (with each label's first move on a graph of its own, as CoopSolver asks), the
  // whole sweeps between near sweeps resume their graphs, and the path is the same.
  ExpansionOptions near_recycling = near;
  near_recycling.recycle_with_near_moves = true;
  near_recycling.first_move_own_graph = true;
  CHECK(recycled_graph_limit(near_recycling) == near_recycling.graph_memory_limit);
  CHECK(wanted_graph_bytes(near_recycling, size, GraphStorage::arrays) ==
        wanted_graph_bytes(whole, size, GraphStorage::arrays));
  CHECK(recycled_steps(near_recycling) > 0);
  const auto energies = [&](const ExpansionOptions& options) {
    ExpansionSolver<> solver(options);
    solver.bind(energy, start);
    std::vector<double> out;
    for (int step = 0; step < 6 * 4; ++step) out.push_back(solver.step());
    return out;
  };
  ExpansionOptions near_own_graph = near;
  near_own_graph.first_move_own_graph = true;
  const std::vector<double> fresh = energies(near_own_graph), resumed = energies(near_recycling);
  REQUIRE(fresh.size() == resumed.size());
  for (std::size_t k = 0; k < fresh.size(); ++k) {
    INFO("step " << k);
    CHECK(resumed[k] == Approx(fresh[k]).epsilon(1e-12));
  }
}

TEST_CASE("a step reports the variables its move worked over", "[expansion][near]") {
  // 40 x 30 pixels, 4 labels: near moves of radius 2 from their label, then whole sweeps.
  Rng rng(12);
  const PairwiseEnergy energy = random_grid_energy(rng, 40, 30, 4);
  const std::size_t n = energy.num_variables();
  ExpansionOptions options;
  options.near_radius = 2;
  options.near_seeds = NearSeeds::label;
  ExpansionSolver<> solver(options);
  solver.bind(energy, random_labeling(rng, n, 4));
  std::size_t near_steps = 0, whole_steps = 0;
  for (int step = 0; step < 40; ++step) {
    const Labeling before(solver.labeling().begin(), solver.labeling().end());
    solver.step();
    const MoveStep& last = solver.last_step();
    if (!last.near) {
      CHECK(last.variables == n);
      ++whole_steps;
      continue;
    }
    // Brute force: the variables within 2 edges of one labelled alpha, not labelled alpha.
    std::vector<int> distance(n, 1 << 20);
    for (std::size_t v = 0; v < n; ++v)
      if (before[v] == last.alpha) distance[v] = 0;
    for (int round = 0; round < 2; ++round) {
      std::vector<int> next = distance;
      for (const Edge& edge : energy.edges()) {
        next[edge.u] = std::min(next[edge.u], distance[edge.v] + 1);
        next[edge.v] = std::min(next[edge.v], distance[edge.u] + 1);
      }
      distance = next;
    }
    std::size_t free = 0;
    for (std::size_t v = 0; v < n; ++v) free += distance[v] <= 2 && before[v] != last.alpha;
    CHECK(last.variables == free);
    CHECK(last.variables < n);
    ++near_steps;
  }
  CHECK(near_steps > 0);
  CHECK(whole_steps > 0);
}

TEST_CASE("near moves only where the edges are local, when asked", "[expansion][near]") {
  Rng rng(21);
  // A 64 x 64 grid: 3 x 64 of its 8064 edges join the four bands of 16 rows.
  const PairwiseEnergy grid = random_grid_energy(rng, 64, 64, 4);
  // 4096 variables joined at random: about three quarters of the edges join different bands.
  const PairwiseEnergy random = random_energy(rng, 4096, 4, 8192);
  CHECK(edges_local(grid));
  CHECK_FALSE(edges_local(random));
  CHECK(share_of_edges_between_parts(grid, kDefaultFlowParts) ==
        Approx(3.0 * 64.0 / 8064.0).epsilon(1e-12));

  ExpansionOptions near;
  near.near_radius = 2;
  ExpansionOptions local = near;
  local.near_moves_only_if_local = true;
  CHECK(makes_near_moves(near, random));
  CHECK(makes_near_moves(local, grid));
  CHECK_FALSE(makes_near_moves(local, random));
  CHECK_FALSE(makes_near_moves(ExpansionOptions{}, grid));
  CHECK(near_only_if_local_from_string(near_graphs_name(true)));
  CHECK_FALSE(near_only_if_local_from_string(near_graphs_name(false)));
  CHECK_THROWS_WITH(near_only_if_local_from_string("grids"),
                    Catch::Contains("'grids'") && Catch::Contains("local or any"));

  // On the random graph the solver asked for near moves only where local makes whole moves,
  // step for step as without near moves (recycling each label's graph); on the grid, near moves
  // as without the condition.
  const auto trace = [](const PairwiseEnergy& energy, const ExpansionOptions& options,
                        const Labeling& start) {
    ExpansionSolver<> solver(options);
    solver.bind(energy, start);
    std::vector<double> energies;
    std::size_t near_steps = 0, recycled = 0;
    for (std::size_t step = 0; step < 3 * solver.quiet_steps_to_converge(energy); ++step) {
      energies.push_back(solver.step());
      near_steps += solver.last_step().near;
      recycled += solver.last_step().recycled;
    }
    return std::tuple(energies, near_steps, recycled);
  };
  const Labeling random_start = random_labeling(rng, random.num_variables(), 4);
  const auto [asked, asked_near, asked_recycled] = trace(random, local, random_start);
  const auto [whole, whole_near, whole_recycled] = trace(random, ExpansionOptions{}, random_start);
  CHECK(asked == whole);
  CHECK(asked_near == 0);
  CHECK(asked_recycled == whole_recycled);
  CHECK(ExpansionSolver<>(local).quiet_steps_to_converge(random) == 4);
  const Labeling grid_start = random_labeling(rng, grid.num_variables(), 4);
  const auto [on_grid, grid_near, grid_recycled] = trace(grid, local, grid_start);
  const auto [plain, plain_near, plain_recycled] = trace(grid, near, grid_start);
  CHECK(on_grid == plain);
  CHECK(grid_near == plain_near);
  CHECK(grid_near > 0);
  CHECK(ExpansionSolver<>(local).quiet_steps_to_converge(grid) == 12);

  // Near moves only on an energy of at least near_moves_min_variables variables: on a smaller
  // one, whole moves step for step (recycling included).
  ExpansionOptions sized = near;
  sized.near_moves_min_variables = grid.num_variables();
  CHECK(makes_near_moves(sized, grid));
  sized.near_moves_min_variables = grid.num_variables() + 1;
  CHECK_FALSE(makes_near_moves(sized, grid));
  const auto [small, small_near, small_recycled] = trace(grid, sized, grid_start);
  const auto [grid_whole, grid_whole_near, grid_whole_recycled] =
      trace(grid, ExpansionOptions{}, grid_start);
  CHECK(small == grid_whole);
  CHECK(small_near == 0);
  CHECK(small_recycled == grid_whole_recycled);
  CHECK(ExpansionSolver<>(sized).quiet_steps_to_converge(grid) == 4);
}

TEST_CASE("label_and_adjacent seeds as label where shift moves are made or labels are few",
          "[expansion][near]") {
  Rng rng(31);
  // Every step's energy and freed variables, from one start, over three label sweeps.
  const auto trace = [](const PairwiseEnergy& energy, const ExpansionOptions& options,
                        const Labeling& start) {
    ExpansionSolver<> solver(options);
    solver.bind(energy, start);
    std::vector<std::pair<double, std::size_t>> steps;
    for (int step = 0; step < 3 * energy.num_labels(); ++step) {
      const double value = solver.step();
      steps.emplace_back(value, solver.last_step().variables);
    }
    return steps;
  };
  ExpansionOptions label;
  label.near_radius = 1;
  label.near_seeds = NearSeeds::label;
  ExpansionOptions adjacent = label;
  adjacent.near_seeds = NearSeeds::label_and_adjacent;
  for (const int num_labels : {4, kMinLabelsForAdjacentSeeds}) {
    const PairwiseEnergy energy = random_grid_energy(rng, 30, 20, num_labels);
    const Labeling start = random_labeling(rng, energy.num_variables(), num_labels);
    INFO(num_labels << " labels");
    // With shift moves (which move a region one label off as a whole), the same steps.
    ExpansionOptions label_shift = label, adjacent_shift = adjacent;
    label_shift.shift_moves = adjacent_shift.shift_moves = true;
    CHECK(trace(energy, adjacent_shift, start) == trace(energy, label_shift, start));
    // Without them, the same steps on fewer than 16 labels; on 16, a near move frees more.
    const auto with_adjacent = trace(energy, adjacent, start);
    const auto with_label = trace(energy, label, start);
    if (num_labels < kMinLabelsForAdjacentSeeds) {
      CHECK(with_adjacent == with_label);
    } else {
      CHECK(with_adjacent.front().second > with_label.front().second);
    }
  }
}

TEST_CASE("near_seeds_in_use narrows label_and_adjacent where it does not apply",
          "[expansion][near]") {
  Rng rng(37);
  // A 6 x 5 grid of `labels` labels with random unaries and the pairwise term `term`.
  const auto grid = [&rng](int labels, PairwiseTerm term) {
    const std::size_t width = 6, height = 5, n = width * height;
    std::vector<double> unaries(n * static_cast<std::size_t>(labels));
    for (double& u : unaries) u = std::uniform_real_distribution<double>(0.0, 2.0)(rng);
    std::vector<Edge> edges;
    for (std::size_t y = 0; y < height; ++y) {
      for (std::size_t x = 0; x < width; ++x) {
        const auto v = static_cast<VariableIndex>(y * width + x);
        if (x + 1 < width) edges.push_back({v, v + 1, 0.5, 0});
        if (y + 1 < height) edges.push_back({v, static_cast<VariableIndex>(v + width), 0.5, 0});
      }
    }
    return PairwiseEnergy(n, labels, std::move(unaries), {std::move(term)}, std::move(edges));
  };
  const int many_labels = kMinLabelsForAdjacentSeeds;
  const PairwiseEnergy few = grid(many_labels - 1, PairwiseTerm::truncated_linear(4.0));
  const PairwiseEnergy many = grid(many_labels, PairwiseTerm::truncated_linear(4.0));
  // Truncated quadratic: some expansion move is not submodular.
  std::vector<double> quadratic(static_cast<std::size_t>(many_labels * many_labels));
  for (int a = 0; a < many_labels; ++a)
    for (int b = 0; b < many_labels; ++b)
      quadratic[static_cast<std::size_t>(a * many_labels + b)] = std::min((a - b) * (a - b), 9);
  const PairwiseEnergy not_submodular =
      grid(many_labels, PairwiseTerm::table(many_labels, quadratic));
  REQUIRE(expansion_moves_submodular(many));
  REQUIRE_FALSE(expansion_moves_submodular(not_submodular));

  ExpansionOptions options;
  options.near_radius = 2;
  options.near_seeds = NearSeeds::label_and_adjacent;
  CHECK(near_seeds_in_use(options, many) == NearSeeds::label_and_adjacent);
  CHECK(near_seeds_in_use(options, few) == NearSeeds::label);
  CHECK(near_seeds_in_use(options, not_submodular) == NearSeeds::label_and_adjacent);
  options.shift_moves_unless_submodular = true;
  CHECK(near_seeds_in_use(options, many) == NearSeeds::label_and_adjacent);
  CHECK(near_seeds_in_use(options, not_submodular) == NearSeeds::label);
  options.shift_moves = true;
  CHECK(near_seeds_in_use(options, many) == NearSeeds::label);
  // The other seeds are used as asked, on any energy.
  for (const NearSeeds seeds : {NearSeeds::label, NearSeeds::label_and_cheapest}) {
    options.near_seeds = seeds;
    for (const PairwiseEnergy* energy : {&few, &many, &not_submodular})
      CHECK(near_seeds_in_use(options, *energy) == seeds);
  }
}

// A run's memory budget: how it is chosen and reported, and how it is split between the run's
// floor and the recycled move graphs.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "c2f/adapters/run_memory.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/core/memory_need.hpp"
#include "support/random_models.hpp"

using namespace c2f;

TEST_CASE("the default budget is a quarter of the machine, growing to a run's needs up to half",
          "[memory]") {
  const MemoryBudget budget = default_memory_budget();
  const auto available = available_memory_bytes();
  REQUIRE(available.has_value());
  CHECK(budget.bytes > 0);
  CHECK(budget.bytes <= budget.ceiling());
  CHECK(budget.ceiling() <= *available);
  CHECK_THAT(budget.describe(), Catch::Contains(" GiB (") || Catch::Contains(" MiB ("));
  // A growing budget takes a run's needs up to its ceiling, and says so.
  const MemoryBudget growing{std::size_t{1} << 30, "a share", std::size_t{3} << 30};
  CHECK(growing.describe() == "1.0 GiB (a share; a run that needs more may take up to 3.0 GiB)");
  CHECK(growing.for_need(std::size_t{1} << 20) == std::size_t{1} << 30);
  CHECK(growing.for_need(std::size_t{2} << 30) == std::size_t{2} << 30);
  CHECK(growing.for_need(std::size_t{5} << 30) == std::size_t{3} << 30);
  CHECK_NOTHROW(growing.require_within("a run", std::size_t{2} << 30));
  CHECK_THROWS_WITH(growing.require_within("a big run", std::size_t{4} << 30),
                    Catch::Contains("a big run needs 4.0 GiB, more than the run's memory budget "
                                    "of 1.0 GiB (a share; a run that needs more may take up to "
                                    "3.0 GiB)"));
  const MemoryBudget two = memory_budget_of_gib(2.0, "--memory 2");
  CHECK(two.bytes == std::size_t{2} << 30);
  CHECK(two.describe() == "2.0 GiB (--memory 2)");
  for (const double bad : {0.0, -1.0, std::nan(""), std::numeric_limits<double>::infinity()}) {
    CHECK_THROWS_WITH(memory_budget_of_gib(bad, "--memory x"),
                      Catch::StartsWith("--memory x: the memory budget must be"));
  }
  CHECK_THROWS_WITH(two.require_within("a big run", std::size_t{3} << 30),
                    "a big run needs 3.0 GiB, more than the run's memory budget of 2.0 GiB "
                    "(--memory 2)");
  CHECK_THROWS_WITH(two.require_within("an overflowing run", std::nullopt),
                    Catch::Contains("needs more than 16 EiB"));
  CHECK_NOTHROW(two.require("a small run", std::size_t{1} << 20));
}

TEST_CASE("the recycled graphs get what the budget leaves above the run's floor", "[memory]") {
  test::Rng rng(8);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 30, 20, 6);
  CHECK(energy_memory_bytes(energy) >=
        energy.unaries().bytes() + energy.edges().size() * sizeof(Edge));
  SolverChoice choice;
  choice.graph_memory_limit = std::numeric_limits<std::size_t>::max();
  const ProblemSize size = problem_size(energy);
  const auto floor = run_memory_floor(choice, size);
  REQUIRE(floor.has_value());
  // Near and shift moves add a second solver's working memory.
  SolverChoice near = choice;
  near.near_radius = 3;
  CHECK(*run_memory_floor(near, size) > *floor);
  // The grid estimate before building matches the built energy's sizes.
  const auto predicted = grid_problem_size(30, 20, 6, CostStorage::double_precision);
  REQUIRE(predicted.has_value());
  CHECK(predicted->variables == size.variables);
  CHECK(predicted->edges == size.edges);
  CHECK_FALSE(grid_problem_size(std::size_t{1} << 40, std::size_t{1} << 30, 256,
                                CostStorage::double_precision));
  // Float unaries: the energy's own bytes as predicted, half the double energy's unaries.
  const std::vector<double> table(36, 1.0);
  const PairwiseEnergy single = PairwiseEnergy::with_float_unaries(
      600, 6, c2f::FloatValues(3600, 0.5f), {PairwiseTerm::table(6, table)},
      grid_edges({30, 20}, Connectivity::four, [](VariableIndex, VariableIndex) { return 1.0; }));
  const auto single_predicted = grid_problem_size(30, 20, 6, CostStorage::single_precision);
  REQUIRE(single_predicted.has_value());
  CHECK(single_predicted->energy_bytes + sizeof(PairwiseTerm) >= energy_memory_bytes(single));
  CHECK(grid_problem_size(30, 20, 6, CostStorage::double_precision)->energy_bytes ==
        single_predicted->energy_bytes + 3600 * sizeof(float));
  CHECK(energy_memory_bytes(single) + 3600 * sizeof(float) ==
        energy_memory_bytes(
            PairwiseEnergy(600, 6, std::vector<double>(3600, 0.5), {PairwiseTerm::table(6, table)},
                           std::vector<Edge>(single.edges().begin(), single.edges().end()))));

  const MemoryBudget budget{*floor + 12345, "a test"};
  const SolverChoice fitted = fit_to_budget(choice, size, budget, "the run");
  CHECK(fitted.graph_memory_limit == 12345);
  // No limit of its own: unfitted, the solvers get MoveOptions' default; fitted, what the
  // budget leaves.
  const SolverChoice unset;
  CHECK(unset.expansion_options().graph_memory_limit == MoveOptions{}.graph_memory_limit);
  const MemoryBudget roomy{*floor + MoveOptions{}.graph_memory_limit + 1, "a test"};
  CHECK(fit_to_budget(unset, size, roomy, "the run").expansion_options().graph_memory_limit ==
        MoveOptions{}.graph_memory_limit + 1);
  CHECK(fit_to_budget(unset, size, budget, "the run").swap_options().graph_memory_limit == 12345);
  choice.graph_memory_limit = 100;  // a smaller limit given stays
  CHECK(fit_to_budget(choice, size, budget, "the run").graph_memory_limit == 100);
  const MemoryBudget small{*floor - 1, "a test"};
  CHECK_THROWS_WITH(
      fit_to_budget(choice, size, small, "the run"),
      Catch::StartsWith("the run needs ") &&
          Catch::EndsWith("more than the run's memory budget of " + small.describe()));
}

TEST_CASE("a coarse level is solved when its reduced energy and solver fit the room left",
          "[memory]") {
  test::Rng rng(9);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 30, 20, 6);
  const ProblemSize size = problem_size(energy);
  SolverChoice choice;
  choice.graph_memory_limit = std::numeric_limits<std::size_t>::max();
  const auto floor = run_memory_floor(choice, size);
  REQUIRE(floor.has_value());
  // The level's reduced energy (double unaries, at most the original's edges), its solver and
  // its recycled graphs (none here: a limit of 0).
  choice.graph_memory_limit = 0;
  const auto level = coarse_level_memory(choice, size, 50);
  REQUIRE(level.has_value());
  const auto solver_alone = coarse_level_memory(choice, size, 0);
  REQUIRE(solver_alone.has_value());
  CHECK(*level - *solver_alone >= 50 * 6 * sizeof(double));
  CHECK(*coarse_level_memory(choice, size, 600) > *level);
  // Unfitted: every level is admitted.
  CHECK(coarse_level_admission(choice, size)(600));
  // Fitted with all the budget to the graphs, the room is the original solver's share and the
  // graphs': small levels fit, a level as large as the original does not (its reduced energy
  // comes on top).
  choice.graph_memory_limit = std::numeric_limits<std::size_t>::max();
  const SolverChoice fitted = fit_to_budget(choice, size, MemoryBudget{*floor + 4096, "t"}, "run");
  CHECK(*coarse_level_memory(fitted, size, 50) > *level);  // with its graphs
  const auto fits = coarse_level_admission(fitted, size);
  CHECK(fits(50));
  CHECK_FALSE(fits(600));
  // A smaller graph limit leaves the rest of the budget to coarse levels too.
  SolverChoice capped = choice;
  capped.graph_memory_limit = 0;
  const auto roomy = coarse_level_admission(
      fit_to_budget(capped, size, MemoryBudget{*floor + *level * 4, "t"}, "run"), size);
  CHECK(roomy(600));
  // Near moves on the original problem only: the coarse solver has no second solver.
  SolverChoice near = choice;
  near.graph_memory_limit = 0;
  near.near_radius = 3;
  CHECK(coarse_level_memory(near, size, 50) == level);
  near.near_levels = NearLevels::all;
  CHECK(*coarse_level_memory(near, size, 50) > *level);
}

TEST_CASE("a grid run needs the larger of its preparation and its floor", "[memory]") {
  SolverChoice choice;
  const auto floor =
      run_memory_floor(choice, *grid_problem_size(30, 20, 6, CostStorage::double_precision));
  REQUIRE(floor);
  CHECK(grid_run_memory_need(choice, 30, 20, 6, CostStorage::double_precision, 0) == floor);
  CHECK(grid_run_memory_need(choice, 30, 20, 6, CostStorage::double_precision, *floor + 1) ==
        *floor + 1);
  // An overflowing preparation or grid is "beyond std::size_t", never a small number.
  CHECK_FALSE(grid_run_memory_need(choice, 30, 20, 6, CostStorage::double_precision, std::nullopt));
  CHECK_FALSE(grid_run_memory_need(choice, std::size_t{1} << 40, std::size_t{1} << 30, 256,
                                   CostStorage::single_precision, 0));
}

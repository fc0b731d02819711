// A run's memory budget: how it is chosen and reported, what each solver says it works in, and
// how the run layer splits the budget between the run's floor, the recycled move graphs and
// coarse levels.

#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/core/memory_budget.hpp"
#include "c2f/run/memory_plan.hpp"
#include "c2f/support/memory_need.hpp"
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

namespace {

/// Expansion with near moves of radius 3 on the levels `levels` says.
SolverSpec near_expansion(NearLevels levels) {
  ExpansionOptions options;
  options.near_radius = 3;
  return expansion_spec(options, levels);
}

}  // namespace

TEST_CASE("each solver states its working memory, and the floor adds the energy's",
          "[memory][run]") {
  test::Rng rng(8);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 30, 20, 6);
  const ProblemSize size = problem_size(energy);
  CHECK(size.variables == 600);
  CHECK(size.labels == 6);
  CHECK(size.energy_bytes == energy_memory_bytes(energy));
  // Graph cuts: 300 bytes per variable and 240 per edge per binary-move solver, twice that for
  // adjacency lists; near or shift moves add a second solver.
  const std::size_t one = 600 * 300 + energy.edges().size() * 240;
  CHECK(move_solver_bytes(size, GraphStorage::arrays) == one);
  CHECK(move_solver_bytes(size, GraphStorage::adjacency_lists) == 2 * one);
  ExpansionOptions near;
  near.near_radius = 3;
  // Expansion also tallies each move's energy with the energy's edge incidences.
  const std::size_t incidences =
      600 * sizeof(std::size_t) + energy.edges().size() * 2 * sizeof(Incidence);
  CHECK(working_memory_bytes(ExpansionOptions{}, size, GraphStorage::arrays) == one + incidences);
  CHECK(working_memory_bytes(near, size, GraphStorage::arrays) == 2 * one + incidences);
  CHECK(working_memory_bytes(SwapOptions{}, size, GraphStorage::arrays) == one);
  CHECK(wanted_graph_bytes(ExpansionOptions{}, size, GraphStorage::arrays) == 6 * one);
  CHECK(wanted_graph_bytes(SwapOptions{}, size, GraphStorage::arrays) == 21 * one);
  CHECK(working_memory_bytes(LbpOptions{}, size) ==
        (energy.edges().size() * 4 + 600 * 3) * 6 * sizeof(double));
  CHECK(working_memory_bytes(IcmOptions{}, size) == 600 * 16);
  CHECK_FALSE(move_solver_bytes({std::size_t{1} << 62, 2, 0, 0}, GraphStorage::arrays));
  // The run layer asks the spec's solver on its backend.
  CHECK(working_memory_bytes(SolverOptions{SwapOptions{}}, MaxFlowKind::boost, size) == 2 * one);
  CHECK(working_memory_bytes(SolverOptions{IcmOptions{}}, MaxFlowKind::dynamic, size) == 600 * 16);

  const auto floor = run_memory_floor(SolverSpec{}, size);
  REQUIRE(floor.has_value());
  CHECK(*floor == (std::size_t{128} << 20) + size.energy_bytes + 600 * 64 + one + incidences);
  CHECK(*run_memory_floor(near_expansion(NearLevels::original), size) == *floor + one);
}

TEST_CASE("the recycled graphs get what the budget leaves above the run's floor", "[memory][run]") {
  test::Rng rng(8);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 30, 20, 6);
  CHECK(energy_memory_bytes(energy) >=
        energy.unaries().bytes() + energy.edges().size() * sizeof(Edge));
  const SolverSpec spec;
  const ProblemSize size = problem_size(energy);
  const auto floor = run_memory_floor(spec, size);
  REQUIRE(floor.has_value());
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

  // Too little above the floor for the kept move problems (6 x (600 + 1150) doubles): the
  // recycled graphs get it all.
  const std::size_t problems = 6 * (600 + energy.edges().size()) * sizeof(double);
  CHECK(kept_problem_bytes(ExpansionOptions{}, size) == problems);
  const MemoryBudget budget{*floor + 12345, "a test"};
  const MemoryPlan plan = plan_memory(spec, size, budget, std::nullopt, "the run");
  CHECK(plan.floor == *floor);
  CHECK(plan.budget == *floor + 12345);
  CHECK(plan.problem_memory == 0);
  CHECK(plan.graph_memory == 12345);
  // Room for them: the problems first, the graphs all the rest (beyond MoveOptions' default
  // too, when the run sets no limit).
  const MemoryBudget roomy{*floor + problems + MoveOptions{}.graph_memory_limit + 1, "a test"};
  const MemoryPlan roomy_plan = plan_memory(spec, size, roomy, std::nullopt, "the run");
  CHECK(roomy_plan.problem_memory == problems);
  CHECK(roomy_plan.graph_memory == MoveOptions{}.graph_memory_limit + 1);
  // A small graph limit given stays, and never drops the kept problems.
  const MemoryPlan capped = plan_memory(spec, size, roomy, 100, "the run");
  CHECK(capped.graph_memory == 100);
  CHECK(capped.problem_memory == problems);
  // Swap keeps no problems. The spec's options get the plan's limits on every level.
  CHECK(plan_memory(SolverSpec{MaxFlowKind::dynamic, SwapOptions{}}, size, roomy, std::nullopt,
                    "the run")
            .problem_memory == 0);
  const SolverSpec limited = with_memory_plan(near_expansion(NearLevels::original), capped);
  for (const SolverOptions& options : {limited.original, limited.coarse_options()}) {
    CHECK(std::get<ExpansionOptions>(options).graph_memory_limit == 100);
    CHECK(std::get<ExpansionOptions>(options).problem_memory_limit == problems);
  }
  // A default budget grows to the floor up to its ceiling.
  const MemoryBudget growing{*floor / 2, "a share", *floor * 2};
  CHECK(plan_memory(spec, size, growing, std::nullopt, "the run").budget == *floor);
  const MemoryBudget small{*floor - 1, "a test"};
  CHECK_THROWS_WITH(
      plan_memory(spec, size, small, std::nullopt, "the run"),
      Catch::StartsWith("the run needs ") &&
          Catch::EndsWith("more than the run's memory budget of " + small.describe()));
}

TEST_CASE("a coarse level is solved when its reduced energy and solver fit the room left",
          "[memory][run]") {
  test::Rng rng(9);
  const PairwiseEnergy energy = test::random_grid_energy(rng, 30, 20, 6);
  const ProblemSize size = problem_size(energy);
  const SolverSpec spec;
  const auto floor = run_memory_floor(spec, size);
  REQUIRE(floor.has_value());
  // The level's reduced energy (double unaries, at most the original's edges), its solver and
  // its recycled graphs (none here: a limit of 0).
  const auto level = coarse_level_memory(spec, size, 50, 0);
  REQUIRE(level.has_value());
  const auto solver_alone = coarse_level_memory(spec, size, 0, 0);
  REQUIRE(solver_alone.has_value());
  CHECK(*level - *solver_alone >= 50 * 6 * sizeof(double));
  CHECK(*coarse_level_memory(spec, size, 600, 0) > *level);
  // Planned with all the budget to the graphs, the room is the original solver's share and the
  // graphs': small levels fit, a level as large as the original does not (its reduced energy
  // comes on top).
  const MemoryPlan plan =
      plan_memory(spec, size, MemoryBudget{*floor + 4096, "t"}, std::nullopt, "run");
  CHECK(*coarse_level_memory(spec, size, 50, plan.graph_memory) > *level);  // with its graphs
  const auto fits = coarse_level_admission(spec, size, plan);
  CHECK(fits(50));
  CHECK_FALSE(fits(600));
  // A smaller graph limit leaves the rest of the budget to coarse levels too.
  const auto roomy = coarse_level_admission(
      spec, size, plan_memory(spec, size, MemoryBudget{*floor + *level * 4, "t"}, 0, "run"));
  CHECK(roomy(600));
  // Near moves on the original problem only: the coarse solver has no second solver.
  CHECK(coarse_level_memory(near_expansion(NearLevels::original), size, 50, 0) == level);
  CHECK(*coarse_level_memory(near_expansion(NearLevels::all), size, 50, 0) > *level);
}

TEST_CASE("a grid run needs the larger of its preparation and its floor", "[memory][run]") {
  const SolverSpec spec;
  const auto floor =
      run_memory_floor(spec, *grid_problem_size(30, 20, 6, CostStorage::double_precision));
  REQUIRE(floor);
  CHECK(grid_run_memory_need(spec, 30, 20, 6, CostStorage::double_precision, 0) == floor);
  CHECK(grid_run_memory_need(spec, 30, 20, 6, CostStorage::double_precision, *floor + 1) ==
        *floor + 1);
  // An overflowing preparation or grid is "beyond std::size_t", never a small number.
  CHECK_FALSE(grid_run_memory_need(spec, 30, 20, 6, CostStorage::double_precision, std::nullopt));
  CHECK_FALSE(grid_run_memory_need(spec, std::size_t{1} << 40, std::size_t{1} << 30, 256,
                                   CostStorage::single_precision, 0));
}

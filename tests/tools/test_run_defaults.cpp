// The tools' flags default to the library's RunDefaults: one definition for the tools, the C++
// API and Python (python/tests compares Python with the tools).

#include <catch2/catch.hpp>

#include <variant>
#include <vector>

#include "c2f/adapters/graphcut/move_options.hpp"
#include "c2f/lift/schedule.hpp"
#include "c2f/run/defaults.hpp"
#include "c2f/run/stereo_run.hpp"
#include "run_flags.hpp"
#include "support/random_models.hpp"
#include "tool_options.hpp"

using namespace c2f;
using c2f::test::Rng;

namespace {

/// The RunConfig a tool's RunFlags give with `arguments` on the command line, for an energy
/// on a pixel grid (on_grid) or not.
RunConfig config_with_flags(const RunDefaults& defaults, std::vector<const char*> arguments,
                            bool on_grid = true) {
  examples::RunFlags flags(defaults);
  examples::ToolOptions options("test");
  flags.declare(options);
  arguments.insert(arguments.begin(), "tool");
  REQUIRE(options.parse(static_cast<int>(arguments.size()), arguments.data(), {"", 0}).has_value());
  return flags.config(on_grid);
}

/// The RunConfig a tool's RunFlags give with no flag on the command line.
RunConfig config_without_flags(const RunDefaults& defaults, bool on_grid = true) {
  return config_with_flags(defaults, {}, on_grid);
}

/// The original problem's expansion options of `config`.
const ExpansionOptions& original_expansion(const RunConfig& config) {
  const auto* options = std::get_if<ExpansionOptions>(&config.solver.original);
  REQUIRE(options != nullptr);
  return *options;
}

}  // namespace

TEST_CASE("the run flags' defaults are the library's RunDefaults", "[tools][defaults]") {
  // And defaults whose near moves differ from both in every near-move setting, so that every
  // near-move flag's default comes from RunDefaults too.
  RunDefaults other_near = pairwise_defaults();
  other_near.near_radius = 2;
  other_near.near_seeds = NearSeeds::label_and_cheapest;
  other_near.near_moves_only_if_local = false;
  other_near.near_moves_min_variables = 1000;
  for (const RunDefaults& defaults : {pairwise_defaults(), vision::stereo_defaults(), other_near})
    for (const bool on_grid : {true, false}) {
      INFO("on a grid: " << on_grid);
      const RunConfig expected = defaults.config(on_grid);
      const RunConfig flags = config_without_flags(defaults, on_grid);
      const auto* want = std::get_if<ExpansionOptions>(&expected.solver.original);
      const auto* got = std::get_if<ExpansionOptions>(&flags.solver.original);
      REQUIRE(want != nullptr);
      REQUIRE(got != nullptr);
      CHECK(*got == *want);
      CHECK(got->near_radius == defaults.near_radius);
      CHECK(got->near_seeds == defaults.near_seeds_on(on_grid));
      CHECK(got->near_moves_only_if_local == defaults.near_moves_only_if_local);
      CHECK(got->near_moves_min_variables == defaults.near_moves_min_variables);
      CHECK(got->shift_moves == defaults.shift_moves);
      CHECK(flags.solver.coarse == expected.solver.coarse);
      CHECK(flags.solver.maxflow == expected.solver.maxflow);
      CHECK(flags.limits.plateau_steps == expected.limits.plateau_steps);
      CHECK(flags.limits.plateau_tolerance == expected.limits.plateau_tolerance);
      CHECK(flags.limits.time_limit_seconds == expected.limits.time_limit_seconds);
      CHECK(flags.limits.max_total_steps == expected.limits.max_total_steps);
    }
  // The pairwise defaults start near moves elsewhere on a grid; a named --near-seeds is kept.
  const RunDefaults pairwise = pairwise_defaults();
  CHECK(pairwise.near_seeds_on(true) == NearSeeds::label_and_adjacent);
  CHECK(pairwise.near_seeds_on(false) == NearSeeds::label);
  for (const bool on_grid : {true, false}) {
    CHECK(original_expansion(config_with_flags(pairwise, {"--near-seeds", "label"}, on_grid))
              .near_seeds == NearSeeds::label);
    CHECK(original_expansion(
              config_with_flags(pairwise, {"--near-seeds", "label_and_adjacent"}, on_grid))
              .near_seeds == NearSeeds::label_and_adjacent);
  }
  CHECK_THROWS_WITH(config_with_flags(pairwise, {"--near-radius", "0", "--near-seeds", "label"}),
                    Catch::Contains("--near-seeds: has no effect without --near-radius"));
  // Their coarse plateau's tolerance differs on a grid too; a named --plateau-tolerance is kept
  // on either, and one outside [0, 1) is refused.
  CHECK(pairwise.plateau_tolerance_on(true) != pairwise.plateau_tolerance_on(false));
  for (const bool on_grid : {true, false}) {
    CHECK(pairwise.config(on_grid).limits.plateau_tolerance ==
          pairwise.plateau_tolerance_on(on_grid));
    CHECK(config_with_flags(pairwise, {"--plateau-tolerance", "0.003"}, on_grid)
              .limits.plateau_tolerance == 0.003);
    CHECK(config_with_flags(pairwise, {"--plateau-tolerance", "0"}, on_grid)
              .limits.plateau_tolerance == 0.0);
  }
  CHECK_THROWS_WITH(config_with_flags(pairwise, {"--plateau-tolerance", "1"}),
                    Catch::Contains("--plateau-tolerance"));
  CHECK_THROWS_WITH(config_with_flags(pairwise, {"--plateau-tolerance", "lots"}),
                    Catch::Contains("--plateau-tolerance"));
  // The stereo defaults differ from a generic energy's: the loop above compares two configs.
  CHECK(vision::stereo_defaults().near_radius != pairwise_defaults().near_radius);
}

TEST_CASE("the defaults' size floor for near moves goes with their near moves",
          "[tools][defaults]") {
  const RunDefaults defaults = pairwise_defaults();
  REQUIRE(defaults.near_radius > 0);
  REQUIRE(defaults.near_moves_min_variables > 0);
  // Nothing named: the defaults' floor. --near-radius alone: near moves at any size, unless
  // --near-min-variables is named too.
  CHECK(original_expansion(config_without_flags(defaults)).near_moves_min_variables ==
        defaults.near_moves_min_variables);
  CHECK(original_expansion(config_with_flags(defaults, {"--near-radius", "5"}))
            .near_moves_min_variables == 0);
  const ExpansionOptions both = original_expansion(
      config_with_flags(defaults, {"--near-radius", "5", "--near-min-variables", "700"}));
  CHECK(both.near_radius == 5);
  CHECK(both.near_moves_min_variables == 700);
  CHECK(original_expansion(config_with_flags(defaults, {"--near-min-variables", "700"}))
            .near_moves_min_variables == 700);
  CHECK_THROWS_WITH(
      config_with_flags(defaults, {"--near-radius", "0", "--near-min-variables", "700"}),
      Catch::Contains("--near-min-variables: has no effect without --near-radius"));
}

TEST_CASE("the defaults' schedule goes with the energy's graph", "[tools][defaults]") {
  Rng rng(5);
  // A 64 x 64 grid energy (local edges), and 4096 variables joined at random (not local).
  const PairwiseEnergy lattice = test::random_grid_energy(rng, 64, 64, 4);
  const PairwiseEnergy random = test::random_energy(rng, 4096, 4, 8192);
  REQUIRE(edges_local(lattice));
  REQUIRE_FALSE(edges_local(random));
  const RunDefaults defaults = pairwise_defaults();
  // Three schedules, each one a schedule c2f-solve's grammar reads.
  for (const std::string& text :
       {defaults.grid_schedule, defaults.local_schedule, defaults.general_schedule})
    CHECK_NOTHROW(Schedule::parse(text));
  CHECK(defaults.local_schedule != defaults.general_schedule);
  // A pixel grid's schedule wherever the caller knows the grid; off a grid, by the edges.
  CHECK(defaults.schedule_for(lattice, true) == defaults.grid_schedule);
  CHECK(defaults.schedule_for(random, true) == defaults.grid_schedule);
  CHECK(defaults.schedule_for(lattice, false) == defaults.local_schedule);
  CHECK(defaults.schedule_for(random, false) == defaults.general_schedule);
  // No local schedule: the general one on every graph that is no grid.
  const RunDefaults stereo = vision::stereo_defaults();
  REQUIRE(stereo.local_schedule.empty());
  CHECK(stereo.schedule_for(lattice, false) == stereo.general_schedule);
  CHECK(stereo.schedule_for(random, false) == stereo.general_schedule);
}

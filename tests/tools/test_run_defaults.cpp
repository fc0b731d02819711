// The tools' flags default to the library's RunDefaults: one definition for the tools, the C++
// API and Python (python/tests compares Python with the tools).

#include <catch2/catch.hpp>

#include <variant>

#include "c2f/run/defaults.hpp"
#include "c2f/run/stereo_run.hpp"
#include "run_flags.hpp"
#include "tool_options.hpp"

using namespace c2f;

namespace {

/// The RunConfig a tool's RunFlags give with no flag on the command line.
RunConfig config_without_flags(const RunDefaults& defaults) {
  examples::RunFlags flags(defaults);
  examples::ToolOptions options("test");
  flags.declare(options);
  const char* argv[] = {"tool"};
  REQUIRE(options.parse(1, argv, {"", 0}).has_value());
  return flags.config();
}

}  // namespace

TEST_CASE("the run flags' defaults are the library's RunDefaults", "[tools][defaults]") {
  // And defaults that make near moves from their label only where the edges are local, so that
  // every near-move flag's default comes from RunDefaults too.
  RunDefaults local_near = pairwise_defaults();
  local_near.near_radius = 3;
  local_near.near_seeds = NearSeeds::label;
  local_near.near_moves_only_if_local = true;
  for (const RunDefaults& defaults : {pairwise_defaults(), vision::stereo_defaults(), local_near}) {
    const RunConfig expected = defaults.config();
    const RunConfig flags = config_without_flags(defaults);
    const auto* want = std::get_if<ExpansionOptions>(&expected.solver.original);
    const auto* got = std::get_if<ExpansionOptions>(&flags.solver.original);
    REQUIRE(want != nullptr);
    REQUIRE(got != nullptr);
    CHECK(*got == *want);
    CHECK(got->near_radius == defaults.near_radius);
    CHECK(got->near_seeds == defaults.near_seeds);
    CHECK(got->near_moves_only_if_local == defaults.near_moves_only_if_local);
    CHECK(got->shift_moves == defaults.shift_moves);
    CHECK(flags.solver.coarse == expected.solver.coarse);
    CHECK(flags.solver.maxflow == expected.solver.maxflow);
    CHECK(flags.limits.plateau_steps == expected.limits.plateau_steps);
    CHECK(flags.limits.plateau_tolerance == expected.limits.plateau_tolerance);
    CHECK(flags.limits.time_limit_seconds == expected.limits.time_limit_seconds);
    CHECK(flags.limits.max_total_steps == expected.limits.max_total_steps);
  }
  // The stereo defaults differ from a generic energy's: the loop above compares two configs.
  CHECK(vision::stereo_defaults().near_radius != pairwise_defaults().near_radius);
}

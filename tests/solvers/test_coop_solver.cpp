// The cooperative-cut solvers: every strategy keeps the true energy monotone and exact, mm ends
// at a minimiser of its own E_h (exact for two labels), h carries over between levels, and the
// driver runs them coarse to fine on schedule levels, within a memory budget.

#include <catch2/catch.hpp>

#include <random>
#include <vector>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/run/coop_run.hpp"
#include "c2f/run/run_error.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// A grid energy with vertical bands of preferred labels. Edge classes are random, or, when
/// `structured`, 0 inside a band and 1 / 2 (by side) across bands, so colour passing can group.
CoopEnergy region_coop(Rng& rng, std::size_t w, std::size_t h, int num_labels, int num_classes,
                       bool structured = false) {
  std::uniform_real_distribution<double> noise(0.0, 1.0), weight(0.1, 1.0);
  std::uniform_int_distribution<int> edge_class(0, num_classes);
  const std::size_t n = w * h;
  std::vector<double> unaries(n * static_cast<std::size_t>(num_labels));
  for (std::size_t i = 0; i < n; ++i) {
    const int preferred = static_cast<int>((i % w) * static_cast<std::size_t>(num_labels) / w);
    for (int l = 0; l < num_labels; ++l)
      unaries[i * static_cast<std::size_t>(num_labels) + static_cast<std::size_t>(l)] =
          (l == preferred ? 0.0 : 1.0) + noise(rng);
  }
  std::vector<CoopEdge> edges;
  std::vector<ClassWeight> entries;
  std::vector<double> totals(static_cast<std::size_t>(num_classes), 0.0);
  for (const auto& [u, v] : grid_neighbour_pairs({w, h}, Connectivity::eight)) {
    const auto first = static_cast<std::uint32_t>(entries.size());
    const double w_e = weight(rng);
    const bool across = (u % w) * static_cast<std::size_t>(num_labels) / w !=
                        (v % w) * static_cast<std::size_t>(num_labels) / w;
    for (int side = 0; side < 2; ++side) {
      const auto c = structured ? static_cast<std::uint32_t>(across ? 1 + side : 0)
                                : static_cast<std::uint32_t>(edge_class(rng));
      entries.push_back({c, w_e});
      if (c < static_cast<std::uint32_t>(num_classes)) totals[c] += w_e;
    }
    edges.push_back({u, v, first, first + 1, first + 2});
  }
  return CoopEnergy(n, num_labels, std::move(unaries), num_classes, std::move(totals),
                    {1.5, 0.05, 0.0}, std::move(edges), std::move(entries));
}

CoopSolverOptions options_for(AuxStrategy strategy, ExpansionStart start) {
  CoopSolverOptions options;
  options.strategy = strategy;
  options.start = start;
  options.relaxation.max_iterations = 15;
  return options;
}

}  // namespace

TEST_CASE("every cooperative-cut strategy keeps the true energy exact and never increasing",
          "[coop][solver][property]") {
  Rng rng(21);
  for (const auto& [strategy, start] : {std::pair{AuxStrategy::greedy, ExpansionStart::zero},
                                        std::pair{AuxStrategy::greedy, ExpansionStart::current},
                                        std::pair{AuxStrategy::mm, ExpansionStart::zero},
                                        std::pair{AuxStrategy::ceres, ExpansionStart::zero}}) {
    INFO(to_string(strategy) << " from " << to_string(start));
    std::size_t improving = 0;
    for (int trial = 0; trial < 4; ++trial) {
      const CoopEnergy energy = region_coop(rng, 9, 7, 2 + trial % 3, 3);
      CoopSolver solver(options_for(strategy, start));
      solver.bind(energy, random_labeling(rng, energy.num_variables(), energy.num_labels()));
      double previous = solver.energy();
      for (int step = 0; step < 12; ++step) {
        const Labeling before(solver.labeling().begin(), solver.labeling().end());
        const double now = solver.step();
        CHECK(now <= previous);
        CHECK(now == energy.evaluate(solver.labeling()));
        CHECK(solver.last_step().improved == (now < previous));
        std::size_t changed = 0;
        for (std::size_t v = 0; v < before.size(); ++v)
          changed += before[v] != solver.labeling()[v];
        CHECK(solver.last_step().changed == changed);
        // A majorise-minimise step known to change nothing is not solved.
        CHECK((solver.last_step().expansion_moves > 0 || solver.last_step().known_quiet));
        if (solver.last_step().known_quiet) CHECK_FALSE(solver.last_step().improved);
        improving += solver.last_step().improved;
        previous = now;
      }
    }
    CHECK(improving > 0);
  }
}

TEST_CASE("majorise-minimise ends at a minimiser of its own E_h (two labels: exact)",
          "[coop][solver][brute-force]") {
  Rng rng(8);
  for (int trial = 0; trial < 12; ++trial) {
    const CoopEnergy energy = region_coop(rng, 4, 3, 2, 2);
    CoopSolver solver(options_for(AuxStrategy::mm, ExpansionStart::current));
    solver.bind(energy, Labeling(energy.num_variables(), 0));
    for (int step = 0; step < 30; ++step) {
      solver.step();
      if (!solver.last_step().improved) break;
    }
    const Labeling x(solver.labeling().begin(), solver.labeling().end());
    const CoopAuxiliary h = CoopAuxiliary::optimal_for(energy, x);
    const PairwiseEnergy pairwise = pairwise_energy(energy, h);
    CHECK(close_relative(pairwise.evaluate(x), brute_force_minimum(pairwise).energy, 1e-12));
    // and the brute-force minimum of the true energy is no higher than what it found
    CHECK(brute_force_minimum(pairwise).energy + aux_constant(energy, h) >=
          energy.evaluate(x) - 1e-9);
  }
}

TEST_CASE("majorise-minimise with near moves converges where whole moves find nothing",
          "[coop][solver][brute-force]") {
  Rng rng(21);
  for (int trial = 0; trial < 12; ++trial) {
    const bool tiny = trial % 2 == 0;  // 4 x 3, two labels: the minimum of E_h by brute force
    const CoopEnergy energy = tiny ? region_coop(rng, 4, 3, 2, 2) : region_coop(rng, 9, 7, 3, 3);
    CoopSolverOptions options = options_for(AuxStrategy::mm, ExpansionStart::zero);
    options.near_radius = tiny ? 1 : 2;
    CoopSolver solver(options);
    solver.bind(energy, random_labeling(rng, energy.num_variables(), energy.num_labels()));
    double before = solver.energy();
    bool converged = false;
    const auto sweep = static_cast<std::size_t>(energy.num_labels());
    for (int step = 0; step < 60 && !converged; ++step) {
      solver.step();
      CHECK(solver.energy() <= before);
      before = solver.energy();
      const CoopStep& last = solver.last_step();
      converged = !last.improved;
      // A step's cycle: one near sweep that lowered E_h (so the step improved), or a near sweep
      // that lowered nothing and a whole sweep; none for a step known to be quiet.
      if (last.known_quiet) {
        CHECK(last.expansion_moves == 0);
      } else if (last.expansion_moves == sweep) {
        CHECK(last.improved);
      } else {
        CHECK(last.expansion_moves == 2 * sweep);
      }
    }
    REQUIRE(converged);
    const Labeling x(solver.labeling().begin(), solver.labeling().end());
    // A quiet step's cycle ended in a whole sweep: a solver of whole moves finds nothing either.
    CoopSolver whole(options_for(AuxStrategy::mm, ExpansionStart::zero));
    whole.bind(energy, x);
    whole.step();
    CHECK_FALSE(whole.last_step().improved);
    if (tiny) {
      const PairwiseEnergy pairwise =
          pairwise_energy(energy, CoopAuxiliary::optimal_for(energy, x));
      CHECK(close_relative(pairwise.evaluate(x), brute_force_minimum(pairwise).energy, 1e-12));
    }
  }
  CoopSolverOptions negative;
  negative.near_radius = -1;
  CHECK_THROWS_WITH(CoopSolver(negative), Catch::Contains("near_radius"));
}

TEST_CASE("majorise-minimise skips only steps that solving would leave quiet", "[coop][solver]") {
  Rng rng(13);
  std::size_t skipped = 0;
  for (int trial = 0; trial < 16; ++trial) {
    const CoopEnergy energy = region_coop(rng, 9, 7, 2 + trial % 3, 3);
    CoopSolver solver(options_for(AuxStrategy::mm, ExpansionStart::zero));
    solver.bind(energy, random_labeling(rng, energy.num_variables(), energy.num_labels()));
    for (int step = 0; step < 30; ++step) {
      const Labeling before(solver.labeling().begin(), solver.labeling().end());
      solver.step();
      if (!solver.last_step().known_quiet) continue;
      ++skipped;
      CHECK(Labeling(solver.labeling().begin(), solver.labeling().end()) == before);
      // A fresh solver from the same labeling solves the step: it must find nothing either.
      CoopSolver fresh(options_for(AuxStrategy::mm, ExpansionStart::zero));
      fresh.bind(energy, before);
      fresh.step();
      CHECK_FALSE(fresh.last_step().known_quiet);
      CHECK(fresh.last_step().expansion_moves > 0);
      CHECK_FALSE(fresh.last_step().improved);
      CHECK(Labeling(fresh.labeling().begin(), fresh.labeling().end()) == before);
      break;
    }
  }
  CHECK(skipped > 0);
}

TEST_CASE("majorise-minimise refreshes h after every expansion cycle by default",
          "[coop][solver]") {
  CHECK(options_for(AuxStrategy::mm, ExpansionStart::zero).cycles() == 1);
  CHECK(options_for(AuxStrategy::greedy, ExpansionStart::zero).cycles() == 10);
  CHECK(options_for(AuxStrategy::ceres, ExpansionStart::zero).cycles() == 10);
  CoopSolverOptions three = options_for(AuxStrategy::mm, ExpansionStart::zero);
  three.expansion_cycles = 3;
  CHECK(three.cycles() == 3);

  Rng rng(17);
  std::size_t longer_steps = 0;
  for (int trial = 0; trial < 8; ++trial) {
    const CoopEnergy energy = region_coop(rng, 9, 7, 2 + trial % 3, 3);
    const Labeling start = random_labeling(rng, energy.num_variables(), energy.num_labels());
    const auto L = static_cast<std::size_t>(energy.num_labels());
    for (const int cycles : {0, 10}) {
      CoopSolverOptions options = options_for(AuxStrategy::mm, ExpansionStart::zero);
      options.expansion_cycles = cycles;
      CoopSolver solver(options);
      solver.bind(energy, start);
      for (int step = 0; step < 40; ++step) {
        solver.step();
        const CoopStep& last = solver.last_step();
        if (cycles == 0) CHECK((last.expansion_moves == L || last.known_quiet));
        if (cycles == 10) longer_steps += last.expansion_moves > L;
        if (last.known_quiet) break;
      }
      // Either way the run ends at a fixed point: a fresh solver from it finds nothing.
      const Labeling end(solver.labeling().begin(), solver.labeling().end());
      CoopSolver fresh(options);
      fresh.bind(energy, end);
      fresh.step();
      CHECK_FALSE(fresh.last_step().improved);
    }
  }
  CHECK(longer_steps > 0);
}

TEST_CASE("the auxiliary variables carry over when the solver moves to another level",
          "[coop][solver]") {
  Rng rng(30);
  const CoopEnergy energy = region_coop(rng, 8, 6, 3, 3);
  const DensePartition groups = random_partition(rng, energy.num_variables(), 12);
  const CoopEnergy coarse = reduce(energy, groups);
  CoopSolver solver(options_for(AuxStrategy::greedy, ExpansionStart::current));
  solver.bind(coarse, Labeling(coarse.num_variables(), 0));
  for (int step = 0; step < 10; ++step) solver.step();
  const CoopAuxiliary kept = solver.aux();
  solver.bind(energy, expand(solver.labeling(), groups));
  CHECK(solver.aux() == kept);
  CHECK(solver.energy() == energy.evaluate(solver.labeling()));
  CHECK_THROWS_WITH(CoopSolver(CoopSolverOptions{AuxStrategy::mm, ExpansionStart::zero, -1, {}}),
                    Catch::Contains("expansion_cycles must be >= 0"));
  CHECK(aux_strategy_from_string("ceres") == AuxStrategy::ceres);
  CHECK_THROWS_WITH(aux_strategy_from_string("annealing"), Catch::Contains("'annealing'"));
  // A sweep: every (label, class) flip and the trial of h unchanged; mm: one step; ceres: two.
  CHECK(energy.num_labels() * energy.num_classes() == 9);
  CHECK(CoopSolver(options_for(AuxStrategy::greedy, ExpansionStart::zero))
            .quiet_steps_to_converge(energy) == 10);
  CHECK(CoopSolver(options_for(AuxStrategy::mm, ExpansionStart::zero))
            .quiet_steps_to_converge(energy) == 1);
  CHECK(CoopSolver(options_for(AuxStrategy::ceres, ExpansionStart::zero))
            .quiet_steps_to_converge(energy) == 2);
}

TEST_CASE("cooperative cuts run coarse to fine on colour-passing levels",
          "[coop][solver][driver]") {
  Rng rng(44);
  const CoopEnergy energy = region_coop(rng, 12, 10, 3, 4, true);
  for (const AuxStrategy strategy : {AuxStrategy::greedy, AuxStrategy::mm}) {
    ScheduleProvider levels(Schedule::parse("cp:2,1 cp:2,2 flat"), {12, 10});
    CoopSolver solver(options_for(strategy, ExpansionStart::current));
    Options options;
    options.plateau_steps = {3};
    options.max_total_steps = 60;
    std::vector<double> energies;
    const Summary summary =
        coarse_to_fine(energy, levels, solver, options, [&](const StepEvent& event) {
          CHECK(close_relative(event.energy, energy.evaluate(event.ground_labeling()), 1e-12));
          if (!energies.empty()) CHECK(event.energy <= energies.back() * (1 + 1e-12));
          energies.push_back(event.energy);
          return ObserverDecision::continue_run;
        });
    CHECK(summary.levels.size() >= 2);
    CHECK(summary.levels[0].num_variables < energy.num_variables());
    CHECK(summary.energy == energy.evaluate(summary.labeling));
    CHECK(levels.reports().front().level == "cp:2,1");
  }
}

TEST_CASE("a cooperative-cut run fits its memory budget: its floor and its recycled graphs",
          "[coop][solver][memory]") {
  Rng rng(45);
  const CoopEnergy energy = region_coop(rng, 30, 20, 4, 3, true);
  const std::size_t kept = 1000;  // e.g. the Potts energy the caller keeps
  const CoopSolverOptions mm = options_for(AuxStrategy::mm, ExpansionStart::current);
  // The floor, as the contract composes it: alpha-expansion's floor on E_h's sizes with the
  // cooperative energy, E_h, the caller's bytes and the solver's own beside it.
  ProblemSize size = problem_size(pairwise_energy(energy, CoopAuxiliary(4, 3)));
  const auto own = working_memory_bytes(mm, size);
  REQUIRE(own.has_value());
  size.energy_bytes += energy_memory_bytes(energy) + kept + *own;
  const auto floor = run_memory_floor(SolverSpec{}, size);
  REQUIRE(floor.has_value());
  CHECK(energy_memory_bytes(energy) >= energy.unaries().size_bytes() + energy.edges().size_bytes());

  // The recycled graphs get what the budget leaves above the floor; a smaller limit stays.
  CoopRunConfig config;
  config.solver = mm;
  config.kept_bytes = kept;
  config.energy_name = "the run";
  config.memory = MemoryBudget{*floor + 12345, "a test"};
  const MemoryPlan plan = plan_run(energy, config);
  CHECK(plan.floor == *floor);
  CHECK(plan.graph_memory == 12345);
  config.solver.graph_memory_limit = 100;
  CHECK(plan_run(energy, config).graph_memory == 100);
  config.graph_memory = 50;
  CHECK(plan_run(energy, config).graph_memory == 50);
  config.memory = MemoryBudget{*floor - 1, "a test"};
  try {
    (void)plan_run(energy, config);
    FAIL("a floor above the budget was accepted");
  } catch (const RunConfigError& error) {
    CHECK(error.field() == "memory");
    CHECK_THAT(error.problem(), Catch::StartsWith("the run needs ") &&
                                    Catch::Contains("more than the run's memory budget"));
  }
  // The relaxation's L-BFGS history counts for the ceres strategy.
  const auto ceres =
      working_memory_bytes(options_for(AuxStrategy::ceres, ExpansionStart::zero), size);
  REQUIRE(ceres.has_value());
  CHECK(*ceres >= *own + 600 * 4 * 40 * sizeof(double));

  // The recycled graphs' limit changes how fast, not where mm goes on this energy.
  std::vector<std::vector<double>> runs;
  for (const std::size_t limit : {std::size_t{0}, MoveOptions{}.graph_memory_limit}) {
    CoopSolverOptions options = mm;
    options.graph_memory_limit = limit;
    CoopSolver solver(options);
    solver.bind(energy, Labeling(energy.num_variables(), 0));
    std::vector<double>& energies = runs.emplace_back();
    for (int step = 0; step < 4; ++step) energies.push_back(solver.step());
  }
  CHECK(runs[0] == runs[1]);
}

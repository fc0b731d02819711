#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>
#include <vector>

#include "c2f/adapters/icm/icm.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/block_hierarchy.hpp"
#include "c2f/lift/partition_list.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// A refining sequence of 1 to 4 random partitions, coarsest first.
std::vector<DensePartition> random_sequence(Rng& rng, std::size_t n) {
  std::vector<DensePartition> levels{random_partition(rng, n, std::max<std::size_t>(1, n / 8))};
  const std::size_t extra = std::uniform_int_distribution<std::size_t>(0, 3)(rng);
  for (std::size_t i = 0; i < extra; ++i)
    levels.push_back(random_refinement(rng, levels.back(), 2));
  return levels;
}

struct Recorded {
  std::vector<StepEvent> events;
  std::vector<double> ground_energies;
};

/// ICM that records the sizes of the energies it is bound to, its steps and its releases.
struct CountingSolver {
  IcmSolver icm;
  std::vector<std::size_t> bound_sizes;
  long steps = 0;
  int releases = 0;
  void bind(const PairwiseEnergy& energy, std::span<const Label> start) {
    bound_sizes.push_back(energy.num_variables());
    icm.bind(energy, start);
  }
  double step() {
    ++steps;
    return icm.step();
  }
  [[nodiscard]] double energy() const { return icm.energy(); }
  [[nodiscard]] std::span<const Label> labeling() const { return icm.labeling(); }
  void release() { ++releases; }
};

}  // namespace

TEST_CASE("coarse-to-fine with ICM: energies never increase and the summary is exact",
          "[driver][property]") {
  Rng rng(424242);
  for (int trial = 0; trial < 150; ++trial) {
    const std::size_t w = std::uniform_int_distribution<std::size_t>(2, 9)(rng);
    const std::size_t h = std::uniform_int_distribution<std::size_t>(2, 9)(rng);
    const int num_labels = std::uniform_int_distribution<int>(2, 5)(rng);
    const PairwiseEnergy energy = trial % 2 == 0 ? random_grid_energy(rng, w, h, num_labels)
                                                 : random_energy(rng, w * h, num_labels, 3 * w * h);
    const auto sequence = random_sequence(rng, energy.num_variables());
    PartitionList levels(sequence);
    IcmSolver solver(IcmOptions{trial % 3 == 0 ? VisitOrder::random : VisitOrder::sequential,
                                static_cast<std::uint64_t>(trial), 1e-12});
    Options options;
    options.plateau_steps = {std::uniform_int_distribution<int>(1, 3)(rng)};
    options.max_steps_per_level = 50;
    Recorded recorded;
    Labeling scratch;
    const Summary summary =
        coarse_to_fine(energy, levels, solver, options, [&](const StepEvent& event) {
          recorded.events.push_back(event);
          const Labeling ground = event.ground_labeling();
          recorded.ground_energies.push_back(energy.evaluate(ground));
          // Without an allocation: the same labeling, the level's own on the original level.
          const std::span<const Label> kept = event.ground_labeling(scratch);
          CHECK(std::equal(kept.begin(), kept.end(), ground.begin(), ground.end()));
          CHECK((kept.data() == event.level_labeling.data()) == event.group_of.empty());
          return ObserverDecision::continue_run;
        });
    INFO("trial " << trial);
    REQUIRE(summary.levels.size() == sequence.size() + 1);
    CHECK(summary.reason == TerminationReason::converged);
    for (std::size_t i = 0; i < recorded.events.size(); ++i) {
      // The observer sees the energy of the ground labeling.
      CHECK(close_relative(recorded.events[i].energy, recorded.ground_energies[i], 1e-12));
      if (i > 0) {
        CHECK(recorded.events[i].energy <=
              recorded.events[i - 1].energy +
                  1e-12 * std::max(1.0, std::abs(recorded.events[i - 1].energy)));
      }
    }
    CHECK(recorded.events.back().at_original);
    CHECK(summary.energy == energy.evaluate(summary.labeling));
    CHECK(close_relative(summary.energy, recorded.events.back().energy, 1e-12));
    for (std::size_t level = 0; level < sequence.size(); ++level) {
      CHECK(summary.levels[level].num_variables == sequence[level].num_groups());
    }
    CHECK(summary.levels.back().num_variables == energy.num_variables());
  }
}

TEST_CASE("a flat run is a coarse-to-fine run without partitions", "[driver]") {
  Rng rng(3);
  const PairwiseEnergy energy = random_grid_energy(rng, 12, 10, 4);
  PartitionList flat;
  IcmSolver solver;
  const Summary summary = coarse_to_fine(energy, flat, solver, Options{});
  REQUIRE(summary.levels.size() == 1);
  CHECK(summary.levels[0].num_variables == 120);
  // ICM's step is a sweep: one step without decrease is a fixed point, and the run ends there.
  CHECK(summary.reason == TerminationReason::converged);
  CHECK(summary.levels[0].steps >= 1);
  CHECK(summary.energy <= summary.levels[0].start_energy);
}

TEST_CASE("a run starts from a labeling of one's own", "[driver][start]") {
  Rng rng(11);
  const PairwiseEnergy energy = random_grid_energy(rng, 9, 7, 4);
  Labeling start(energy.num_variables());
  for (Label& label : start) label = std::uniform_int_distribution<Label>(0, 3)(rng);
  Options options;
  options.start_labeling = start;
  std::vector<StepEvent> events;
  const auto record = [&](const StepEvent& event) {
    events.push_back(event);
    return ObserverDecision::continue_run;
  };
  // Flat: step 0 is the start labeling itself.
  PartitionList flat;
  IcmSolver solver;
  const Summary summary = coarse_to_fine(energy, flat, solver, options, record);
  REQUIRE_FALSE(events.empty());
  CHECK(events.front().energy == energy.evaluate(start));
  CHECK(summary.energy <= energy.evaluate(start));
  // Coarse first: every group starts at its members' majority label.
  events.clear();
  const DensePartition blocks = random_partition(rng, energy.num_variables(), 8);
  PartitionList levels({blocks});
  IcmSolver coarse_solver;
  coarse_to_fine(energy, levels, coarse_solver, options, record);
  const Labeling expected =
      transfer_labels_by_majority(start, DensePartition::identity(start.size()), blocks);
  CHECK(close_relative(events.front().energy, energy.evaluate(expand(expected, blocks)), 1e-12));
  // A start labeling of the wrong size or with a label out of range is refused by name.
  options.start_labeling.pop_back();
  PartitionList again;
  CHECK_THROWS_WITH(coarse_to_fine(energy, again, solver, options),
                    Catch::Contains("Options::start_labeling has 62 labels, the energy has 63"));
  options.start_labeling = start;
  options.start_labeling[5] = 4;
  CHECK_THROWS_WITH(coarse_to_fine(energy, again, solver, options),
                    Catch::Contains("gives variable 5 label 4, outside [0, 3]"));
}

TEST_CASE("coarse levels and the original problem can have solvers of their own", "[driver]") {
  Rng rng(31);
  const PairwiseEnergy energy = random_grid_energy(rng, 16, 16, 4);
  Options options;
  options.plateau_steps = {3};
  CountingSolver coarse, original;
  BlockHierarchy levels(GridShape{16, 16}, {8, 4});
  const Summary summary = coarse_to_fine(energy, levels, LevelSolvers(coarse, original), options);
  REQUIRE(summary.levels.size() == 3);
  // The coarse solver solves both coarse levels (2x2 and 4x4 blocks), the original solver the
  // original problem; the coarse solver is released once, when the original problem begins.
  CHECK(coarse.bound_sizes == std::vector<std::size_t>{4, 16});
  CHECK(original.bound_sizes == std::vector<std::size_t>{256});
  CHECK(coarse.steps == summary.levels[0].steps + summary.levels[1].steps);
  CHECK(original.steps == summary.levels[2].steps);
  CHECK(coarse.releases == 1);
  CHECK(original.releases == 0);
  CHECK(summary.energy == energy.evaluate(summary.labeling));

  // Two solvers configured alike give the run of one; one object passed twice is not released.
  BlockHierarchy same_levels(GridShape{16, 16}, {8, 4});
  CountingSolver both;
  const Summary one = coarse_to_fine(energy, same_levels, LevelSolvers(both, both), options);
  CHECK(one.labeling == summary.labeling);
  CHECK(one.total_steps == summary.total_steps);
  CHECK(both.bound_sizes == std::vector<std::size_t>{4, 16, 256});
  CHECK(both.releases == 0);
}

TEST_CASE("stopping rules end the run with their reason", "[driver][rules]") {
  Rng rng(8);
  const PairwiseEnergy energy = random_grid_energy(rng, 16, 16, 5);

  SECTION("total step limit") {
    BlockHierarchy levels(GridShape{16, 16}, {8, 4, 2});
    IcmSolver solver;
    Options options;
    options.max_total_steps = 3;
    options.plateau_steps = {100};
    const Summary summary = coarse_to_fine(energy, levels, solver, options);
    CHECK(summary.reason == TerminationReason::step_limit);
    CHECK(summary.total_steps == 3);
    CHECK(summary.labeling.size() == energy.num_variables());  // expanded from the lifted level
    CHECK(summary.energy == energy.evaluate(summary.labeling));
  }
  SECTION("per-level step limit refines, and on the original problem ends the run") {
    BlockHierarchy levels(GridShape{16, 16}, {8, 4});
    IcmSolver solver;
    Options options;
    options.plateau_steps = {};
    options.max_steps_per_level = 2;
    const Summary summary = coarse_to_fine(energy, levels, solver, options);
    REQUIRE(summary.levels.size() == 3);
    for (const LevelSummary& level : summary.levels) CHECK(level.steps == 2);
    CHECK(summary.reason == TerminationReason::step_limit);
  }
  SECTION("target energy") {
    BlockHierarchy levels(GridShape{16, 16}, {8, 4});
    IcmSolver solver;
    Options options;
    options.target_energy = 1e300;  // reached by the start labeling
    const Summary summary = coarse_to_fine(energy, levels, solver, options);
    CHECK(summary.reason == TerminationReason::target_energy);
    CHECK(summary.total_steps == 0);
  }
  SECTION("time limit") {
    BlockHierarchy levels(GridShape{16, 16}, {8, 4});
    IcmSolver solver;
    Options options;
    options.time_limit_seconds = 1e-9;
    const Summary summary = coarse_to_fine(energy, levels, solver, options);
    CHECK(summary.reason == TerminationReason::time_limit);
  }
  SECTION("observer") {
    PartitionList flat;
    IcmSolver solver;
    long seen = 0;
    const Summary summary =
        coarse_to_fine(energy, flat, solver, Options{}, [&](const StepEvent& event) {
          ++seen;
          return event.step == 1 ? ObserverDecision::stop : ObserverDecision::continue_run;
        });
    CHECK(summary.reason == TerminationReason::observer);
    CHECK(seen == 2);
    CHECK(summary.total_steps == 1);
  }
}

namespace {
/// The per-step record the rules read, with the fields they look at.
StepEvent rule_event(double time_s, int level, bool at_original, long step, long total_steps,
                     std::span<const double> level_energies) {
  StepEvent event;
  event.time_s = time_s;
  event.level = level;
  event.at_original = at_original;
  event.step = step;
  event.total_steps = total_steps;
  event.level_energies = level_energies;
  event.energy = level_energies.empty() ? 0.0 : level_energies.back();
  return event;
}
}  // namespace

TEST_CASE("rules compose: the strongest verdict wins", "[driver][rules]") {
  const std::vector<double> flat_history{5.0, 5.0, 5.0};
  StepEvent progress = rule_event(0.5, 1, false, 2, 10, flat_history);
  Rules rules;
  rules.add(no_decrease({2}));
  CHECK(rules.decide(progress).decision == Decision::refine);
  rules.add(total_step_limit(10));
  CHECK(rules.decide(progress).decision == Decision::stop);
  CHECK(rules.decide(progress).reason == TerminationReason::step_limit);

  const std::vector<double> falling{5.0, 4.0, 3.0};
  progress.level_energies = falling;
  progress.total_steps = 1;
  CHECK(rules.decide(progress).decision == Decision::continue_level);

  // Per-level k: level 0 uses k = 1, deeper levels the last entry (k = 3).
  Rules per_level;
  per_level.add(no_decrease({1, 3}));
  const std::vector<double> one_flat{5.0, 4.0, 4.0};
  progress.level_energies = one_flat;
  progress.level = 0;
  CHECK(per_level.decide(progress).decision == Decision::refine);
  progress.level = 5;
  CHECK(per_level.decide(progress).decision == Decision::continue_level);
}

TEST_CASE("the plateau rule can wait longer on the original problem", "[driver][rules]") {
  const std::vector<double> two_flat{5.0, 5.0, 5.0};
  const Rule rule = no_decrease({2}, 0.0, 3);
  StepEvent lifted = rule_event(0.1, 0, false, 2, 2, two_flat);
  CHECK(rule(lifted).decision == Decision::refine);
  StepEvent original = rule_event(0.1, 1, true, 2, 4, two_flat);
  CHECK(rule(original).decision == Decision::continue_level);
  const std::vector<double> three_flat{5.0, 5.0, 5.0, 5.0};
  original.level_energies = three_flat;
  CHECK(rule(original).decision == Decision::refine);
  CHECK_THROWS_WITH(no_decrease({2}, 0.0, -1), Catch::Contains("steps_at_original must be >= 0"));
  Options options;
  options.plateau_steps_at_original = -3;
  CHECK_THAT(options.validate(), Catch::Contains("plateau_steps_at_original must be >= 0"));
}

TEST_CASE("a plateau tolerance leaves creeping coarse levels but not the original problem",
          "[driver][rules]") {
  // Decreases of 0.05 per step on an energy of 1000: 2e-4 of |E| over the last 4 steps.
  const std::vector<double> creeping{1000.0, 999.95, 999.90, 999.85, 999.80};
  const Rule rule = no_decrease({4}, 3e-4, 0, 0.0);
  const StepEvent coarse = rule_event(0.1, 0, false, 4, 4, creeping);
  CHECK(rule(coarse).decision == Decision::refine);
  const StepEvent original = rule_event(0.1, 1, true, 4, 8, creeping);
  CHECK(rule(original).decision == Decision::continue_level);
  CHECK(no_decrease({4}, 0.0, 0, 3e-4)(original).decision == Decision::refine);
  CHECK(no_decrease({4}, 1e-4)(coarse).decision == Decision::continue_level);

  Options options;
  options.plateau_steps = {4};
  options.plateau_tolerance = 3e-4;
  CHECK(options.rules().decide(coarse).decision == Decision::refine);
  CHECK(options.rules().decide(original).decision == Decision::continue_level);
  options.plateau_tolerance_at_original = 3e-4;
  CHECK(options.rules().decide(original).decision == Decision::refine);
  options.plateau_tolerance_at_original = -1.0;
  CHECK_THAT(options.validate(),
             Catch::Contains("plateau_tolerance_at_original must be finite and >= 0"));
  CHECK_THROWS_WITH(no_decrease({4}, 0.0, 0, std::nan("")),
                    Catch::Contains("tolerance_at_original must be finite and >= 0"));
}

TEST_CASE("the progress-rate rule leaves a coarse level slower than the next is expected to be",
          "[driver][rules]") {
  // A level of 25 variables of 100 (every one in group 0, labelled 3), each step a move over
  // the 25, sweeps of 2 steps: the next level's first sweep is expected to work over
  // 50 * 100 / 25 = 200 variables.
  const std::vector<double> energies{100.0, 90.0, 80.0, 75.0, 72.0, 70.0, 69.0, 68.5, 68.4};
  const std::vector<VariableIndex> group_of(100, 0);
  const std::vector<Label> level_labeling{3};
  const auto event_at = [&](std::span<const double> history, std::size_t step, bool at_original) {
    StepEvent event = rule_event(static_cast<double>(step), 0, at_original, static_cast<long>(step),
                                 static_cast<long>(step), history.subspan(0, step + 1));
    event.num_variables = 25;
    event.step_variables = step > 0 ? 25 : 0;
    event.level_labeling = level_labeling;
    if (!at_original) event.group_of = group_of;
    return event;
  };
  const auto decisions = [&](Rule rule, bool at_original) {
    std::vector<Decision> out;
    for (std::size_t step = 0; step < energies.size(); ++step)
      out.push_back(rule(event_at(energies, step, at_original)).decision);
    return out;
  };
  using enum Decision;
  // Without an estimate of its own the next level is expected to gain what the first sweep
  // gained (20), 0.1 per variable moved. Over windows of 2 steps (50 variables moved) the level
  // falls 0.4, 0.3, 0.16 per variable at steps 2 to 4 and 0.1 at step 5: not above, so it is
  // left there.
  CHECK(decisions(progress_rate({2}), false) ==
        std::vector<Decision>{continue_level, continue_level, continue_level, continue_level,
                              continue_level, refine, refine, refine, refine});
  CHECK(decisions(progress_rate({2}), true) ==
        std::vector<Decision>(energies.size(), continue_level));
  // With an estimate: asked once, at the end of the first sweep, with the labeling the level
  // would hand down. A gain of 4 is 0.02 per variable; windows of 2 steps fall 0.03 at step 7
  // and 0.012 at step 8.
  int asked = 0;
  const NextLevelGain gain_of_four = [&](std::span<const Label> ground) {
    ++asked;
    CHECK(ground.size() == 100);
    CHECK(std::ranges::all_of(ground, [](Label l) { return l == 3; }));
    return 4.0;
  };
  CHECK(decisions(progress_rate({2}, gain_of_four), false) ==
        std::vector<Decision>{continue_level, continue_level, continue_level, continue_level,
                              continue_level, continue_level, continue_level, continue_level,
                              refine});
  CHECK(asked == 1);
  // Sweeps of 8 steps: nothing is compared before step 8, and then over the last 4 steps
  // ((72 - 68.4) / 100 = 0.036 per variable against 4 / 800 = 0.005).
  asked = 0;
  CHECK(decisions(progress_rate({8}, gain_of_four), false) ==
        std::vector<Decision>(energies.size(), continue_level));
  CHECK(asked == 1);
  // A level that has stopped decreasing is left even when nothing is expected of the next one.
  const std::vector<double> level{5.0, 4.0, 3.0, 3.0, 3.0};
  Rule nothing_expected = progress_rate({2}, [](std::span<const Label>) { return 0.0; });
  std::vector<Decision> flat_out;
  for (std::size_t step = 0; step < level.size(); ++step)
    flat_out.push_back(nothing_expected(event_at(level, step, false)).decision);
  CHECK(flat_out == std::vector<Decision>{continue_level, continue_level, continue_level,
                                          continue_level, refine});
  // Each level is judged on its own steps: a second level starts afresh at its step 0.
  Rule twice = progress_rate({2});
  CHECK(decisions(twice, false).back() == refine);
  CHECK(decisions(twice, false) == decisions(progress_rate({2}), false));
  // Through Options, beside the plateau rule.
  Options options;
  options.progress_sweep_steps = 2;
  options.next_level_gain = gain_of_four;
  Rule through_options = [rules = options.rules()](const StepEvent& event) {
    return rules.decide(event);
  };
  CHECK(decisions(through_options, false)[7] == continue_level);
  CHECK(decisions(through_options, false).back() == refine);
  options.progress_sweep_steps = -1;
  CHECK_THAT(options.validate(), Catch::Contains("progress_sweep_steps must be >= 0"));
  CHECK_THROWS_WITH(progress_rate({0}), Catch::Contains("every sweep must be >= 1 step"));
}

TEST_CASE("options and rules validate their fields", "[driver][options][validation]") {
  Options options;
  CHECK(options.validate().empty());
  options.plateau_steps = {4, 0};
  CHECK_THAT(options.validate(), Catch::Contains("plateau_steps[1] must be >= 1"));
  options.plateau_steps = {};
  CHECK_THAT(options.validate(), Catch::Contains("no rule ends a level"));
  options.max_steps_per_level = -1;
  CHECK_THAT(options.validate(), Catch::Contains("max_steps_per_level must be >= 0"));
  options = Options{};
  options.time_limit_seconds = std::nan("");
  CHECK_THAT(options.validate(), Catch::Contains("time_limit_seconds"));
  options = Options{};
  options.target_energy = std::numeric_limits<double>::infinity();
  CHECK_THAT(options.validate(), Catch::Contains("target_energy must be finite"));
  CHECK_THROWS_WITH(options.rules(), Catch::Contains("coarse-to-fine options: target_energy"));
  CHECK_THROWS_WITH(no_decrease({}), Catch::Contains("steps_per_level is empty"));
  CHECK_THROWS_WITH(time_limit(0.0), Catch::Contains("seconds must be > 0"));
  CHECK_THROWS_WITH(level_step_limit(0), Catch::Contains("max_steps must be >= 1"));
  CHECK_THROWS_WITH(total_step_limit(-2),
                    Catch::Contains("total_step_limit: max_steps must be >= 1"));
  CHECK_THROWS_WITH(no_decrease({2, 0}), Catch::Contains("every k must be >= 1, got 0"));
  CHECK_THROWS_WITH(no_decrease({2}, -1.0), Catch::Contains("tolerance must be finite and >= 0"));
  CHECK_THROWS_WITH(target_energy(std::nan("")), Catch::Contains("target must be finite"));
  CHECK_THROWS_WITH(Rules{}.add(Rule{}), Catch::Contains("empty rule"));

  Rng rng(1);
  const PairwiseEnergy energy = random_grid_energy(rng, 4, 4, 2);
  PartitionList flat;
  IcmSolver solver;
  Options endless;
  endless.plateau_steps.clear();
  CHECK_THROWS_WITH(coarse_to_fine(energy, flat, solver, endless),
                    Catch::Contains("no rule ends a level"));
  Options empty_rule;
  empty_rule.extra_rules = {time_limit(1.0), Rule{}};
  CHECK_THROWS_WITH(coarse_to_fine(energy, flat, solver, empty_rule),
                    Catch::Contains("extra_rules[1] is empty"));
  CHECK_THROWS_WITH(coarse_to_fine(energy, flat, solver, options),
                    Catch::Contains("target_energy"));
  options = Options{};
  options.plateau_tolerance = -0.5;
  CHECK_THAT(options.validate(), Catch::Contains("plateau_tolerance must be finite and >= 0"));
  options = Options{};
  options.max_total_steps = -1;
  CHECK_THAT(options.validate(), Catch::Contains("max_total_steps must be >= 0"));
}

TEST_CASE("enum names round-trip", "[driver][options]") {
  for (auto reason :
       {TerminationReason::converged, TerminationReason::step_limit, TerminationReason::time_limit,
        TerminationReason::target_energy, TerminationReason::observer}) {
    CHECK(termination_reason_from_string(to_string(reason)) == reason);
  }
  CHECK(initial_labeling_from_string("zero") == InitialLabeling::zero);
  CHECK(initial_labeling_from_string(to_string(InitialLabeling::unary_argmin)) ==
        InitialLabeling::unary_argmin);
  CHECK_THROWS_WITH(initial_labeling_from_string("random"), Catch::Contains("'random'"));
  CHECK_THROWS_WITH(termination_reason_from_string("done"), Catch::Contains("'done'"));
}

TEST_CASE("the driver starts from the chosen initial labeling", "[driver]") {
  // One variable pair, unaries favour label 2; with zero init and a step limit of 0 steps
  // reached by a target energy, the run reports the start labeling.
  const PairwiseEnergy energy(2, 3, {5, 5, 0, 5, 5, 0}, {PairwiseTerm::potts()},
                              {Edge{0, 1, 1.0, 0}});
  PartitionList flat;
  IcmSolver solver;
  Options options;
  options.target_energy = 1e9;
  options.initial_labeling = InitialLabeling::zero;
  CHECK(coarse_to_fine(energy, flat, solver, options).labeling == Labeling{0, 0});
  PartitionList flat_again;
  options.initial_labeling = InitialLabeling::unary_argmin;
  CHECK(coarse_to_fine(energy, flat_again, solver, options).labeling == Labeling{2, 2});
}

TEST_CASE("rules of one's own are consulted with the options' rules", "[driver][rules]") {
  Rng rng(8);
  const PairwiseEnergy energy = random_grid_energy(rng, 8, 8, 3);
  PartitionList flat;
  IcmSolver solver;
  Options options;
  // A rule of one's own: stop once the run has made two steps.
  options.extra_rules = {[](const StepEvent& event) {
    return event.total_steps >= 2 ? Verdict{Decision::stop, TerminationReason::step_limit}
                                  : Verdict{};
  }};
  const Summary summary = coarse_to_fine(energy, flat, solver, options);
  CHECK(summary.reason == TerminationReason::step_limit);
  CHECK(summary.total_steps == 2);
}

TEST_CASE("a coarse level that does not fit is skipped, and the run is the run without it",
          "[driver][memory]") {
  Rng rng(25);
  const PairwiseEnergy energy = random_grid_energy(rng, 12, 10, 4);
  const DensePartition coarse = random_partition(rng, energy.num_variables(), 6);
  const DensePartition middle = random_refinement(rng, coarse, 4);
  const auto energies_of = [&](std::vector<DensePartition> sequence, const Options& options,
                               Summary& summary) {
    std::vector<double> energies;
    PartitionList levels(std::move(sequence));
    IcmSolver solver;
    summary = coarse_to_fine(energy, levels, solver, options, [&](const StepEvent& event) {
      energies.push_back(event.energy);
      return ObserverDecision::continue_run;
    });
    return energies;
  };
  // The middle level is declined: the run equals the run without it, step for step.
  Options options;
  std::vector<std::size_t> asked;
  options.coarse_level_fits = [&](std::size_t groups) {
    asked.push_back(groups);
    return groups <= coarse.num_groups();
  };
  Summary skipped, without;
  const auto with_skip = energies_of({coarse, middle}, options, skipped);
  const auto plain = energies_of({coarse}, Options{}, without);
  CHECK(with_skip == plain);
  CHECK(skipped.energy == without.energy);
  CHECK(asked == std::vector<std::size_t>{coarse.num_groups(), middle.num_groups()});
  REQUIRE(skipped.levels.size() == 3);
  CHECK_FALSE(skipped.levels[0].skipped);
  CHECK(skipped.levels[1].skipped);
  CHECK(skipped.levels[1].num_variables == middle.num_groups());
  CHECK(skipped.levels[1].steps == 0);
  CHECK_FALSE(skipped.levels[2].skipped);
  CHECK_THAT(skipped.report(), Catch::Contains("level 1: " + std::to_string(middle.num_groups()) +
                                               " groups, skipped"));
  // Every coarse level declined: the flat run, from its own start.
  options.coarse_level_fits = [](std::size_t) { return false; };
  Summary none, flat;
  CHECK(energies_of({coarse, middle}, options, none) == energies_of({}, Options{}, flat));
  CHECK(none.energy == flat.energy);
}

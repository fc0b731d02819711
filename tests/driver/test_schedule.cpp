#include <catch2/catch.hpp>

#include <optional>
#include <variant>
#include <vector>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {
const SchedulePreset kPresets[] = {{"paper", "cp:1,1 cp:2,1 cp:3,1 flat"},
                                   {"two", "blocks:4 blocks:2"}};
}  // namespace

TEST_CASE("schedules parse and print in one vocabulary", "[lift][schedule]") {
  const Schedule paper = Schedule::parse("paper", kPresets);
  CHECK(paper.to_string() == "cp:1,1 cp:2,1 cp:3,1 flat");
  CHECK(Schedule::parse(paper.to_string()).levels == paper.levels);
  CHECK(Schedule::parse("two", kPresets).to_string() == "blocks:4 blocks:2 flat");
  CHECK(std::get<ColourPassingLevel>(paper.levels[1].partition) == ColourPassingLevel{2, 1});
  CHECK(Schedule::parse("flat").levels.empty());
  const Schedule mixed =
      Schedule::parse("  blocks:16 local:2,2 threshold:5 threshold:0.5,3 slic:12 cp:2,3 ");
  CHECK(mixed.to_string() == "blocks:16 local:2,2 threshold:5 threshold:0.5,3 slic:12 cp:2,3 flat");
  const Schedule automatic = Schedule::parse("auto:0.002,0.02,0.2 flat");
  CHECK(automatic.auto_fractions == std::vector<double>{0.002, 0.02, 0.2});
  CHECK(automatic.to_string() == "auto:0.002,0.02,0.2 flat");
}

TEST_CASE("malformed schedules are rejected with the offending level named",
          "[lift][schedule][validation]") {
  CHECK_THROWS_WITH(Schedule::parse(""), Catch::Contains("empty"));
  CHECK_THROWS_WITH(
      Schedule::parse("flat cp:1,1"),
      Catch::Contains("level 'flat': 'flat' (the original problem) can only be the last"));
  CHECK_THROWS_WITH(Schedule::parse("cp:1"),
                    Catch::Contains("level 'cp:1': expected cp:N_L,N_iter"));
  CHECK_THROWS_WITH(Schedule::parse("cp:0,1"), Catch::Contains("'0' must be a whole number >= 1"));
  // Too large is said so (it read "must be a whole number >= 1").
  CHECK_THROWS_WITH(Schedule::parse("cp:99999999999999999999,1"),
                    Catch::Contains("'99999999999999999999' is too large (at most 1000000000)"));
  CHECK_THROWS_WITH(Schedule::parse("cp:2000000000,1"), Catch::Contains("is too large"));
  CHECK_THROWS_WITH(Schedule::parse("cp:1e30,1"), Catch::Contains("'1e30' is too large"));
  CHECK_THROWS_WITH(Schedule::parse("cp:a,1"), Catch::Contains("'a' is not a number"));
  CHECK_THROWS_WITH(Schedule::parse("threshold:-2"), Catch::Contains("TAU must be >= 0"));
  CHECK_THROWS_WITH(Schedule::parse("slic:1"), Catch::Contains("'1' must be a whole number >= 2"));
  CHECK_THROWS_WITH(Schedule::parse("spiral:3"), Catch::Contains("unknown level kind 'spiral'"));
  CHECK_THROWS_WITH(Schedule::parse("auto:0.2,0.02"), Catch::Contains("fractions must increase"));
  CHECK_THROWS_WITH(Schedule::parse("auto:0.2 cp:1,1"), Catch::Contains("stands alone"));
  CHECK_THROWS_WITH(Schedule::parse("auto:"), Catch::Contains("auto needs at least one fraction"));
  CHECK_THROWS_WITH(Schedule::parse("paper flat", kPresets),
                    Catch::Contains("'paper' stands alone"));
  CHECK_THROWS_WITH(Schedule::parse("cp:1,1 two", kPresets), Catch::Contains("'two' stands alone"));
  CHECK_THROWS_WITH(Schedule::parse("papr", kPresets),
                    Catch::Contains("level 'papr': neither a level (KIND:ARGS), flat, nor a preset "
                                    "(paper, two)"));
  CHECK_THROWS_WITH(Schedule::parse("paper"), Catch::Contains("expected KIND:ARGS"));
  CHECK_THROWS_WITH(Schedule::parse("cp:1.5,1"),
                    Catch::Contains("'1.5' must be a whole number >= 1"));
  CHECK_THROWS_WITH(Schedule::parse("blocks:4x"), Catch::Contains("'4x' is not a number"));
  CHECK(Schedule::parse("cp:3,1 local:2,1").validate(3).empty());
  CHECK(Schedule::parse("cp:3,1 local:4,1").validate(3) ==
        "level local:4,1 has N_L 4 above the 3 labels");
  CHECK_THROWS_WITH(ScheduleProvider(Schedule::parse("slic:8"), {4, 4}),
                    Catch::Contains("needs superpixels"));
}

TEST_CASE("schedules say which levels need a pixel grid", "[lift][schedule]") {
  CHECK(Schedule::parse("cp:1,1 cp:2,1 flat").validate_without_grid().empty());
  CHECK(Schedule::parse("auto:0.1,0.5").validate_without_grid().empty());
  CHECK(Schedule::parse("cp:1,1 cp:2,1/cc agg:2/cc").validate_without_grid().empty());
  CHECK(Schedule::parse("agg:1 local:1,1").validate_without_grid() ==
        "level local:1,1 needs a pixel grid");
  CHECK(Schedule::parse("cp:1,1 threshold:1/cc").validate_without_grid() ==
        "level threshold:1/cc needs a pixel grid");
  CHECK(Schedule::parse("flat").validate_without_grid().empty());
}

TEST_CASE("every schedule level refines the previous one", "[lift][schedule][property]") {
  Rng rng(3);
  const GridShape shape{14, 11};
  for (const char* text : {"cp:1,1 cp:2,1 cp:3,1", "cp:1,1 cp:1,2 cp:2,2 cp:3,3",
                           "blocks:8 blocks:4 cp:1,1", "threshold:20 threshold:5 threshold:0",
                           "local:1,1 local:1,2 local:2,2 local:3,2", "auto:0.01,0.1,0.5"}) {
    const PairwiseEnergy energy = random_grid_energy(rng, shape.width, shape.height, 4);
    ScheduleProvider provider(Schedule::parse(text), shape);
    std::optional<DensePartition> previous;
    std::size_t levels = 0;
    while (auto partition = provider.next(energy)) {
      if (previous) CHECK(partition->is_refinement_of(*previous));
      previous = std::move(partition);
      ++levels;
    }
    INFO(text);
    REQUIRE(provider.reports().size() == levels);
    CHECK(levels > 0);
    for (const LevelReport& report : provider.reports()) CHECK(report.num_groups > 0);
  }
}

TEST_CASE("levels keep classes apart and still refine each other", "[lift][schedule]") {
  Rng rng(5);
  const GridShape shape{14, 11};
  std::vector<int> classes(shape.size());
  for (int& c : classes) c = static_cast<int>(rng() % 3);
  for (const char* text : {"blocks:8 blocks:4 cp:1,1", "local:1,1 local:2,2", "auto:0.05,0.3"}) {
    INFO(text);
    const PairwiseEnergy energy = random_grid_energy(rng, shape.width, shape.height, 4);
    ScheduleProvider provider(Schedule::parse(text), shape);
    provider.keep_apart(classes);
    std::optional<DensePartition> previous;
    while (auto partition = provider.next(energy)) {
      for (std::size_t g = 0; g < partition->num_groups(); ++g) {
        const auto members = partition->members(g);
        for (const VariableIndex v : members) CHECK(classes[v] == classes[members[0]]);
      }
      if (previous) CHECK(partition->is_refinement_of(*previous));
      CHECK(provider.reports().back().num_groups == partition->num_groups());
      previous = std::move(partition);
    }
    CHECK(previous.has_value());
  }
  ScheduleProvider provider(Schedule::parse("blocks:4"), shape);
  CHECK_THROWS_WITH(provider.keep_apart(std::vector<int>(shape.size() - 1, 0)),
                    Catch::Contains("153 classes for a grid of 154 pixels"));
  std::vector<int> negative(shape.size(), 0);
  negative[7] = -1;
  CHECK_THROWS_WITH(provider.keep_apart(negative), Catch::Contains("classes[7] = -1 is negative"));
}

TEST_CASE("auto schedules pick colour-passing levels in refining order", "[lift][schedule]") {
  Rng rng(17);
  const PairwiseEnergy energy = random_grid_energy(rng, 30, 20, 6);
  ScheduleProvider provider(Schedule::parse("auto:0.05,0.3,0.8"), {30, 20});
  while (provider.next(energy)) {
  }
  CHECK(provider.schedule().levels.empty());  // the schedule as given stays as given
  const auto& levels = provider.levels();
  REQUIRE(!levels.empty());
  for (std::size_t i = 1; i < levels.size(); ++i) {
    const auto& level = std::get<ColourPassingLevel>(levels[i].partition);
    const auto& before = std::get<ColourPassingLevel>(levels[i - 1].partition);
    CHECK(level.labels >= before.labels);
    CHECK(level.iterations >= before.iterations);
    CHECK(provider.reports()[i].num_groups >= provider.reports()[i - 1].num_groups);
  }
}

TEST_CASE("non-refining schedules are rejected unless labels go down by majority",
          "[lift][schedule][driver][validation]") {
  Rng rng(23);
  const PairwiseEnergy energy = random_grid_energy(rng, 12, 9, 5);
  ExpansionSolver<> solver;
  ScheduleProvider strict(Schedule::parse("threshold:0 blocks:4"), {12, 9});
  CHECK_THROWS_WITH(coarse_to_fine(energy, strict, solver, Options{}),
                    Catch::Contains("the partition of level 1 (") &&
                        Catch::Contains("does not refine level 0 (") &&
                        Catch::Contains("LevelTransfer::majority"));

  ScheduleProvider relaxed(Schedule::parse("threshold:0 blocks:4"), {12, 9});
  Options options;
  options.level_transfer = LevelTransfer::majority;
  const Summary summary = coarse_to_fine(energy, relaxed, solver, options);
  CHECK(summary.levels.size() == 3);
  CHECK(summary.energy == energy.evaluate(summary.labeling));

  ScheduleProvider wrong_grid(Schedule::parse("cp:1,1"), {5, 5});
  CHECK_THROWS_WITH(wrong_grid.next(energy),
                    Catch::Contains("the energy has 108 variables, the 5x5 grid has 25"));
  ScheduleProvider too_many_labels(Schedule::parse("cp:9,1"), {12, 9});
  CHECK_THROWS_WITH(too_many_labels.next(energy),
                    Catch::Contains("schedule: level cp:9,1 has N_L 9 above the 5 labels"));
}

TEST_CASE("majority transfer equals the exact transfer on refinements", "[lift][transfer]") {
  Rng rng(2);
  for (int trial = 0; trial < 50; ++trial) {
    const DensePartition coarse = random_partition(rng, 40, 8);
    const DensePartition fine = random_refinement(rng, coarse, 3);
    const Labeling y = random_labeling(rng, coarse.num_groups(), 5);
    CHECK(transfer_labels_by_majority(y, coarse, fine) == transfer_labels(y, coarse, fine));
  }
  // Group {0, 1, 2} of `to` spans old groups labelled 4, 4, 1: it takes 4.
  const DensePartition from({0, 0, 1, 2}, 3), to({0, 0, 0, 1}, 2);
  CHECK(transfer_labels_by_majority(Labeling{4, 1, 7}, from, to) == Labeling{4, 7});
}

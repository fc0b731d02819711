#include <catch2/catch.hpp>

#include "c2f/lift/colour_passing.hpp"
#include "c2f/lift/connected_components.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/vision/stereo/stereo_schedules.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("groups split into their 4-connected components", "[lift][connected]") {
  // 3x3 grid: group 0 on a diagonal and the corner (not 4-connected), group 1 elsewhere.
  //  0 1 1
  //  1 0 1
  //  0 1 0
  const DensePartition p({0, 1, 1, 1, 0, 1, 0, 1, 0}, 2);
  const DensePartition cc = connected_components(p, {3, 3});
  CHECK(cc.num_groups() == 7);  // four single 0s; 1s: {1,2,5}, {3}, {7}
  CHECK(cc.group_of(1) == cc.group_of(2));
  CHECK(cc.group_of(2) == cc.group_of(5));
  CHECK(cc.group_of(3) != cc.group_of(1));
  CHECK(cc.is_refinement_of(p));
  CHECK_THROWS_WITH(connected_components(p, {2, 2}), Catch::Contains("the 2x2 grid has 4 pixels"));
}

TEST_CASE("groups split into their components along an energy's edges", "[lift][connected]") {
  // Edges 0-1, 1-2, 3-4 (5 alone); group 0 = {0, 2, 3, 4}, group 1 = {1, 5}.
  const PairwiseEnergy energy(6, 2, std::vector<double>(12, 0.0), {PairwiseTerm::potts()},
                              {{0, 1, 1.0, 0}, {2, 1, 1.0, 0}, {4, 3, 1.0, 0}});
  const LiftingView view = lifting_view(energy);
  const DensePartition p({0, 1, 0, 0, 0, 1}, 2);
  const DensePartition cc = connected_components_along_edges(p, view);
  CHECK(cc.num_groups() == 5);  // 0s: {0}, {2}, {3, 4}; 1s: {1}, {5}
  CHECK(cc.group_of(3) == cc.group_of(4));
  CHECK(cc.group_of(0) != cc.group_of(2));
  CHECK(cc.group_of(1) != cc.group_of(5));
  CHECK(cc.is_refinement_of(p));
  CHECK_THROWS_WITH(connected_components_along_edges(DensePartition::identity(4), view),
                    Catch::Contains("the partition has 4 variables, the energy 6"));
  // On a grid energy the edges are the 4-neighbours: both versions agree.
  Rng rng(45);
  const PairwiseEnergy grid = random_grid_energy(rng, 9, 7, 3);
  const DensePartition groups = random_partition(rng, 63, 3);
  CHECK(connected_components_along_edges(groups, lifting_view(grid)) ==
        connected_components(groups, {9, 7}));
}

TEST_CASE("connected components keep refining sequences nested", "[lift][connected][property]") {
  Rng rng(44);
  for (int trial = 0; trial < 40; ++trial) {
    const PairwiseEnergy energy = random_grid_energy(rng, 10, 8, 3);
    const DensePartition coarse = random_partition(rng, 80, 4);
    const DensePartition fine = random_refinement(rng, coarse, 2);
    CHECK(connected_components(fine, {10, 8})
              .is_refinement_of(connected_components(coarse, {10, 8})));
    ScheduleProvider provider(vision::parse_stereo_schedule("paper-cc"), {10, 8});
    std::optional<DensePartition> previous;
    while (auto level = provider.next(energy)) {
      if (previous) CHECK(level->is_refinement_of(*previous));
      CHECK(*level == connected_components(*level, {10, 8}));  // already connected
      previous = std::move(level);
    }
  }
  CHECK(vision::parse_stereo_schedule("paper-cc").to_string() ==
        "cp:1,1/cc cp:2,1/cc cp:3,1/cc flat");
  CHECK(vision::parse_stereo_schedule("regions").to_string() ==
        "local:1,1/cc local:2,1/cc local:3,1/cc flat");
  CHECK(vision::parse_stereo_schedule("aggregated").to_string() == "agg:1/cc flat");
  CHECK_THROWS_WITH(vision::parse_stereo_schedule("regions flat"),
                    Catch::Contains("'regions' stands alone"));
  CHECK(Schedule::parse("threshold:5/cc blocks:4").levels[0].connected);
  CHECK_THROWS_WITH(Schedule::parse("auto:0.1/cc"), Catch::Contains("auto levels cannot take /cc"));
}

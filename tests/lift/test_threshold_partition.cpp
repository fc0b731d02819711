#include <catch2/catch.hpp>

#include "c2f/lift/threshold_partition.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("threshold partitions are single-linkage components of similar neighbours",
          "[lift][threshold]") {
  // A 4x1 row with unary rows (0,0), (0,1), (0,3), (0,3.5): L1 steps 1, 2, 0.5.
  const std::vector<double> unaries{0, 0, 0, 1, 0, 3, 0, 3.5};
  const PairwiseEnergy energy(4, 2, unaries, {}, {});
  auto groups = [&](double tau, int radius) {
    const DensePartition p = threshold_partition(energy, {4, 1}, tau, radius);
    return std::vector<VariableIndex>(p.group_ids().begin(), p.group_ids().end());
  };
  CHECK(groups(0.0, 1) == std::vector<VariableIndex>{0, 1, 2, 3});
  CHECK(groups(0.5, 1) == std::vector<VariableIndex>{0, 1, 2, 2});
  CHECK(groups(1.0, 1) == std::vector<VariableIndex>{0, 0, 1, 1});
  CHECK(groups(2.0, 1) ==
        std::vector<VariableIndex>{0, 0, 0, 0});  // chained: pixels 0 and 3 differ by 3.5
  CHECK(groups(3.0, 1) == std::vector<VariableIndex>{0, 0, 0, 0});
  // Radius 2 links pixels 1 and 3 (distance 2.5) directly.
  CHECK(groups(2.5, 2) == std::vector<VariableIndex>{0, 0, 0, 0});
  CHECK_THROWS_WITH(threshold_partition(energy, {4, 1}, -1.0), Catch::Contains("tau must be >= 0"));
  CHECK_THROWS_WITH(threshold_partition(energy, {4, 1}, 1.0, 0),
                    Catch::Contains("radius must be >= 1"));
  CHECK_THROWS_WITH(threshold_partition(energy, {2, 1}, 1.0),
                    Catch::Contains("the energy has 4 variables"));
}

TEST_CASE("smaller thresholds refine larger ones", "[lift][threshold][property]") {
  Rng rng(5);
  for (int trial = 0; trial < 30; ++trial) {
    const PairwiseEnergy energy = random_grid_energy(rng, 9, 8, 3);
    const int radius = 1 + trial % 3;
    DensePartition coarse = threshold_partition(energy, {9, 8}, 12.0, radius);
    for (double tau : {9.0, 6.0, 3.0, 0.0}) {
      const DensePartition fine = threshold_partition(energy, {9, 8}, tau, radius);
      CHECK(fine.is_refinement_of(coarse));
      CHECK(fine == threshold_partition(energy, {9, 8}, tau, radius));
      coarse = fine;
    }
  }
}

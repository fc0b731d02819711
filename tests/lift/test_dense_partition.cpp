#include <catch2/catch.hpp>

#include <vector>

#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/block_hierarchy.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/partition_list.hpp"

using namespace c2f;

TEST_CASE("partitions list their groups' members in ascending order", "[lift][partition]") {
  const DensePartition p({1, 0, 1, 2, 0}, 3);
  CHECK(p.num_variables() == 5);
  CHECK(p.num_groups() == 3);
  CHECK(p.group_of(2) == 1);
  CHECK(std::vector<VariableIndex>(p.members(0).begin(), p.members(0).end()) ==
        std::vector<VariableIndex>{1, 4});
  CHECK(std::vector<VariableIndex>(p.members(1).begin(), p.members(1).end()) ==
        std::vector<VariableIndex>{0, 2});
  CHECK(std::vector<VariableIndex>(p.members(2).begin(), p.members(2).end()) ==
        std::vector<VariableIndex>{3});
  CHECK_FALSE(p.is_identity());
  CHECK(DensePartition::identity(4).is_identity());
  CHECK(DensePartition::single_group(4).num_groups() == 1);
}

TEST_CASE("from_ids numbers groups by first occurrence", "[lift][partition]") {
  const std::vector<std::int64_t> ids{70, 5, 70, 9000000000, 5};
  const DensePartition p = DensePartition::from_ids(ids);
  CHECK(p == DensePartition({0, 1, 0, 2, 1}, 3));
  const std::vector<int> bad{0, -3};
  CHECK_THROWS_WITH(DensePartition::from_ids(bad), Catch::Contains("ids[1] = -3 is negative"));
}

TEST_CASE("partition construction validates group ids", "[lift][partition][validation]") {
  CHECK_THROWS_WITH(DensePartition({0, 3}, 2),
                    Catch::Contains("group_of[1] = 3 is out of range, num_groups = 2"));
  CHECK_THROWS_WITH(DensePartition({0, 2}, 3), Catch::Contains("group 1 has no members"));
}

TEST_CASE("is_refinement_of follows the definition", "[lift][partition]") {
  const DensePartition coarse({0, 0, 1, 1}, 2);
  const DensePartition fine({0, 1, 2, 2}, 3);
  const DensePartition crossing({0, 1, 1, 2}, 3);
  CHECK(fine.is_refinement_of(coarse));
  CHECK(coarse.is_refinement_of(coarse));
  CHECK(DensePartition::identity(4).is_refinement_of(coarse));
  CHECK(coarse.is_refinement_of(DensePartition::single_group(4)));
  CHECK_FALSE(coarse.is_refinement_of(fine));
  CHECK_FALSE(crossing.is_refinement_of(coarse));
  CHECK_FALSE(fine.is_refinement_of(DensePartition::identity(5)));
}

TEST_CASE("block partitions nest when each size divides the previous", "[lift][blocks]") {
  const GridShape shape{10, 7};
  const DensePartition b4 = block_partition(shape, 4);
  CHECK(b4.num_groups() == 3 * 2);
  CHECK(b4.group_of(9) == 2);       // x = 9 -> third block column
  CHECK(b4.group_of(4 * 10) == 3);  // y = 4 -> second block row
  CHECK(block_partition(shape, 2).is_refinement_of(b4));
  CHECK(block_partition(shape, 1).is_identity());
  CHECK_FALSE(block_partition(shape, 3).is_refinement_of(b4));

  const PairwiseEnergy energy(70, 2, std::vector<double>(140, 0.0), {}, {});
  BlockHierarchy hierarchy(shape, {8, 4, 2});
  auto first = hierarchy.next(energy);
  auto second = hierarchy.next(energy);
  auto third = hierarchy.next(energy);
  REQUIRE((first && second && third));
  CHECK(second->is_refinement_of(*first));
  CHECK(third->is_refinement_of(*second));
  CHECK_FALSE(hierarchy.next(energy).has_value());
  CHECK_FALSE(hierarchy.next(energy).has_value());

  CHECK_THROWS_WITH(BlockHierarchy(shape, {8, 3}),
                    Catch::Contains("block size 3 does not divide the previous size 8"));
  CHECK_THROWS_WITH(BlockHierarchy(shape, {0}), Catch::Contains("block size 0 is 0"));
  BlockHierarchy wrong_grid(GridShape{5, 5}, {2});
  CHECK_THROWS_WITH(wrong_grid.next(energy),
                    Catch::Contains("the energy has 70 variables, the 5x5 grid has 25 pixels"));
}

TEST_CASE("partition lists must refine and fit the energy", "[lift][partition][validation]") {
  const DensePartition coarse({0, 0, 1, 1}, 2);
  const DensePartition crossing({0, 1, 1, 2}, 3);
  CHECK_THROWS_WITH(PartitionList({coarse, crossing}),
                    Catch::Contains("partition 1 does not refine partition 0"));
  CHECK_THROWS_WITH(PartitionList({coarse, DensePartition::identity(5)}),
                    Catch::Contains("partition 1 covers 5 variables"));
  PartitionList list({coarse});
  const PairwiseEnergy five(5, 2, std::vector<double>(10, 0.0), {}, {});
  CHECK_THROWS_WITH(list.next(five),
                    Catch::Contains("partition 0 covers 4 variables, the energy has 5"));
}

TEST_CASE("intersect groups variables that share a group in both partitions", "[lift][partition]") {
  const DensePartition halves({0, 0, 0, 1, 1, 1}, 2);
  const DensePartition pairs({0, 1, 1, 2, 2, 0}, 3);
  const DensePartition both = intersect(halves, pairs);
  CHECK(both == DensePartition({0, 1, 1, 2, 2, 3}, 4));
  CHECK(both.is_refinement_of(halves));
  CHECK(both.is_refinement_of(pairs));
  CHECK(intersect(halves, halves) == halves);
  CHECK(intersect(halves, DensePartition::identity(6)) == DensePartition::identity(6));
  CHECK_THROWS_WITH(intersect(halves, DensePartition::identity(5)),
                    Catch::Contains("intersect: the partitions cover 6 and 5 variables"));
}

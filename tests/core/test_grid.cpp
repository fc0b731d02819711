#include <catch2/catch.hpp>

#include "c2f/core/grid.hpp"

using namespace c2f;

TEST_CASE("grid neighbour pairs cover 4- and 8-neighbourhoods in raster order", "[core][grid]") {
  const GridShape shape{4, 3};
  const auto four = grid_neighbour_pairs(shape, Connectivity::four);
  CHECK(four.size() == 3 * 3 + 4 * 2);
  CHECK(four[0] == std::pair<VariableIndex, VariableIndex>{0, 1});
  CHECK(four[1] == std::pair<VariableIndex, VariableIndex>{0, 4});
  const auto eight = grid_neighbour_pairs(shape, Connectivity::eight);
  CHECK(eight.size() == four.size() + 2 * 3 * 2);
  // Pixel 1 (x = 1, y = 0): right, down, down-right, down-left.
  CHECK(eight[3] == std::pair<VariableIndex, VariableIndex>{1, 2});
  CHECK(eight[4] == std::pair<VariableIndex, VariableIndex>{1, 5});
  CHECK(eight[5] == std::pair<VariableIndex, VariableIndex>{1, 6});
  CHECK(eight[6] == std::pair<VariableIndex, VariableIndex>{1, 4});
  for (const auto& [u, v] : eight) CHECK(u < v);
  CHECK_THROWS_WITH(grid_neighbour_pairs({0, 3}, Connectivity::four),
                    Catch::Contains("width and height must be >= 1"));
}

TEST_CASE("grid energies carry per-edge weights", "[core][grid]") {
  const GridShape shape{3, 2};
  const auto pairs = grid_neighbour_pairs(shape, Connectivity::four);
  const PairwiseEnergy e = make_grid_energy(
      shape, Connectivity::four, 2, std::vector<double>(12, 0.0), PairwiseTerm::potts(),
      [](VariableIndex u, VariableIndex v) { return u + 10.0 * v; });
  REQUIRE(e.edges().size() == pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    CHECK(e.edges()[i].u == pairs[i].first);
    CHECK(e.edges()[i].weight == pairs[i].first + 10.0 * pairs[i].second);
  }
  // All labels 0 except pixel 4: its edges (1,4), (3,4), (4,5) are cut.
  CHECK(e.evaluate(Labeling{0, 0, 0, 0, 1, 0}) == (1 + 40) + (3 + 40) + (4 + 50));
  const std::vector<double> too_few(3, 1.0);
  CHECK_THROWS_WITH(make_grid_energy(shape, Connectivity::four, 2, std::vector<double>(12, 0.0),
                                     PairwiseTerm::potts(), too_few),
                    Catch::Contains("edge_weights has 3 entries, the 3x2 grid has 7 edges"));
}

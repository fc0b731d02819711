#include <catch2/catch.hpp>

#include "c2f/core/grid.hpp"
#include "c2f/lift/colour_passing.hpp"
#include "c2f/lift/local_grouping.hpp"
#include "c2f/lift/reduce.hpp"
#include "c2f/lift/transfer.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

std::vector<VariableIndex> groups(const DensePartition& p) {
  return {p.group_ids().begin(), p.group_ids().end()};
}

/// A chain 0 - 1 - 2 - 3 - 4 (a 5x1 grid) where every pixel prefers label 0.
PairwiseEnergy uniform_chain() {
  std::vector<double> unaries;
  for (int v = 0; v < 5; ++v) unaries.insert(unaries.end(), {0.0, 1.0, 2.0});
  return make_grid_energy({5, 1}, Connectivity::four, 3, unaries, PairwiseTerm::potts(),
                          [](VariableIndex, VariableIndex) { return 1.0; });
}

}  // namespace

TEST_CASE("lowest-cost labels break ties by label index", "[lift][colour-passing]") {
  const std::vector<double> row{3.0, 1.0, 1.0, 0.5, 3.0};
  std::vector<Label> top(4);
  lowest_cost_labels(std::span<const double>(row), 4, top);
  CHECK(top == std::vector<Label>{3, 1, 2, 0});
  const std::vector<float> float_row(row.begin(), row.end());
  std::vector<Label> float_top(4);
  lowest_cost_labels(std::span<const float>(float_row), 4, float_top);
  CHECK(float_top == top);
}

TEST_CASE("colour passing on a chain finds its mirror symmetry", "[lift][colour-passing]") {
  const PairwiseEnergy chain = uniform_chain();
  ColourPassing cp(chain, 1);
  CHECK(cp.num_groups() == 1);  // CP(1, 0): one colour
  CHECK(cp.iterate());
  CHECK(groups(cp.partition()) == std::vector<VariableIndex>{0, 1, 1, 1, 0});  // ends vs interior
  CHECK(cp.iterate());
  CHECK(groups(cp.partition()) ==
        std::vector<VariableIndex>{0, 1, 2, 1, 0});  // distance to the ends
  CHECK_FALSE(cp.iterate());                         // stable: the mirror pairs stay together
  CHECK(cp.iterations() == 3);
}

TEST_CASE("the unary tuple and its increase split pixels by their best labels",
          "[lift][colour-passing]") {
  // 2x2 grid: pixels 0 and 3 rank labels (0, 1, 2), pixel 1 ranks (0, 2, 1), pixel 2 (1, 0, 2).
  const std::vector<double> unaries{0, 1, 2, 0, 2, 1, 1, 0, 2, 0, 1, 2};
  const PairwiseEnergy energy =
      make_grid_energy({2, 2}, Connectivity::four, 3, unaries, PairwiseTerm::potts(),
                       [](VariableIndex, VariableIndex) { return 1.0; });
  ColourPassing cp(energy, 1);
  cp.iterate();  // every pixel has two edges of the same class: only the best label matters
  CHECK(groups(cp.partition()) == std::vector<VariableIndex>{0, 0, 1, 0});
  cp.increase_labels();  // N_L = 2 separates pixel 1 by its second label
  CHECK(groups(cp.partition()) == std::vector<VariableIndex>{0, 1, 2, 0});
  CHECK(cp.labels() == 2);
  ColourPassing scratch(energy, 2);
  scratch.iterate();
  CHECK(scratch.partition() == cp.partition());  // CP(2, 1) either way
  cp.increase_labels();
  CHECK_THROWS_WITH(cp.increase_labels(),
                    Catch::Contains("N_L is already the number of labels (3)"));
  CHECK_THROWS_WITH(ColourPassing(energy, 4), Catch::Contains("N_L must be in [1, 3], got 4"));
}

TEST_CASE("pairwise factors are coloured by term and weight", "[lift][colour-passing]") {
  // Same unaries everywhere; the middle edge of a 4-chain has another weight.
  std::vector<double> unaries(8, 0.0);
  const PairwiseEnergy energy(4, 2, unaries, {PairwiseTerm::potts()},
                              {Edge{0, 1, 1.0, 0}, Edge{1, 2, 2.0, 0}, Edge{2, 3, 1.0, 0}});
  ColourPassing cp(energy, 1);
  cp.iterate();
  CHECK(groups(cp.partition()) == std::vector<VariableIndex>{0, 1, 1, 0});
}

TEST_CASE("colour passing only refines, is deterministic and reduces exactly",
          "[lift][colour-passing][property]") {
  Rng rng(61);
  for (int trial = 0; trial < 60; ++trial) {
    const PairwiseEnergy energy =
        random_grid_energy(rng, 6 + trial % 7, 5 + trial % 4, 3 + trial % 3);
    ColourPassing cp(energy, 1), twin(energy, 1);
    DensePartition previous = cp.partition();
    for (int step = 0; step < 6; ++step) {
      const bool raise = step % 2 == 1 && cp.labels() < energy.num_labels();
      if (raise) {
        cp.increase_labels();
        twin.increase_labels();
      } else {
        cp.iterate();
        twin.iterate();
      }
      const DensePartition current = cp.partition();
      CHECK(current.is_refinement_of(previous));
      CHECK(current == twin.partition());
      const PairwiseEnergy reduced = reduce(energy, current);
      const Labeling y = random_labeling(rng, reduced.num_variables(), energy.num_labels());
      CHECK(close_relative(reduced.evaluate(y), energy.evaluate(expand(y, current)), 1e-12));
      previous = current;
    }
  }
}

TEST_CASE("local grouping reproduces the reference's rule", "[lift][local-grouping]") {
  const PairwiseEnergy chain = uniform_chain();
  // Initial colouring: same tuple; pixels 0..3 own one (right) edge, pixel 4 none.
  CHECK(groups(local_grouping(chain, {5, 1}, 1, 1)) == std::vector<VariableIndex>{0, 0, 0, 0, 1});
  // A round adds the classes of the own edges, all equal here; neighbours never matter.
  CHECK(groups(local_grouping(chain, {5, 1}, 1, 2)) == std::vector<VariableIndex>{0, 0, 0, 0, 1});

  // 3x2 grid with one heavy edge (pixel 1 -> 2, a right edge): only pixel 1, which owns it,
  // is split off; pixel 2 (the other endpoint) is not, unlike genuine colour passing.
  const std::vector<double> unaries(12, 0.0);
  const PairwiseEnergy grid = make_grid_energy(
      {3, 2}, Connectivity::four, 2, unaries, PairwiseTerm::potts(),
      [](VariableIndex u, VariableIndex v) { return u == 1 && v == 2 ? 5.0 : 1.0; });
  // Owned edges: pixels 0, 1 own right + down; 2 owns down; 3, 4 own right; 5 owns none.
  CHECK(groups(local_grouping(grid, {3, 2}, 1, 1)) == std::vector<VariableIndex>{0, 0, 1, 1, 1, 2});
  CHECK(groups(local_grouping(grid, {3, 2}, 1, 2)) == std::vector<VariableIndex>{0, 1, 2, 2, 2, 3});
  ColourPassing genuine(grid, 1);
  genuine.iterate();
  CHECK(genuine.partition().group_of(2) !=
        genuine.partition().group_of(0));  // pixel 2 sees the heavy edge

  CHECK_THROWS_WITH(local_grouping(grid, {2, 2}, 1, 1), Catch::Contains("the 2x2 grid has 4"));
  CHECK_THROWS_WITH(local_grouping(grid, {3, 2}, 3, 1), Catch::Contains("N_L must be in [1, 2]"));
  CHECK_THROWS_WITH(local_grouping(grid, {3, 2}, 1, 0), Catch::Contains("N_iter must be >= 1"));
}

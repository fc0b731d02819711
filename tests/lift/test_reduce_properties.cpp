// Property tests of the reduction algebra over hundreds of random small energies:
// Theorem 1 (reduced energy == original energy of the expanded labeling), Corollary 1
// (reduced minimum >= original minimum) and energy-preserving transfers.

#include <catch2/catch.hpp>

#include <set>
#include <tuple>

#include "c2f/lift/reduce.hpp"
#include "c2f/lift/transfer.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// A random energy of 2-30 variables, 1-5 labels and up to 3 edges per variable.
PairwiseEnergy random_small_energy(Rng& rng) {
  const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 30)(rng);
  const int num_labels = std::uniform_int_distribution<int>(1, 5)(rng);
  return random_energy(rng, n, num_labels,
                       std::uniform_int_distribution<std::size_t>(0, 3 * n)(rng));
}

}  // namespace

TEST_CASE("reduced energy of y equals original energy of expand(y)", "[lift][reduce][property]") {
  Rng rng(20261121);
  for (int trial = 0; trial < 400; ++trial) {
    const PairwiseEnergy energy = random_small_energy(rng);
    const std::size_t n = energy.num_variables();
    const int num_labels = energy.num_labels();
    const DensePartition partition = random_partition(rng, n, n);
    const PairwiseEnergy reduced = reduce(energy, partition);
    REQUIRE(reduced.num_variables() == partition.num_groups());
    REQUIRE(reduced.num_labels() == num_labels);
    for (int sample = 0; sample < 5; ++sample) {
      const Labeling y = random_labeling(rng, reduced.num_variables(), num_labels);
      const double lifted = reduced.evaluate(y);
      const double ground = energy.evaluate(expand(y, partition));
      INFO("trial " << trial << ": reduced " << lifted << ", ground " << ground);
      CHECK(close_relative(lifted, ground, 1e-12));
    }
  }
}

TEST_CASE(
    "reduction merges edges: at most one edge per group pair, orientation (asymmetric terms only) "
    "and term",
    "[lift][reduce]") {
  Rng rng(7);
  for (int trial = 0; trial < 100; ++trial) {
    const PairwiseEnergy energy = random_grid_energy(rng, 9, 7, 3);
    const DensePartition partition = random_partition(rng, energy.num_variables(), 12);
    const PairwiseEnergy reduced = reduce(energy, partition);
    std::set<std::tuple<VariableIndex, VariableIndex, std::uint32_t>> seen;
    for (const Edge& e : reduced.edges()) {
      CHECK(e.u != e.v);
      const bool symmetric = reduced.terms()[e.term].is_symmetric();
      CHECK((!symmetric || e.u < e.v));
      CHECK(seen.insert({e.u, e.v, e.term}).second);
      if (symmetric) CHECK(seen.count({e.v, e.u, e.term}) == 0);
    }
    // The total weight is conserved between groups: sum over ground edges crossing groups.
    double crossing = 0.0;
    for (const Edge& e : energy.edges()) {
      if (partition.group_of(e.u) != partition.group_of(e.v)) crossing += e.weight;
    }
    double merged = 0.0;
    for (const Edge& e : reduced.edges()) merged += e.weight;
    CHECK(close_relative(crossing, merged, 1e-12));
  }
}

TEST_CASE("the identity partition reduces to the same energy values", "[lift][reduce]") {
  Rng rng(11);
  const PairwiseEnergy energy = random_energy(rng, 12, 4, 30);
  const PairwiseEnergy reduced = reduce(energy, DensePartition::identity(12));
  for (int sample = 0; sample < 20; ++sample) {
    const Labeling x = random_labeling(rng, 12, 4);
    CHECK(close_relative(reduced.evaluate(x), energy.evaluate(x), 1e-12));
  }
}

TEST_CASE("the minimum of a reduced energy is never below the original minimum (Corollary 1)",
          "[lift][reduce][property][brute-force]") {
  Rng rng(99);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 7)(rng);
    const int num_labels = std::uniform_int_distribution<int>(2, 3)(rng);
    const PairwiseEnergy energy = random_energy(rng, n, num_labels, 2 * n);
    const DensePartition partition = random_partition(rng, n, n);
    const BruteForceResult original = brute_force_minimum(energy);
    const BruteForceResult lifted = brute_force_minimum(reduce(energy, partition));
    INFO("trial " << trial);
    CHECK(lifted.energy >= original.energy - 1e-12 * std::max(1.0, std::abs(original.energy)));
    // The lifted optimum is a real labeling of the original problem with the same energy.
    CHECK(
        close_relative(energy.evaluate(expand(lifted.labeling, partition)), lifted.energy, 1e-12));
  }
}

TEST_CASE("transfer between refining partitions keeps the energy", "[lift][transfer][property]") {
  Rng rng(5);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 40)(rng);
    const int num_labels = std::uniform_int_distribution<int>(2, 6)(rng);
    const PairwiseEnergy energy = random_energy(rng, n, num_labels, 2 * n);
    const DensePartition coarse = random_partition(rng, n, std::max<std::size_t>(1, n / 4));
    const DensePartition fine = random_refinement(rng, coarse, 3);
    REQUIRE(fine.is_refinement_of(coarse));
    const Labeling y = random_labeling(rng, coarse.num_groups(), num_labels);
    const Labeling z = transfer_labels(y, coarse, fine);
    CHECK(expand(z, fine) == expand(y, coarse));
    CHECK(close_relative(reduce(energy, fine).evaluate(z), reduce(energy, coarse).evaluate(y),
                         1e-12));
  }
}

TEST_CASE("transfer and expand reject inputs that do not fit", "[lift][transfer][validation]") {
  const DensePartition coarse({0, 0, 1, 1}, 2);
  const DensePartition crossing({0, 1, 1, 2}, 3);
  CHECK_THROWS_WITH(transfer_labels(Labeling{0, 1}, coarse, crossing),
                    Catch::Contains("the target partition does not refine the source partition"));
  CHECK_THROWS_WITH(
      transfer_labels(Labeling{0}, coarse, DensePartition::identity(4)),
      Catch::Contains("the labeling has 1 entries, the source partition has 2 groups"));
  CHECK_THROWS_WITH(transfer_labels(Labeling{0, 1}, coarse, DensePartition::identity(5)),
                    Catch::Contains("cover 4 and 5 variables"));
  CHECK_THROWS_WITH(expand(Labeling{0, 1, 2}, coarse),
                    Catch::Contains("the labeling has 3 entries, the partition has 2 groups"));
  const PairwiseEnergy energy(5, 2, std::vector<double>(10, 0.0), {}, {});
  CHECK_THROWS_WITH(reduce(energy, coarse),
                    Catch::Contains("the partition has 4 variables, the energy has 5"));
}

TEST_CASE("edges inside a group fold their diagonal cost into the group's unary",
          "[lift][reduce]") {
  // Two variables in one group joined by a table edge with cost(l, l) = 10 + l.
  const PairwiseEnergy energy(2, 2, {1.0, 2.0, 3.0, 4.0},
                              {PairwiseTerm::table(2, {10.0, 0.0, 0.0, 11.0})},
                              {Edge{0, 1, 0.5, 0}});
  const PairwiseEnergy reduced = reduce(energy, DensePartition::single_group(2));
  REQUIRE(reduced.num_variables() == 1);
  CHECK(reduced.edges().empty());
  CHECK(reduced.unary(0, 0) == 1.0 + 3.0 + 5.0);
  CHECK(reduced.unary(0, 1) == 2.0 + 4.0 + 5.5);
}

TEST_CASE("a float energy reduces to the double reduction of its stored costs",
          "[lift][reduce][float]") {
  Rng rng(20261125);
  for (int trial = 0; trial < 100; ++trial) {
    const PairwiseEnergy energy = random_small_energy(rng);
    const std::size_t n = energy.num_variables();
    const int num_labels = energy.num_labels();
    c2f::FloatValues stored(energy.unaries().size());
    energy.unaries().visit([&](auto costs) {
      for (std::size_t i = 0; i < costs.size(); ++i) stored[i] = static_cast<float>(costs[i]);
    });
    const std::vector<Edge> edges(energy.edges().begin(), energy.edges().end());
    const std::vector<PairwiseTerm> terms(energy.terms().begin(), energy.terms().end());
    const PairwiseEnergy single =
        PairwiseEnergy::with_float_unaries(n, num_labels, stored, terms, edges);
    const PairwiseEnergy twin(n, num_labels, single.unaries().to_doubles(), terms, edges);
    const DensePartition partition = random_partition(rng, n, n);
    const PairwiseEnergy reduced = reduce(single, partition);
    CHECK_FALSE(reduced.single_precision());  // group sums stay in double
    CHECK(reduced.unaries().to_doubles() == reduce(twin, partition).unaries().to_doubles());
    for (int sample = 0; sample < 3; ++sample) {
      const Labeling y = random_labeling(rng, reduced.num_variables(), num_labels);
      CHECK(close_relative(reduced.evaluate(y), single.evaluate(expand(y, partition)), 1e-12));
    }
  }
}

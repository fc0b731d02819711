#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <random>
#include <vector>

#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/energy_tally.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "support/random_models.hpp"

using namespace c2f;

namespace {

/// Whether two doubles have the same bits.
bool same_bits(double a, double b) {
  return std::memcmp(&a, &b, sizeof a) == 0;
}

/// The sum of every unary and every edge cost in one pass, in order (no chunks).
double one_pass_sum(const PairwiseEnergy& energy, const Labeling& x) {
  double total = 0.0;
  for (std::size_t v = 0; v < energy.num_variables(); ++v) total += energy.unary(v, x[v]);
  for (const Edge& e : energy.edges()) total += energy.pairwise_cost(e, x[e.u], x[e.v]);
  return total;
}

}  // namespace

TEST_CASE("evaluate sums by chunks, equal to one pass up to rounding", "[core][energy][tally]") {
  test::Rng rng(11);
  const PairwiseEnergy small = test::random_grid_energy(rng, 30, 20, 5);
  const PairwiseEnergy large = test::random_grid_energy(rng, 130, 70, 5);
  for (const PairwiseEnergy* energy : {&small, &large}) {
    const Labeling x = test::random_labeling(rng, energy->num_variables(), energy->num_labels());
    CHECK(test::close_relative(energy->evaluate(x), one_pass_sum(*energy, x), 1e-12));
  }
}

TEST_CASE("EnergyTally evaluates changed labelings to evaluate's bits", "[core][energy][tally]") {
  test::Rng rng(5);
  // 9100 variables and about 18000 edges: several chunks of each.
  const PairwiseEnergy energy = test::random_grid_energy(rng, 130, 70, 6);
  const auto incidence = std::make_shared<const EdgeIncidence>(energy);
  const int threads = GENERATE(1, 2, 3);
  Labeling x = test::random_labeling(rng, energy.num_variables(), energy.num_labels());
  EnergyTally tally;
  CHECK_FALSE(tally.bound());
  tally.bind(energy, x, incidence, threads);
  REQUIRE(tally.bound());
  CHECK(same_bits(tally.value(), energy.evaluate(x)));
  std::uniform_int_distribution<std::size_t> variable(0, energy.num_variables() - 1);
  std::uniform_int_distribution<int> label(0, energy.num_labels() - 1);
  for (int round = 0; round < 40; ++round) {
    // Few changes (one chunk), many (every chunk), or none; some listed twice.
    const std::size_t count = round % 3 == 0 ? 3 : round % 3 == 1 ? 4000 : 0;
    Labeling candidate = x;
    std::vector<VariableIndex> changed;
    for (std::size_t k = 0; k < count; ++k) {
      const auto v = static_cast<VariableIndex>(variable(rng));
      candidate[v] = static_cast<Label>(label(rng));
      changed.push_back(v);
      if (k % 7 == 0) changed.push_back(v);
    }
    const double value = tally.evaluate_changed(candidate, changed);
    CHECK(same_bits(value, energy.evaluate(candidate)));
    CHECK(same_bits(tally.value(), energy.evaluate(x)));  // not kept yet
    if (round % 2 == 0) {
      tally.keep();
      x = candidate;
    }
    CHECK(same_bits(tally.value(), energy.evaluate(x)));
  }
  // keep() twice keeps the same labeling.
  x[0] = static_cast<Label>((x[0] + 1) % energy.num_labels());
  const std::vector<VariableIndex> first{0};
  (void)tally.evaluate_changed(x, first);
  tally.keep();
  tally.keep();
  CHECK(same_bits(tally.value(), energy.evaluate(x)));
}

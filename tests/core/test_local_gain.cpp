#include <catch2/catch.hpp>

#include <algorithm>
#include <cstddef>
#include <random>
#include <vector>

#include "c2f/core/local_gain.hpp"
#include "support/random_models.hpp"
#include "support/tiny_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// What variable v would gain alone from labeling x, from whole-energy evaluations.
double gain_by_evaluation(const PairwiseEnergy& energy, const Labeling& x, std::size_t v) {
  const double now = energy.evaluate(x);
  double best = now;
  Labeling changed = x;
  for (Label l = 0; l < energy.num_labels(); ++l) {
    changed[v] = l;
    best = std::min(best, energy.evaluate(changed));
  }
  return now - best;
}

}  // namespace

TEST_CASE("local_gain sums what each variable would gain alone", "[core][local_gain]") {
  Rng rng(2024);
  for (int labels = 2; labels <= 5; ++labels) {
    std::vector<PairwiseTerm> terms = test_terms(rng, labels);
    // An asymmetric table too: the variable's side of each edge matters.
    std::uniform_real_distribution<double> cost(-1.0, 2.0);
    std::vector<double> table(static_cast<std::size_t>(labels * labels));
    for (double& c : table) c = cost(rng);
    terms.push_back(PairwiseTerm::table(labels, table));
    for (const PairwiseTerm& term : terms) {
      for (int shape = 0; shape < 3; ++shape) {
        const PairwiseEnergy energy = tiny_model(rng, shape, labels, term);
        const Labeling x = random_labeling(rng, energy.num_variables(), labels);
        double expected = 0.0;
        for (std::size_t v = 0; v < energy.num_variables(); ++v)
          expected += gain_by_evaluation(energy, x, v);
        CHECK(local_gain(energy, x) == Approx(expected).margin(1e-9));
      }
    }
  }
}

TEST_CASE("local_gain visits every s-th variable within its cost budget", "[core][local_gain]") {
  Rng rng(7);
  const PairwiseEnergy energy = random_grid_energy(rng, 9, 7, 4);  // 63 variables, 252 costs
  const Labeling x = random_labeling(rng, energy.num_variables(), 4);
  CHECK(local_gain(energy, x, 252) == Approx(local_gain(energy, x)).margin(1e-9));
  // 60 costs: 15 variables at most, so every 8th (the least power of two visiting <= 15):
  // variables 0, 8, ..., 56, their sum scaled by 63 / 8.
  double visited = 0.0;
  for (std::size_t v = 0; v < energy.num_variables(); v += 8)
    visited += gain_by_evaluation(energy, x, v);
  CHECK(local_gain(energy, x, 60) == Approx(visited * 63.0 / 8.0).margin(1e-9));
  // At a labeling no variable improves alone, nothing to gain.
  Labeling descended = x;
  for (bool changed = true; changed;) {
    changed = false;
    for (std::size_t v = 0; v < descended.size(); ++v) {
      Labeling candidate = descended;
      for (Label l = 0; l < 4; ++l) {
        candidate[v] = l;
        if (energy.evaluate(candidate) < energy.evaluate(descended) - 1e-12) {
          descended[v] = l;
          changed = true;
        }
      }
    }
  }
  CHECK(local_gain(energy, descended) == Approx(0.0).margin(1e-9));
}

TEST_CASE("local_gain refuses a labeling that is not the energy's", "[core][local_gain]") {
  Rng rng(3);
  const PairwiseEnergy energy = random_grid_energy(rng, 4, 3, 3);
  CHECK_THROWS_WITH(
      local_gain(energy, Labeling(11, 0)),
      Catch::Contains("local_gain: labeling: has 11 entries, expected num_variables = 12"));
  Labeling bad(12, 0);
  bad[5] = 3;
  CHECK_THROWS_WITH(local_gain(energy, bad),
                    Catch::Contains("label 3 of variable 5 is out of range"));
}

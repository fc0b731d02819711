#include <catch2/catch.hpp>

#include "c2f/adapters/icm/icm.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("ICM never increases the energy and stops in a single-site local minimum",
          "[icm][property]") {
  Rng rng(17);
  for (int trial = 0; trial < 100; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 25)(rng);
    const int num_labels = std::uniform_int_distribution<int>(2, 5)(rng);
    const PairwiseEnergy energy = random_energy(rng, n, num_labels, 2 * n);
    IcmSolver solver(IcmOptions{trial % 2 ? VisitOrder::random : VisitOrder::sequential, 5, 1e-12});
    solver.bind(energy, random_labeling(rng, n, num_labels));
    double previous = solver.energy();
    CHECK(close_relative(previous, energy.evaluate(solver.labeling()), 1e-12));
    for (int step = 0; step < 200; ++step) {
      const double now = solver.step();
      CHECK(now <= previous + 1e-12 * std::max(1.0, std::abs(previous)));
      CHECK(now == energy.evaluate(solver.labeling()));
      previous = now;
      if (solver.last_step().changed == 0) break;
    }
    REQUIRE(solver.last_step().changed == 0);
    // No single variable can lower the energy by changing its label alone.
    Labeling x(solver.labeling().begin(), solver.labeling().end());
    const double at_minimum = energy.evaluate(x);
    for (std::size_t v = 0; v < n; ++v) {
      const Label keep = x[v];
      for (Label l = 0; l < num_labels; ++l) {
        x[v] = l;
        CHECK(energy.evaluate(x) >= at_minimum - 1e-9);
      }
      x[v] = keep;
    }
  }
}

TEST_CASE("ICM reaches the brute-force optimum on a chain with dominant unaries",
          "[icm][brute-force]") {
  // Unaries dominate the Potts weights, so the optimum is the unary argmin and ICM finds it.
  const PairwiseEnergy energy(4, 3, {0, 9, 9, 9, 0, 9, 9, 9, 0, 0, 9, 9}, {PairwiseTerm::potts()},
                              {Edge{0, 1, 1.0, 0}, Edge{1, 2, 1.0, 0}, Edge{2, 3, 1.0, 0}});
  IcmSolver solver;
  solver.bind(energy, Labeling{2, 2, 1, 1});
  while (solver.step() > brute_force_minimum(energy).energy && solver.last_step().changed > 0) {
  }
  CHECK(solver.energy() == brute_force_minimum(energy).energy);
}

TEST_CASE("ICM validates its inputs", "[icm][validation]") {
  const PairwiseEnergy energy(2, 2, {0, 1, 1, 0}, {PairwiseTerm::potts()}, {Edge{0, 1, 1.0, 0}});
  IcmSolver solver;
  CHECK_THROWS_WITH(solver.step(), Catch::Contains("call bind() first"));
  CHECK_THROWS_WITH(solver.bind(energy, Labeling{0}),
                    Catch::Contains("IcmSolver::bind: start: has 1 entries"));
  CHECK_THROWS_WITH(solver.bind(energy, Labeling{0, 5}),
                    Catch::Contains("label 5 of variable 1 is out of range"));
  CHECK_THROWS_WITH(IcmSolver(IcmOptions{VisitOrder::sequential, 1, -1.0}),
                    Catch::Contains("tolerance"));
  CHECK(visit_order_from_string("random") == VisitOrder::random);
  CHECK_THROWS_WITH(visit_order_from_string("spiral"), Catch::Contains("'spiral'"));
}

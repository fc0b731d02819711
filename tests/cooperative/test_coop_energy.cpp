// The cooperative-cut energy: hand-computed values, exact reduction, the auxiliary-variable
// identity E(x) = min_h E_h(x) + const, and the Potts baseline.

#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <vector>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/lift/transfer.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("the cooperative-cut energy of a tiny graph, by hand", "[segmentation][coop]") {
  // Chain 0 - 1 - 2, two labels, K = 1 (class 0 cooperative, class 1 linear).
  // Edge (0,1): u side class 0 weight 2, v side class 0 weight 2.
  // Edge (1,2): u side class 0 weight 4, v side class 1 (linear) weight 4.
  // T_0 = 2 + 2 + 4 = 8; theta 0.25: breakpoint 2; alpha 0.5; lambda 2.
  const std::vector<double> unaries{0.0, 1.0, /**/ 3.0, 0.5, /**/ 1.0, 0.0};
  const CoopEnergy energy(3, 2, unaries, 1, {8.0}, {2.0, 0.25, 0.5},
                          {{0, 1, 0, 1, 2}, {1, 2, 2, 3, 4}},
                          {{0, 2.0}, {0, 2.0}, {0, 4.0}, {1, 4.0}});
  CHECK(energy.breakpoint(0) == 2.0);
  // x = (0, 0, 0): nothing cut: 0 + 3 + 1 = 4.
  CHECK(energy.evaluate(Labeling{0, 0, 0}) == 4.0);
  // x = (0, 1, 1): edge (0,1) cut; S_00 = 1 (u side, label 0), S_10 = 1 (v side, label 1).
  // F(1) = min(1, 0.5 + 0.5 * 2) = 1 each: pairwise 2; unaries 0 + 0.5 + 0 = 0.5; E = 0.5 + 2*2.
  CHECK(energy.evaluate(Labeling{0, 1, 1}) == 4.5);
  // x = (0, 0, 1): edge (1,2) cut: S_00 = 2 (u side of (1,2), weight 4 / 2), linear 2 (v side).
  // F(2) = min(2, 1 + 1) = 2; pairwise 2 + 2 = 4; unaries 0 + 3 + 0 = 3; E = 3 + 2 * 4 = 11.
  CHECK(energy.evaluate(Labeling{0, 0, 1}) == 11.0);
  // x = (1, 0, 1): both cut: S_10 = 1 (u of (0,1)), S_00 = 1 (v of (0,1)) + 2 (u of (1,2)) = 3,
  // linear 2. F(1) = 1, F(3) = min(3, 1.5 + 1) = 2.5; pairwise 1 + 2.5 + 2 = 5.5;
  // unaries 1 + 3 + 0 = 4; E = 4 + 2 * 5.5 = 15.
  CHECK(energy.evaluate(Labeling{1, 0, 1}) == 15.0);
  CHECK_THROWS_WITH(energy.evaluate(Labeling{0, 2, 0}), Catch::Contains("label 2"));
  CHECK_THROWS_WITH(CoopEnergy(2, 2, {0, 0, 0, 0}, 1, {1.0}, {1.0, 0.5, 1.0}, {}, {}),
                    Catch::Contains("alpha must be in [0, 1)"));
  CHECK_THROWS_WITH(
      CoopEnergy(2, 2, {0, 0, 0, 0}, 1, {1.0}, {}, {{0, 1, 0, 1, 2}}, {{0, 1.0}, {2, 1.0}}),
      Catch::Contains("entries[1] needs a class <= 1"));
}

TEST_CASE("reducing a cooperative-cut energy is exact", "[segmentation][coop][reduce][property]") {
  Rng rng(71);
  for (int trial = 0; trial < 40; ++trial) {
    const int L = 2 + trial % 3;
    const CoopEnergy energy =
        random_coop_energy(rng, 6, 5, L, 3, {1.0 + trial % 2, 0.1, 0.25 * (trial % 3)});
    const DensePartition coarse = random_partition(rng, energy.num_variables(), 8);
    const DensePartition fine = random_refinement(rng, coarse, 3);
    const CoopEnergy reduced = reduce(energy, coarse);
    CHECK(reduced.num_variables() == coarse.num_groups());
    for (int sample = 0; sample < 10; ++sample) {
      const Labeling y = random_labeling(rng, coarse.num_groups(), L);
      const double ground = energy.evaluate(expand(y, coarse));
      CHECK(close_relative(reduced.evaluate(y), ground, 1e-12));
      // Reducing twice (coarse of the reduced fine level) keeps the energy too.
      const CoopEnergy fine_reduced = reduce(energy, fine);
      CHECK(close_relative(fine_reduced.evaluate(transfer_labels(y, coarse, fine)), ground, 1e-12));
    }
  }
  CHECK_THROWS_WITH(reduce(random_coop_energy(rng, 3, 3, 2, 2), DensePartition::identity(4)),
                    Catch::Contains("the partition has 4 variables, the energy 9"));
}

TEST_CASE("E is the minimum over h of the pairwise energies E_h plus their constants",
          "[segmentation][coop][aux][property]") {
  Rng rng(5);
  for (int trial = 0; trial < 30; ++trial) {
    const int L = 2 + trial % 3, K = 3;
    const CoopEnergy energy =
        random_coop_energy(rng, 5, 4, L, K, {1.5, 0.08, trial % 2 ? 0.3 : 0.0});
    const DensePartition groups = random_partition(rng, energy.num_variables(), 7);
    for (const CoopEnergy& e : {energy, reduce(energy, groups)}) {
      for (int sample = 0; sample < 8; ++sample) {
        const Labeling x = random_labeling(rng, e.num_variables(), L);
        const double exact = e.evaluate(x);
        const CoopAuxiliary best = CoopAuxiliary::optimal_for(e, x);
        CHECK(close_relative(pairwise_energy(e, best).evaluate(x) + aux_constant(e, best), exact,
                             1e-12));
        CoopAuxiliary other(L, K);
        for (int l = 0; l < L; ++l)
          for (int g = 0; g < K; ++g) other.set(l, g, std::bernoulli_distribution(0.5)(rng));
        CHECK(pairwise_energy(e, other).evaluate(x) + aux_constant(e, other) >= exact - 1e-9);
      }
    }
    // The Potts baseline is E_h for h all 1 (no constant).
    const Labeling x = random_labeling(rng, energy.num_variables(), L);
    CHECK(close_relative(potts_energy(energy).evaluate(x),
                         pairwise_energy(energy, CoopAuxiliary(L, K)).evaluate(x), 1e-12));
  }
}

TEST_CASE("E_h's expansion moves are submodular, so two-label moves are exact for a fixed h",
          "[segmentation][coop][aux][brute-force]") {
  Rng rng(12);
  for (int trial = 0; trial < 20; ++trial) {
    const CoopEnergy energy = random_coop_energy(rng, 3, 3, 2, 2, {2.0, 0.1, 0.0});
    CoopAuxiliary h(2, 2);
    h.set(trial % 2, trial % 2, false);
    const PairwiseEnergy pairwise = pairwise_energy(energy, h);
    ExpansionSolver<> solver;
    solver.bind(pairwise, Labeling(9, 0));
    for (int step = 0; step < 6; ++step) {
      solver.step();
      CHECK_FALSE(solver.last_step().used_qpbo);
    }
    CHECK(close_relative(solver.energy(), brute_force_minimum(pairwise).energy, 1e-12));
  }
}

TEST_CASE("colour passing sees a cooperative-cut edge by its ordered side classes",
          "[segmentation][coop][lift]") {
  Rng rng(3);
  const CoopEnergy energy = random_coop_energy(rng, 4, 3, 3, 2);
  const LiftingView view = lifting_view(energy);
  REQUIRE(view.factors.size() == energy.edges().size());
  for (std::size_t a = 0; a < view.factors.size(); ++a) {
    CHECK_FALSE(view.factors[a].symmetric);
    for (std::size_t b = 0; b < view.factors.size(); ++b) {
      const auto& ea = energy.edges()[a];
      const auto& eb = energy.edges()[b];
      const bool same = energy.u_side(ea)[0].edge_class == energy.u_side(eb)[0].edge_class &&
                        energy.v_side(ea)[0].edge_class == energy.v_side(eb)[0].edge_class;
      CHECK((view.factors[a].colour == view.factors[b].colour) == same);
    }
  }
}

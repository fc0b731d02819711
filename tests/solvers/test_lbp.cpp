#include <catch2/catch.hpp>

#include "c2f/adapters/lbp/lbp.hpp"
#include "support/tiny_models.hpp"

using namespace c2f;
using namespace c2f::test;

TEST_CASE("belief propagation is exact on trees", "[lbp][brute-force]") {
  Rng rng(8080);
  for (int trial = 0; trial < 120; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 8)(rng);
    const int num_labels = 2 + trial % 3;
    const auto terms = test_terms(rng, num_labels);
    std::vector<PairwiseTerm> all_terms(terms.begin(), terms.end());
    std::vector<double> asymmetric(static_cast<std::size_t>(num_labels * num_labels));
    for (double& c : asymmetric) c = std::uniform_real_distribution<double>(-1.0, 2.0)(rng);
    all_terms.push_back(PairwiseTerm::table(num_labels, asymmetric));
    // A random tree: every node after the first attaches to an earlier one, in either orientation.
    std::vector<Edge> edges;
    std::uniform_real_distribution<double> weight(-0.5, 2.0);
    for (VariableIndex v = 1; v < n; ++v) {
      const auto parent = std::uniform_int_distribution<VariableIndex>(0, v - 1)(rng);
      const auto term = std::uniform_int_distribution<std::uint32_t>(
          0, static_cast<std::uint32_t>(all_terms.size() - 1))(rng);
      edges.push_back(trial % 2 ? Edge{parent, v, weight(rng), term}
                                : Edge{v, parent, weight(rng), term});
    }
    std::vector<double> unaries(n * static_cast<std::size_t>(num_labels));
    for (double& u : unaries) u = std::uniform_real_distribution<double>(-2.0, 2.0)(rng);
    const PairwiseEnergy energy(n, num_labels, std::move(unaries), all_terms, std::move(edges));
    LbpSolver solver(
        LbpOptions{trial % 4 < 2 ? BpSchedule::sequential : BpSchedule::parallel, 0.0});
    solver.bind(energy, Labeling(n, 0));
    double previous = solver.energy();
    for (std::size_t iteration = 0; iteration < n + 1; ++iteration) {
      const double now = solver.step();
      CHECK(now <= previous);
      CHECK(now == energy.evaluate(solver.labeling()));
      previous = now;
    }
    INFO("trial " << trial);
    CHECK(close_relative(previous, brute_force_minimum(energy).energy, 1e-9));
    CHECK(solver.last_step().message_change < 1e-9);  // converged to the fixed point
  }
}

TEST_CASE("loopy BP with damping reports a never-increasing energy on grids", "[lbp]") {
  Rng rng(6);
  for (int trial = 0; trial < 40; ++trial) {
    const int num_labels = 2 + trial % 3;
    const auto terms = test_terms(rng, num_labels);
    const PairwiseEnergy energy = tiny_model(rng, trial % 3, num_labels,
                                             terms[static_cast<std::size_t>(trial) % terms.size()]);
    LbpSolver solver(LbpOptions{trial % 2 ? BpSchedule::parallel : BpSchedule::sequential, 0.5});
    solver.bind(energy, random_labeling(rng, energy.num_variables(), num_labels));
    double previous = solver.energy();
    for (int iteration = 0; iteration < 30; ++iteration) {
      const double now = solver.step();
      CHECK(now <= previous);
      CHECK(now == energy.evaluate(solver.labeling()));
      previous = now;
    }
    CHECK(previous >= brute_force_minimum(energy).energy - 1e-9);
  }
}

TEST_CASE("the fast message updates equal the generic O(L^2) update", "[lbp]") {
  // The same chain with a parametric term and with the equivalent table gives identical runs.
  Rng rng(10);
  const int num_labels = 7;
  for (const PairwiseTerm& term :
       {PairwiseTerm::potts(), PairwiseTerm::truncated_linear(2.5), PairwiseTerm::tsgo_step()}) {
    std::vector<double> table(num_labels * num_labels);
    for (int a = 0; a < num_labels; ++a) {
      for (int b = 0; b < num_labels; ++b) table[a * num_labels + b] = term.cost(a, b);
    }
    const PairwiseEnergy parametric = tiny_model(rng, 0, num_labels, term);
    const PairwiseEnergy tabulated(
        parametric.num_variables(), num_labels, parametric.unaries().to_doubles(),
        {PairwiseTerm::table(num_labels, table)},
        std::vector<Edge>(parametric.edges().begin(), parametric.edges().end()));
    LbpSolver fast, generic;
    fast.bind(parametric, Labeling(9, 0));
    generic.bind(tabulated, Labeling(9, 0));
    for (int iteration = 0; iteration < 10; ++iteration) {
      CHECK(fast.step() == Approx(generic.step()).epsilon(1e-12));
      CHECK(std::equal(fast.decoded().begin(), fast.decoded().end(), generic.decoded().begin()));
    }
  }
}

TEST_CASE("LBP validates its options and inputs", "[lbp][validation]") {
  CHECK_THROWS_WITH(LbpSolver(LbpOptions{BpSchedule::sequential, 1.0}),
                    Catch::Contains("damping must be in [0, 1)"));
  LbpSolver solver;
  CHECK_THROWS_WITH(solver.step(), Catch::Contains("call bind() first"));
  CHECK(bp_schedule_from_string("parallel") == BpSchedule::parallel);
  CHECK_THROWS_WITH(bp_schedule_from_string("async"), Catch::Contains("'async'"));
}

// Alpha-expansion and alpha-beta swap against brute force on tiny models.

#include <catch2/catch.hpp>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/adapters/graphcut/swap.hpp"
#include "support/backends.hpp"
#include "support/tiny_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

constexpr VisitOrder kOrders[] = {VisitOrder::sequential, VisitOrder::random,
                                  VisitOrder::frequency};

/// Steps until `sweep` consecutive steps change nothing; checks the energy never increases
/// and always equals evaluate() of the labeling. Returns the final energy.
template <class Solver>
double run_to_convergence(Solver& solver, const PairwiseEnergy& energy, std::size_t sweep) {
  double previous = solver.energy();
  std::size_t quiet = 0;
  for (int step = 0; step < 2000 && quiet < sweep; ++step) {
    const double now = solver.step();
    CHECK(now <= previous);
    CHECK(now == energy.evaluate(solver.labeling()));
    quiet = now < previous ? 0 : quiet + 1;
    previous = now;
  }
  return previous;
}

}  // namespace

TEMPLATE_TEST_CASE("alpha-expansion never increases the energy and stays near the optimum",
                   "[expansion][brute-force]", C2F_MAXFLOW_BACKENDS) {
  Rng rng(2024);
  int qpbo_moves = 0;
  for (int trial = 0; trial < 150; ++trial) {
    const int num_labels = 2 + trial % 3;
    auto terms = test_terms(rng, num_labels);
    std::vector<double> asymmetric(static_cast<std::size_t>(num_labels * num_labels));
    for (double& c : asymmetric) c = std::uniform_real_distribution<double>(-1.0, 2.0)(rng);
    terms.push_back(PairwiseTerm::table(num_labels, asymmetric));  // any table: QPBO handles it
    const PairwiseTerm& term = terms[static_cast<std::size_t>(trial / 3) % terms.size()];
    const PairwiseEnergy energy = tiny_model(rng, trial % 3, num_labels, term);
    ExpansionSolver<TestType> solver(
        ExpansionOptions{kOrders[trial % 3], static_cast<std::uint64_t>(trial), 0.0});
    solver.bind(energy, random_labeling(rng, energy.num_variables(), num_labels));
    double previous = solver.energy();
    std::size_t quiet = 0;
    for (int step = 0; step < 500 && quiet < solver.steps_per_sweep(energy.num_labels()); ++step) {
      const double now = solver.step();
      qpbo_moves += solver.last_step().used_qpbo;
      CHECK(now <= previous);
      CHECK(now == energy.evaluate(solver.labeling()));
      quiet = now < previous ? 0 : quiet + 1;
      previous = now;
    }
    const double optimum = brute_force_minimum(energy).energy;
    INFO("trial " << trial << ", term " << to_string(term.kind()));
    CHECK(previous >= optimum - 1e-9);
    if (num_labels == 2 && term.kind() == TermKind::potts) {
      // Two labels, Potts: one expansion move is the whole (submodular) problem.
      CHECK(close_relative(previous, optimum, 1e-9));
    }
  }
  // The TSGO step term makes moves non-submodular: QPBO was exercised.
  CHECK(qpbo_moves > 0);
}

TEST_CASE("alpha-expansion on Potts is within the factor-2 bound of the optimum",
          "[expansion][brute-force]") {
  // Boykov et al.: with a Potts term and non-negative costs, a labeling where no expansion
  // move helps has energy at most 2 * optimum.
  Rng rng(9);
  for (int trial = 0; trial < 60; ++trial) {
    const int num_labels = 3 + trial % 2;
    PairwiseEnergy raw = tiny_model(rng, trial % 3, num_labels, PairwiseTerm::potts());
    std::vector<double> unaries(raw.unaries().begin(), raw.unaries().end());
    for (double& u : unaries) u += 2.0;  // tiny_model draws unaries in [-2, 4)
    const PairwiseEnergy energy(raw.num_variables(), num_labels, std::move(unaries),
                                {PairwiseTerm::potts()},
                                std::vector<Edge>(raw.edges().begin(), raw.edges().end()));
    ExpansionSolver<> solver;
    solver.bind(energy, Labeling(energy.num_variables(), 0));
    const double converged =
        run_to_convergence(solver, energy, solver.steps_per_sweep(energy.num_labels()));
    CHECK(converged <= 2.0 * brute_force_minimum(energy).energy + 1e-9);
  }
}

TEST_CASE("alpha-beta swap never increases the energy and solves two-label Potts exactly",
          "[swap][brute-force]") {
  Rng rng(55);
  for (int trial = 0; trial < 120; ++trial) {
    const int num_labels = 2 + trial % 3;
    const auto terms = test_terms(rng, num_labels);
    const PairwiseTerm& term = terms[static_cast<std::size_t>(trial / 3) % terms.size()];
    const PairwiseEnergy energy = tiny_model(rng, trial % 3, num_labels, term);
    SwapSolver<> solver(SwapOptions{kOrders[trial % 3], 3});
    solver.bind(energy, random_labeling(rng, energy.num_variables(), num_labels));
    const std::size_t pairs = static_cast<std::size_t>(num_labels * (num_labels - 1) / 2);
    const double converged = run_to_convergence(solver, energy, pairs);
    const double optimum = brute_force_minimum(energy).energy;
    CHECK(converged >= optimum - 1e-9);
    if (num_labels == 2 && term.kind() == TermKind::potts)
      CHECK(close_relative(converged, optimum, 1e-9));
  }
}

TEST_CASE("swap rejects terms that are not semi-metrics", "[swap][validation]") {
  const std::vector<double> zeros(4, 0.0);
  const PairwiseEnergy diagonal(2, 2, zeros, {PairwiseTerm::table(2, {1.0, 2.0, 2.0, 0.0})},
                                {Edge{0, 1, 1.0, 0}});
  SwapSolver<> solver;
  CHECK_THROWS_WITH(solver.bind(diagonal, Labeling{0, 0}),
                    Catch::Contains("term 0 (table) is not a semi-metric: cost(0, 0) != 0"));
  const PairwiseEnergy asymmetric(2, 2, zeros, {PairwiseTerm::table(2, {0.0, 2.0, 1.0, 0.0})},
                                  {Edge{0, 1, 1.0, 0}});
  CHECK_THROWS_WITH(solver.bind(asymmetric, Labeling{0, 0}),
                    Catch::Contains("cost(0, 1) is negative or asymmetric"));
  const PairwiseEnergy negative(2, 2, zeros, {PairwiseTerm::potts()}, {Edge{0, 1, -1.0, 0}});
  CHECK_THROWS_WITH(solver.bind(negative, Labeling{0, 0}),
                    Catch::Contains("edge 0 has negative weight"));
  CHECK_THROWS_WITH(solver.step(), Catch::Contains("call bind() first"));
}

TEST_CASE("expansion validates its options and inputs", "[expansion][validation]") {
  CHECK_THROWS_WITH(ExpansionSolver<>(ExpansionOptions{VisitOrder::sequential, 1, -1.0}),
                    Catch::Contains("tolerance"));
  ExpansionSolver<> solver;
  CHECK_THROWS_WITH(solver.step(), Catch::Contains("call bind() first"));
  const PairwiseEnergy energy(2, 3, std::vector<double>(6, 0.0), {PairwiseTerm::potts()},
                              {Edge{0, 1, 1.0, 0}});
  CHECK_THROWS_WITH(solver.bind(energy, Labeling{0, 3}),
                    Catch::Contains("ExpansionSolver::bind: start: label 3"));
  CHECK(visit_order_from_string("random") == VisitOrder::random);
  CHECK(visit_order_from_string("frequency") == VisitOrder::frequency);
  CHECK_THROWS_WITH(visit_order_from_string("reverse"), Catch::Contains("'reverse'"));
}

TEST_CASE("frequency order visits the labels the start labeling uses most first",
          "[expansion][swap][order]") {
  // 9 variables in a chain, 4 labels; the start uses label 2 four times, 0 three times, 3
  // twice and 1 never: expansion visits 2, 0, 3, 1 and then starts over; swap visits the pairs
  // by the summed use of their labels, ties in (a, b) order.
  std::vector<Edge> chain;
  for (VariableIndex i = 0; i + 1 < 9; ++i) chain.push_back(Edge{i, i + 1, 1.0, 0});
  const PairwiseEnergy energy(9, 4, std::vector<double>(36, 0.0), {PairwiseTerm::potts()}, chain);
  const Labeling start{2, 0, 2, 3, 0, 2, 3, 0, 2};
  ExpansionSolver<> expansion(ExpansionOptions{VisitOrder::frequency});
  expansion.bind(energy, start);
  std::vector<Label> visited;
  for (int step = 0; step < 8; ++step) {
    expansion.step();
    visited.push_back(expansion.last_step().alpha);
  }
  CHECK(visited == std::vector<Label>{2, 0, 3, 1, 2, 0, 3, 1});

  SwapSolver<> swap(SwapOptions{VisitOrder::frequency});
  swap.bind(energy, start);
  std::vector<std::pair<Label, Label>> pairs;
  for (int step = 0; step < 6; ++step) {
    swap.step();
    pairs.push_back(std::pair{swap.last_step().alpha, swap.last_step().beta});
  }
  // Uses: 0 -> 3, 1 -> 0, 2 -> 4, 3 -> 2. Sums: (0,2) 7, (2,3) 6, (0,3) 5, (1,2) 4, (0,1) 3,
  // (1,3) 2.
  const std::vector<std::pair<Label, Label>> expected{{0, 2}, {2, 3}, {0, 3},
                                                      {1, 2}, {0, 1}, {1, 3}};
  CHECK(pairs == expected);
}

#include <catch2/catch.hpp>

#include "c2f/adapters/lbp/lbp.hpp"
#include "support/random_models.hpp"
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
    // Every schedule is exact on trees; bands of 3 variables take some messages from the
    // previous iteration, on 2 threads.
    constexpr BpSchedule kSchedules[] = {BpSchedule::sequential, BpSchedule::parallel,
                                         BpSchedule::bands};
    LbpOptions options{kSchedules[(trial / 2) % 3], 0.0};
    options.threads = 2;
    options.band_variables = 3;
    LbpSolver solver(options);
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

/// The trace of `steps` iterations of LBP with `options` from the all-zero labeling: per step
/// the reported energy, the largest message change and the decoded labeling.
struct LbpTrace {
  std::vector<double> energies, changes;
  std::vector<Labeling> decoded;
  bool operator==(const LbpTrace&) const = default;
};
LbpTrace lbp_trace(const PairwiseEnergy& energy, const LbpOptions& options, int steps) {
  LbpSolver solver(options);
  solver.bind(energy, Labeling(energy.num_variables(), 0));
  LbpTrace trace;
  for (int i = 0; i < steps; ++i) {
    trace.energies.push_back(solver.step());
    trace.changes.push_back(solver.last_step().message_change);
    trace.decoded.emplace_back(solver.decoded().begin(), solver.decoded().end());
  }
  return trace;
}

TEST_CASE("LBP's schedules give the same bits for every thread count", "[lbp]") {
  Rng rng(44);
  const PairwiseEnergy energy = random_grid_energy(rng, 90, 70, 5);  // 6300 variables
  for (const BpSchedule schedule :
       {BpSchedule::sequential, BpSchedule::parallel, BpSchedule::bands}) {
    LbpOptions options{schedule, 0.3};
    options.band_variables = 1000;  // 7 bands
    options.threads = 1;
    const LbpTrace one = lbp_trace(energy, options, 12);
    INFO(to_string(schedule));
    for (const int threads : {2, 3}) {
      options.threads = threads;
      CHECK(lbp_trace(energy, options, 12) == one);
    }
    for (std::size_t i = 1; i < one.energies.size(); ++i)
      CHECK(one.energies[i] <= one.energies[i - 1]);
    CHECK(one.energies.back() < energy.evaluate(Labeling(energy.num_variables(), 0)));
  }
}

TEST_CASE("LBP's bands follow their layout", "[lbp]") {
  Rng rng(45);
  const PairwiseEnergy energy = random_grid_energy(rng, 60, 50, 4);  // 3000 variables
  const auto trace = [&](BpSchedule schedule, std::size_t band_variables) {
    LbpOptions options{schedule, 0.0};
    options.band_variables = band_variables;
    options.threads = 2;
    return lbp_trace(energy, options, 6);
  };
  // One band holding every variable is the sequential schedule.
  CHECK(trace(BpSchedule::bands, 3000) == trace(BpSchedule::sequential, 0));
  // Bands of 600 variables send messages between bands a step late, so they differ from it.
  CHECK_FALSE(trace(BpSchedule::bands, 600) == trace(BpSchedule::sequential, 0));
  LbpSolver solver(LbpOptions{BpSchedule::bands, 0.0});
  solver.bind(energy, Labeling(3000, 0));
  CHECK(solver.band_variables() == LbpOptions::kMinBandVariables);  // the default's floor
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
  CHECK(bp_schedule_from_string("bands") == BpSchedule::bands);
  LbpOptions negative;
  negative.threads = -1;
  CHECK_THROWS_WITH(LbpSolver(negative), Catch::Contains("threads must be >= 0"));
  CHECK_THROWS_WITH(bp_schedule_from_string("async"), Catch::Contains("'async'"));
}

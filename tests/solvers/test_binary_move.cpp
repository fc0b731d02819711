// The binary move solver: exact on submodular problems; on non-submodular ones (QPBO) the
// labelled part agrees with some minimiser and imposing it never increases the objective.

#include <catch2/catch.hpp>

#include <random>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/maxflow/boost_maxflow.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

struct BinaryProblem {
  std::size_t n;
  std::vector<FlowEdge> pairs;
  std::vector<double> d, p;

  double value(const std::vector<int>& b) const {
    double total = 0.0;
    for (std::size_t i = 0; i < n; ++i) total += d[i] * b[i];
    for (std::size_t e = 0; e < pairs.size(); ++e)
      total += p[e] * (1 - b[pairs[e].from]) * b[pairs[e].to];
    return total;
  }
};

BinaryProblem random_binary_problem(Rng& rng, std::size_t n, double non_submodular_fraction) {
  BinaryProblem problem{n, {}, std::vector<double>(n), {}};
  std::uniform_real_distribution<double> value(-3.0, 3.0);
  std::bernoulli_distribution negative(non_submodular_fraction);
  for (double& d : problem.d) d = value(rng);
  std::uniform_int_distribution<FlowNode> node(0, static_cast<FlowNode>(n - 1));
  const std::size_t m = std::uniform_int_distribution<std::size_t>(0, 2 * n)(rng);
  while (problem.pairs.size() < m) {
    const FlowNode a = node(rng), b = node(rng);
    if (a == b) continue;
    problem.pairs.push_back({a, b});
    const double magnitude = std::abs(value(rng));
    problem.p.push_back(negative(rng) ? -magnitude : magnitude);
  }
  return problem;
}

/// Minimum over all b that agree with `fixed` where it is labelled.
double constrained_minimum(const BinaryProblem& problem, const std::vector<MoveLabel>& fixed) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<int> b(problem.n);
  for (std::size_t mask = 0; mask < (std::size_t{1} << problem.n); ++mask) {
    bool consistent = true;
    for (std::size_t i = 0; i < problem.n; ++i) {
      b[i] = (mask >> i) & 1;
      if (fixed[i] != MoveLabel::unlabeled && b[i] != static_cast<int>(fixed[i]))
        consistent = false;
    }
    if (consistent) best = std::min(best, problem.value(b));
  }
  return best;
}

std::vector<MoveLabel> solve(const BinaryProblem& problem, BinaryMoveStats* stats = nullptr) {
  BinaryMoveSolver<BoostMaxFlow> solver;
  solver.bind(problem.n, problem.pairs);
  std::vector<MoveLabel> out(problem.n);
  const BinaryMoveStats s = solver.solve(problem.d, problem.p, out);
  if (stats) *stats = s;
  return out;
}

}  // namespace

TEST_CASE("submodular binary problems are solved exactly", "[binary-move][brute-force]") {
  Rng rng(12);
  for (int trial = 0; trial < 300; ++trial) {
    const auto problem =
        random_binary_problem(rng, std::uniform_int_distribution<std::size_t>(2, 10)(rng), 0.0);
    BinaryMoveStats stats;
    const auto out = solve(problem, &stats);
    CHECK_FALSE(stats.used_qpbo);
    std::vector<int> b(problem.n);
    for (std::size_t i = 0; i < problem.n; ++i) {
      REQUIRE(out[i] != MoveLabel::unlabeled);
      b[i] = static_cast<int>(out[i]);
    }
    const std::vector<MoveLabel> free(problem.n, MoveLabel::unlabeled);
    CHECK(close_relative(problem.value(b), constrained_minimum(problem, free), 1e-9));
  }
}

TEST_CASE("QPBO labels agree with a minimiser and never make a labeling worse",
          "[binary-move][qpbo][brute-force]") {
  Rng rng(77);
  int qpbo_runs = 0, fully_labelled = 0, partially_labelled = 0;
  for (int trial = 0; trial < 400; ++trial) {
    const auto problem =
        random_binary_problem(rng, std::uniform_int_distribution<std::size_t>(2, 10)(rng), 0.4);
    BinaryMoveStats stats;
    const auto out = solve(problem, &stats);
    if (!stats.used_qpbo) continue;
    ++qpbo_runs;
    (stats.unlabeled == 0 ? fully_labelled : partially_labelled) += 1;
    const std::vector<MoveLabel> free(problem.n, MoveLabel::unlabeled);
    INFO("trial " << trial);
    // Weak persistency: some global minimiser agrees with every labelled variable.
    CHECK(close_relative(constrained_minimum(problem, out), constrained_minimum(problem, free),
                         1e-9));
    // Autarky: imposing the labelled part on any b does not increase the objective.
    for (int sample = 0; sample < 10; ++sample) {
      std::vector<int> b(problem.n), imposed(problem.n);
      for (std::size_t i = 0; i < problem.n; ++i) {
        b[i] = std::uniform_int_distribution<int>(0, 1)(rng);
        imposed[i] = out[i] == MoveLabel::unlabeled ? b[i] : static_cast<int>(out[i]);
      }
      CHECK(problem.value(imposed) <= problem.value(b) + 1e-9);
    }
  }
  // The sample exercises both outcomes of QPBO.
  CHECK(qpbo_runs > 100);
  CHECK(fully_labelled > 0);
  CHECK(partially_labelled > 0);
}

// Max-flow backends: flow value == capacity of the cut they report, equal to the brute-force
// minimum cut on tiny graphs, and the backends agree with each other.

#include <catch2/catch.hpp>

#include <random>

#include "c2f/adapters/maxflow/boost_maxflow.hpp"
#include "support/backends.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

struct RandomFlowProblem {
  std::size_t num_nodes;
  std::vector<FlowEdge> edges;
  FlowCapacities caps;
};

RandomFlowProblem random_flow_problem(Rng& rng, std::size_t num_nodes, std::size_t num_edges) {
  RandomFlowProblem problem{num_nodes, {}, {}};
  std::uniform_int_distribution<FlowNode> node(0, static_cast<FlowNode>(num_nodes - 1));
  std::uniform_real_distribution<double> capacity(0.0, 4.0);
  std::bernoulli_distribution zero(0.3);
  while (problem.edges.size() < num_edges) {
    const FlowNode a = node(rng), b = node(rng);
    if (a != b) problem.edges.push_back({a, b});
  }
  problem.caps.resize(num_nodes, num_edges);
  auto draw = [&] { return zero(rng) ? 0.0 : capacity(rng); };
  for (auto* values :
       {&problem.caps.source, &problem.caps.sink, &problem.caps.forward, &problem.caps.backward}) {
    for (double& c : *values) c = draw();
  }
  return problem;
}

double brute_force_min_cut(const RandomFlowProblem& problem) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<char> in_source(problem.num_nodes);
  for (std::size_t mask = 0; mask < (std::size_t{1} << problem.num_nodes); ++mask) {
    for (std::size_t i = 0; i < problem.num_nodes; ++i) in_source[i] = (mask >> i) & 1;
    best = std::min(best, cut_capacity(problem.caps, problem.edges, in_source));
  }
  return best;
}

template <class Backend>
double solve_and_check_cut(const RandomFlowProblem& problem) {
  Backend backend;
  backend.build(problem.num_nodes, problem.edges);
  const double flow = backend.solve(problem.caps);
  std::vector<char> in_source(problem.num_nodes);
  for (std::size_t i = 0; i < problem.num_nodes; ++i)
    in_source[i] = backend.in_source_set(static_cast<FlowNode>(i));
  CHECK(close_relative(cut_capacity(problem.caps, problem.edges, in_source), flow, 1e-9));
  // Solving again after a capacity reset gives the same answer (topology reused).
  CHECK(close_relative(backend.solve(problem.caps), flow, 1e-9));
  return flow;
}

}  // namespace

TEMPLATE_TEST_CASE("max-flow equals the brute-force minimum cut on tiny graphs",
                   "[maxflow][brute-force]", C2F_MAXFLOW_BACKENDS) {
  Rng rng(31337);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(1, 10)(rng);
    const auto problem = random_flow_problem(
        rng, n, n < 2 ? 0 : std::uniform_int_distribution<std::size_t>(0, 3 * n)(rng));
    INFO("trial " << trial);
    CHECK(
        close_relative(solve_and_check_cut<TestType>(problem), brute_force_min_cut(problem), 1e-9));
  }
}

TEST_CASE("max-flow backends agree on larger random graphs", "[maxflow]") {
  Rng rng(4);
  for (int trial = 0; trial < 40; ++trial) {
    const auto problem = random_flow_problem(rng, 500, 2000);
    const double boost_flow = solve_and_check_cut<BoostMaxFlow>(problem);
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
    CHECK(close_relative(boost_flow, solve_and_check_cut<KolmogorovMaxFlow>(problem), 1e-9));
#else
    CHECK(boost_flow >= 0.0);
#endif
  }
}

TEST_CASE("max-flow backends validate topology and capacities", "[maxflow][validation]") {
  BoostMaxFlow flow;
  const std::vector<FlowEdge> self_loop{{1, 1}};
  CHECK_THROWS_WITH(flow.build(3, self_loop),
                    Catch::Contains("edge 0 (1, 1) must join two different nodes < 3"));
  const std::vector<FlowEdge> outside{{0, 5}};
  CHECK_THROWS_WITH(flow.build(3, outside), Catch::Contains("edge 0 (0, 5)"));
  FlowCapacities caps;
  CHECK_THROWS_WITH(flow.solve(caps), Catch::Contains("call build() first"));
  const std::vector<FlowEdge> edge{{0, 1}};
  flow.build(2, edge);
  caps.resize(3, 1);
  CHECK_THROWS_WITH(flow.solve(caps), Catch::Contains("the graph has 2 nodes"));
  caps.resize(2, 1);
  caps.forward[0] = -1.0;
  CHECK_THAT(check_capacities(caps, 2, 1),
             Catch::Contains("forward[0] = -1.000000 is not a finite capacity >= 0"));
}

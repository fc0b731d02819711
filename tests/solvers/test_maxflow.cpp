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
    CHECK(close_relative(boost_flow, solve_and_check_cut<DynamicMaxFlow>(problem), 1e-9));
#ifdef C2F_HAVE_KOLMOGOROV_MAXFLOW
    CHECK(close_relative(boost_flow, solve_and_check_cut<KolmogorovMaxFlow>(problem), 1e-9));
#endif
  }
}

TEMPLATE_TEST_CASE("max-flow backends validate topology and capacities", "[maxflow][validation]",
                   C2F_MAXFLOW_BACKENDS) {
  TestType flow;
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

namespace {

/// Changes a share of the capacities of `caps` (terminal pairs and edges), drawn like
/// random_flow_problem's, with integers when `integral` (exact in doubles).
void change_capacities(Rng& rng, FlowCapacities& caps, double share, bool integral) {
  std::bernoulli_distribution pick(share);
  std::bernoulli_distribution zero(0.3);
  std::uniform_real_distribution<double> real(0.0, 4.0);
  std::uniform_int_distribution<int> whole(0, 6);
  auto draw = [&] { return zero(rng) ? 0.0 : integral ? whole(rng) : real(rng); };
  for (std::size_t i = 0; i < caps.source.size(); ++i) {
    if (!pick(rng)) continue;
    caps.source[i] = draw();
    caps.sink[i] = draw();
  }
  for (std::size_t e = 0; e < caps.forward.size(); ++e) {
    if (!pick(rng)) continue;
    caps.forward[e] = draw();
    caps.backward[e] = draw();
  }
}

std::vector<char> source_set(const auto& backend) {
  std::vector<char> in_source(backend.num_nodes());
  for (std::size_t i = 0; i < in_source.size(); ++i)
    in_source[i] = backend.in_source_set(static_cast<FlowNode>(i));
  return in_source;
}

}  // namespace

TEST_CASE("dynamic max-flow: re-solves after capacity changes equal solves from zero flow",
          "[maxflow][dynamic]") {
  Rng rng(2024);
  for (const double share : {0.01, 0.1, 0.5, 1.0}) {
    for (int trial = 0; trial < 12; ++trial) {
      auto problem = random_flow_problem(rng, 400, 1600);
      DynamicMaxFlow dynamic;
      dynamic.build(problem.num_nodes, problem.edges);
      BoostMaxFlow boost;
      boost.build(problem.num_nodes, problem.edges);
      dynamic.solve(problem.caps);
      for (int round = 0; round < 8; ++round) {
        const FlowCapacities before = problem.caps;
        change_capacities(rng, problem.caps, share, false);
        INFO("share " << share << ", trial " << trial << ", round " << round);
        resolve_with(dynamic, before, problem.caps);
        CHECK(dynamic.last_solve().reused);
        const double resumed = cut_capacity(problem.caps, problem.edges, source_set(dynamic));
        CHECK(close_relative(resumed, boost.solve(problem.caps), 1e-9));
      }
    }
  }
}

TEST_CASE(
    "dynamic max-flow: with integral capacities a re-solve finds exactly the source set "
    "of a solve from zero flow",
    "[maxflow][dynamic]") {
  // The nodes reachable from the source in the residual graph of any maximum flow are the same
  // set, so with exact arithmetic every backend must report it.
  Rng rng(77);
  for (int trial = 0; trial < 20; ++trial) {
    auto problem = random_flow_problem(rng, 300, 1200);
    change_capacities(rng, problem.caps, 1.0, true);
    DynamicMaxFlow dynamic, fresh;
    dynamic.build(problem.num_nodes, problem.edges);
    fresh.build(problem.num_nodes, problem.edges);
    BoostMaxFlow boost;
    boost.build(problem.num_nodes, problem.edges);
    dynamic.solve(problem.caps);
    for (int round = 0; round < 10; ++round) {
      INFO("trial " << trial << ", round " << round);
      const double flow = boost.solve(problem.caps);
      CHECK(fresh.solve(problem.caps) == flow);
      CHECK_FALSE(fresh.last_solve().reused);
      CHECK(cut_capacity(problem.caps, problem.edges, source_set(dynamic)) == flow);
      CHECK(source_set(dynamic) == source_set(boost));
      CHECK(source_set(fresh) == source_set(boost));
      const FlowCapacities before = problem.caps;
      change_capacities(rng, problem.caps, round % 2 == 0 ? 0.05 : 0.5, true);
      resolve_with(dynamic, before, problem.caps);
    }
  }
}

TEST_CASE("dynamic max-flow: tiny graphs, every re-solve equals the brute-force minimum cut",
          "[maxflow][dynamic][brute-force]") {
  Rng rng(5150);
  for (int trial = 0; trial < 200; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 9)(rng);
    auto problem =
        random_flow_problem(rng, n, std::uniform_int_distribution<std::size_t>(1, 3 * n)(rng));
    DynamicMaxFlow dynamic;
    dynamic.build(problem.num_nodes, problem.edges);
    dynamic.solve(problem.caps);
    for (int round = 0; round < 6; ++round) {
      INFO("trial " << trial << ", round " << round);
      CHECK(close_relative(cut_capacity(problem.caps, problem.edges, source_set(dynamic)),
                           brute_force_min_cut(problem), 1e-9));
      const FlowCapacities before = problem.caps;
      change_capacities(rng, problem.caps, 0.3, false);
      resolve_with(dynamic, before, problem.caps);
    }
  }
}

TEST_CASE(
    "dynamic max-flow: an unchanged re-solve does no work, and a copy resumes like the original",
    "[maxflow][dynamic]") {
  Rng rng(8);
  auto problem = random_flow_problem(rng, 200, 800);
  DynamicMaxFlow dynamic;
  dynamic.build(problem.num_nodes, problem.edges);
  dynamic.solve(problem.caps);
  const auto cut = source_set(dynamic);
  CHECK(resolve_with(dynamic, problem.caps, problem.caps) == 0);
  CHECK(dynamic.last_solve().reused);
  CHECK(dynamic.last_solve().augmentations == 0);
  CHECK(source_set(dynamic) == cut);
  DynamicMaxFlow copy(dynamic);
  const FlowCapacities before = problem.caps;
  change_capacities(rng, problem.caps, 0.2, false);
  CHECK(resolve_with(copy, before, problem.caps) > 0);
  resolve_with(dynamic, before, problem.caps);
  CHECK(source_set(copy) == source_set(dynamic));
  CHECK(dynamic.memory_bytes() == DynamicMaxFlow::memory_bytes_for(200, 800));
  // A copy shares the topology and owns its flow state: rebuilding the original leaves it whole.
  CHECK(copy.topology_bytes() > 0);
  CHECK(copy.topology_bytes() == dynamic.topology_bytes());
  dynamic.build(2, std::vector<FlowEdge>{{0, 1}});
  DynamicMaxFlow fresh;
  fresh.build(problem.num_nodes, problem.edges);
  CHECK(copy.solve(before) == fresh.solve(before));
  CHECK(source_set(copy) == source_set(fresh));
  DynamicMaxFlow unsolved;
  unsolved.build(2, std::vector<FlowEdge>{{0, 1}});
  CHECK_THROWS_WITH(unsolved.resolve(), Catch::Contains("solve() first"));
}

TEST_CASE("dynamic max-flow: a hub's arcs are scanned a bounded number of times per solve",
          "[maxflow][dynamic]") {
  // A hub with k leaves, each leaf joined to the sink: every leaf takes an augmentation of its
  // own through the hub. Scanning the hub again from its first arc after each would examine
  // about k^2 / 2 arcs; going on from the arc where the trees met examines each about once.
  const std::size_t leaves = 2000;
  std::vector<FlowEdge> edges;
  for (std::size_t leaf = 1; leaf <= leaves; ++leaf)
    edges.push_back({0, static_cast<FlowNode>(leaf)});
  FlowCapacities caps;
  caps.resize(leaves + 1, leaves);
  caps.source[0] = 2.0 * static_cast<double>(leaves);
  for (std::size_t leaf = 1; leaf <= leaves; ++leaf) {
    caps.sink[leaf] = 1.0;
    caps.forward[leaf - 1] = leaf % 2 == 0 ? 1.0 : 2.0;  // the edge or the sink arc saturates
  }
  const std::size_t bound = 4 * (2 * leaves + 1);  // each arc (both directions) a few times
  DynamicMaxFlow dynamic;
  dynamic.build(leaves + 1, edges);
  CHECK(dynamic.solve(caps) == static_cast<double>(leaves));
  CHECK(dynamic.last_solve().augmentations == leaves);
  CHECK(dynamic.last_solve().arcs_scanned <= bound);
  // A re-solve after every leaf's sink arc doubled: the hub's scan again, from its first arc.
  const FlowCapacities before = caps;
  for (std::size_t leaf = 1; leaf <= leaves; ++leaf) caps.sink[leaf] = 2.0;
  resolve_with(dynamic, before, caps);
  CHECK(cut_capacity(caps, edges, source_set(dynamic)) == 1.5 * static_cast<double>(leaves));
  CHECK(dynamic.last_solve().arcs_scanned <= bound);
}

TEST_CASE("dynamic max-flow: a large copy made on several threads resumes like one made on one",
          "[maxflow][dynamic][threads]") {
  // 270k edges: 4.3 MB of residuals, so the copy asks for some of its pages ahead.
  Rng rng(9);
  auto problem = random_flow_problem(rng, 20000, 270000);
  DynamicMaxFlow dynamic;
  dynamic.build(problem.num_nodes, problem.edges);
  dynamic.solve(problem.caps);
  const FlowCapacities before = problem.caps;
  change_capacities(rng, problem.caps, 0.1, false);
  DynamicMaxFlow serial(dynamic, 1);
  resolve_with(serial, before, problem.caps);
  for (const int threads : {2, 3}) {
    DynamicMaxFlow copy(dynamic, threads);
    CHECK(source_set(copy) == source_set(dynamic));
    resolve_with(copy, before, problem.caps);
    CHECK(copy.last_solve().augmentations == serial.last_solve().augmentations);
    CHECK(source_set(copy) == source_set(serial));
  }
}

namespace {

/// Part ids of a problem's nodes: `parts` ranges of about equal size (a band layout), or random.
std::vector<std::uint8_t> node_parts(Rng& rng, std::size_t num_nodes, std::size_t parts,
                                     bool random) {
  std::vector<std::uint8_t> part(num_nodes);
  std::uniform_int_distribution<std::size_t> any(0, parts - 1);
  for (std::size_t i = 0; i < num_nodes; ++i)
    part[i] = static_cast<std::uint8_t>(random ? any(rng) : i * parts / num_nodes);
  return part;
}

}  // namespace

TEST_CASE("dynamic max-flow in parts: the brute-force minimum cut on tiny graphs",
          "[maxflow][dynamic][parts][brute-force]") {
  Rng rng(909);
  for (int trial = 0; trial < 300; ++trial) {
    const std::size_t n = std::uniform_int_distribution<std::size_t>(2, 10)(rng);
    auto problem =
        random_flow_problem(rng, n, std::uniform_int_distribution<std::size_t>(1, 3 * n)(rng));
    const auto part = node_parts(rng, n, 1 + trial % 4, trial % 2 == 1);
    DynamicMaxFlow dynamic;
    dynamic.build(problem.num_nodes, problem.edges);
    dynamic.cut_into_parts(part);
    dynamic.solve_cut_in_parts(problem.caps, 1 + trial % 3);
    INFO("trial " << trial);
    CHECK(close_relative(cut_capacity(problem.caps, problem.edges, source_set(dynamic)),
                         brute_force_min_cut(problem), 1e-9));
    // It resolves on from the flow the parts left, serially and in parts.
    for (int round = 0; round < 4; ++round) {
      INFO("round " << round);
      const FlowCapacities before = problem.caps;
      change_capacities(rng, problem.caps, 0.3, false);
      if (round % 2 == 0) {
        resolve_with(dynamic, before, problem.caps);
      } else {
        apply_capacity_changes(dynamic, before, problem.caps);
        dynamic.resolve_in_parts(1 + round % 3);
      }
      CHECK(close_relative(cut_capacity(problem.caps, problem.edges, source_set(dynamic)),
                           brute_force_min_cut(problem), 1e-9));
    }
  }
}

TEST_CASE(
    "dynamic max-flow in parts: with integral capacities exactly the source set of a serial "
    "solve, and the same bits for every thread count",
    "[maxflow][dynamic][parts]") {
  Rng rng(4242);
  for (int trial = 0; trial < 24; ++trial) {
    auto problem = random_flow_problem(rng, 600, 2400);
    change_capacities(rng, problem.caps, 1.0, true);
    const auto part = node_parts(rng, problem.num_nodes, 2 + trial % 7, trial % 3 == 0);
    BoostMaxFlow boost;
    boost.build(problem.num_nodes, problem.edges);
    const double flow = boost.solve(problem.caps);
    const std::vector<char> expected = source_set(boost);
    std::vector<char> first;
    for (const int threads : {1, 2, 3}) {
      INFO("trial " << trial << ", " << threads << " threads");
      DynamicMaxFlow dynamic;
      dynamic.build(problem.num_nodes, problem.edges);
      dynamic.cut_into_parts(part);
      dynamic.solve_cut_in_parts(problem.caps, threads);
      CHECK(cut_capacity(problem.caps, problem.edges, source_set(dynamic)) == flow);
      CHECK(source_set(dynamic) == expected);
      if (threads == 1) first = source_set(dynamic);
      CHECK(source_set(dynamic) == first);
      // Re-solves in parts after changes of every size find the exact source set too.
      FlowCapacities caps = problem.caps;
      Rng changes(static_cast<std::uint64_t>(trial));  // the same changes for every thread count
      for (int round = 0; round < 6; ++round) {
        const FlowCapacities before = caps;
        change_capacities(changes, caps, round % 2 == 0 ? 0.05 : 0.5, true);
        apply_capacity_changes(dynamic, before, caps);
        dynamic.resolve_in_parts(threads);
        CHECK(dynamic.last_solve().reused);
        CHECK(cut_capacity(caps, problem.edges, source_set(dynamic)) == boost.solve(caps));
        CHECK(source_set(dynamic) == source_set(boost));
      }
    }
  }
  DynamicMaxFlow dynamic;
  auto problem = random_flow_problem(rng, 10, 20);
  dynamic.build(problem.num_nodes, problem.edges);
  CHECK_THROWS_WITH(dynamic.cut_into_parts(std::vector<std::uint8_t>(9, 0)),
                    Catch::Contains("9 part ids for 10 nodes"));
  CHECK(dynamic.num_parts() == 1);
  dynamic.cut_into_parts(std::vector<std::uint8_t>{0, 0, 1, 1, 2, 2, 2, 0, 1, 2});
  CHECK(dynamic.num_parts() == 3);
  DynamicMaxFlow copy(dynamic);
  CHECK(copy.num_parts() == 3);
  dynamic.build(problem.num_nodes, problem.edges);  // a new topology forgets the parts
  CHECK(dynamic.num_parts() == 1);
}

TEST_CASE("dynamic max-flow built and cut on several threads is the graph built on one",
          "[maxflow][dynamic][parts][threads]") {
  // 200k edges: several ranges of build()'s parallel placement and of the topology check. The
  // same arcs in the same order make the same search: the same flow, bit for bit, the same
  // augmentations and the same source set, whole and in parts.
  Rng rng(99);
  auto problem = random_flow_problem(rng, 20000, 200000);
  const auto part = node_parts(rng, problem.num_nodes, 4, false);
  DynamicMaxFlow serial;
  serial.build(problem.num_nodes, problem.edges);
  const double flow = serial.solve(problem.caps);
  DynamicMaxFlow serial_parts;
  serial_parts.build(problem.num_nodes, problem.edges);
  serial_parts.cut_into_parts(part);
  serial_parts.solve_cut_in_parts(problem.caps, 1);
  for (const int threads : {2, 3}) {
    INFO(threads << " threads");
    DynamicMaxFlow built;
    built.build(problem.num_nodes, problem.edges, threads);
    CHECK(built.solve(problem.caps) == flow);
    CHECK(built.last_solve().augmentations == serial.last_solve().augmentations);
    CHECK(source_set(built) == source_set(serial));
    DynamicMaxFlow in_parts;
    in_parts.build(problem.num_nodes, problem.edges, threads);
    in_parts.cut_into_parts(part, threads);
    in_parts.solve_cut_in_parts(problem.caps, threads);
    CHECK(in_parts.last_solve().augmentations == serial_parts.last_solve().augmentations);
    CHECK(source_set(in_parts) == source_set(serial_parts));
  }
  // The checks on several threads name the first bad edge, as on one.
  problem.edges[150000] = {7, 7};
  problem.edges[190000] = {1, 20000};
  DynamicMaxFlow bad;
  CHECK_THROWS_WITH(bad.build(problem.num_nodes, problem.edges, 2),
                    Catch::Contains("edge 150000 (7, 7) must join two different nodes < 20000"));
}

namespace {

/// The changes from `before` to `after` as change_in_parts takes them, in index order.
std::pair<LargeVector<TerminalChange>, LargeVector<EdgeChange>> changes_between(
    const FlowCapacities& before, const FlowCapacities& after) {
  std::pair<LargeVector<TerminalChange>, LargeVector<EdgeChange>> changes;
  for (std::size_t i = 0; i < after.source.size(); ++i) {
    const double delta = (after.source[i] - after.sink[i]) - (before.source[i] - before.sink[i]);
    if (delta != 0.0) changes.first.push_back({static_cast<FlowNode>(i), delta});
  }
  for (std::size_t e = 0; e < after.forward.size(); ++e) {
    if (after.forward[e] != before.forward[e] || after.backward[e] != before.backward[e])
      changes.second.push_back(
          {e, after.forward[e] - before.forward[e], after.backward[e] - before.backward[e]});
  }
  return changes;
}

/// `terminals` and `edges` (change_in_parts' lists) listed by part for change_by_parts, in their
/// order: node i in part[i], an edge in its nodes' part or between parts.
ChangesByPart listed_by_part(std::span<const TerminalChange> terminals,
                             std::span<const EdgeChange> edges,
                             const std::vector<std::uint8_t>& part,
                             const std::vector<FlowEdge>& graph_edges, std::size_t parts) {
  ChangesByPart by_part;
  by_part.clear(parts);
  for (const TerminalChange& change : terminals)
    by_part.terminals[part[change.node]].push_back(change);
  for (const EdgeChange& change : edges) {
    const FlowEdge& edge = graph_edges[change.edge];
    const bool inside = part[edge.from] == part[edge.to];
    by_part.edges[inside ? part[edge.from] : parts].push_back(change);
  }
  return by_part;
}

}  // namespace

TEST_CASE("dynamic max-flow: changes listed by part make the graph change_in_parts makes",
          "[maxflow][dynamic][parts][threads]") {
  // The same changes in the same order per part: the same flow and trees, so the re-solves
  // find the same augmenting paths and the same cut, on any thread count.
  Rng rng(616);
  for (int trial = 0; trial < 6; ++trial) {
    auto problem = random_flow_problem(rng, 3000, 12000);
    change_capacities(rng, problem.caps, 1.0, true);
    const std::size_t parts = 2 + static_cast<std::size_t>(trial) % 4;
    const auto part = node_parts(rng, problem.num_nodes, parts, trial % 2 == 0);
    DynamicMaxFlow sorted;
    sorted.build(problem.num_nodes, problem.edges);
    sorted.cut_into_parts(part);
    sorted.solve_cut_in_parts(problem.caps, 1);
    for (const int threads : {1, 2, 3}) {
      INFO("trial " << trial << ", " << threads << " threads");
      DynamicMaxFlow sorting(sorted), listed(sorted);
      FlowCapacities caps = problem.caps;
      Rng changes(static_cast<std::uint64_t>(trial));
      for (int round = 0; round < 4; ++round) {
        const FlowCapacities before = caps;
        change_capacities(changes, caps, round % 2 == 0 ? 0.05 : 0.5, true);
        const auto [terminals, edges] = changes_between(before, caps);
        sorting.change_in_parts(terminals, edges, threads);
        listed.change_by_parts(listed_by_part(terminals, edges, part, problem.edges, parts),
                               threads);
        sorting.resolve_in_parts(threads);
        listed.resolve_in_parts(threads);
        CHECK(listed.last_solve().changed_nodes == terminals.size());
        CHECK(listed.last_solve().changed_edges == edges.size());
        CHECK(listed.last_solve().augmentations == sorting.last_solve().augmentations);
        CHECK(listed.last_solve().arcs_scanned == sorting.last_solve().arcs_scanned);
        CHECK(source_set(listed) == source_set(sorting));
        BoostMaxFlow boost;
        boost.build(problem.num_nodes, problem.edges);
        CHECK(cut_capacity(caps, problem.edges, source_set(listed)) == boost.solve(caps));
      }
    }
  }
}

TEST_CASE("dynamic max-flow: changes listed in the wrong part are refused",
          "[maxflow][dynamic][parts]") {
  Rng rng(717);
  auto problem = random_flow_problem(rng, 40, 120);
  std::vector<std::uint8_t> part(problem.num_nodes);
  for (std::size_t i = 0; i < part.size(); ++i) part[i] = i < 20 ? 0 : 1;
  DynamicMaxFlow dynamic;
  dynamic.build(problem.num_nodes, problem.edges);
  CHECK_THROWS_WITH(dynamic.change_by_parts(ChangesByPart{}, 1), Catch::Contains("solve() first"));
  dynamic.cut_into_parts(part);
  dynamic.solve_cut_in_parts(problem.caps, 2);
  const std::vector<char> solved = source_set(dynamic);
  ChangesByPart changes;
  changes.clear(3);
  CHECK_THROWS_WITH(dynamic.change_by_parts(changes, 2),
                    Catch::Contains("3 and 4 lists of changes for a graph in 2 parts"));
  // An edge inside a part listed between parts: refused before anything changes.
  std::size_t inside = 0, between = 0;
  while (part[problem.edges[inside].from] != part[problem.edges[inside].to]) ++inside;
  while (part[problem.edges[between].from] == part[problem.edges[between].to]) ++between;
  changes.clear(2);
  changes.terminals[0].push_back({3, 100.0});
  changes.edges[2].push_back({inside, 1.0, 0.0});
  CHECK_THROWS_WITH(
      dynamic.change_by_parts(changes, 2),
      Catch::Contains("names edge " + std::to_string(inside) + ", which is not between parts"));
  dynamic.resolve_in_parts(2);
  CHECK(dynamic.last_solve().changed_nodes == 0);
  CHECK(source_set(dynamic) == solved);
  // A node of part 1 in part 0's list, and an edge between parts in a part's list: refused
  // after the other parts' changes, and the flow is dropped until the next solve.
  for (const bool node : {true, false}) {
    changes.clear(2);
    if (node) {
      changes.terminals[0].push_back({25, 1.0});
    } else {
      changes.edges[1].push_back({between, 1.0, 0.0});
    }
    CHECK_THROWS_WITH(dynamic.change_by_parts(changes, 2),
                      Catch::Contains(node ? "names node 25, which is not in that part"
                                           : "names edge " + std::to_string(between) +
                                                 ", which is not inside that part"));
    CHECK_THROWS_WITH(dynamic.resolve_in_parts(2), Catch::Contains("solve() first"));
    dynamic.solve_cut_in_parts(problem.caps, 2);
    CHECK(source_set(dynamic) == solved);
  }
  // One part: one list each and no edges between parts.
  DynamicMaxFlow whole;
  whole.build(problem.num_nodes, problem.edges);
  whole.solve_cut(problem.caps);
  changes.clear(1);
  changes.edges[1].push_back({between, 1.0, 0.0});
  CHECK_THROWS_WITH(whole.change_by_parts(changes, 1),
                    Catch::Contains("edges between parts changed in a graph of one part"));
}

TEST_CASE("dynamic max-flow: changes made by parts re-solve to the exact cut on any threads",
          "[maxflow][dynamic][parts][threads]") {
  Rng rng(515);
  for (int trial = 0; trial < 12; ++trial) {
    auto problem = random_flow_problem(rng, 3000, 12000);
    change_capacities(rng, problem.caps, 1.0, true);
    const bool in_parts = trial % 4 != 0;  // else one part: the changes one at a time
    const auto part = node_parts(rng, problem.num_nodes, 2 + trial % 5, trial % 3 == 0);
    std::vector<std::vector<char>> first_sets;
    for (const int threads : {1, 2, 3}) {
      INFO("trial " << trial << ", " << threads << " threads");
      DynamicMaxFlow dynamic;
      dynamic.build(problem.num_nodes, problem.edges);
      if (in_parts) dynamic.cut_into_parts(part);
      dynamic.solve_cut_in_parts(problem.caps, threads);
      DynamicMaxFlow one_at_a_time(dynamic);
      FlowCapacities caps = problem.caps;
      Rng changes(static_cast<std::uint64_t>(trial));  // the same changes for every thread count
      for (int round = 0; round < 5; ++round) {
        const FlowCapacities before = caps;
        change_capacities(changes, caps, round % 2 == 0 ? 0.05 : 0.5, true);
        const auto [terminals, edges] = changes_between(before, caps);
        const std::span<const TerminalChange> all_terminals(terminals);
        const std::span<const EdgeChange> all_edges(edges);
        const std::size_t half_terminals = terminals.size() / 2, half_edges = edges.size() / 2;
        if (in_parts && round == 3) {  // in two calls before the re-solve
          dynamic.change_in_parts(all_terminals.first(half_terminals), all_edges.first(half_edges),
                                  threads);
          dynamic.change_in_parts(all_terminals.subspan(half_terminals),
                                  all_edges.subspan(half_edges), threads);
        } else if (in_parts && round == 4 && !terminals.empty()) {  // the last one on its own
          dynamic.change_in_parts(all_terminals.first(terminals.size() - 1), edges, threads);
          dynamic.change_terminal(terminals.back().node, terminals.back().delta);
        } else {
          dynamic.change_in_parts(terminals, edges, threads);
        }
        dynamic.resolve_in_parts(threads);
        CHECK(dynamic.last_solve().changed_nodes == terminals.size());
        CHECK(dynamic.last_solve().changed_edges == edges.size());
        BoostMaxFlow boost;
        boost.build(problem.num_nodes, problem.edges);
        const double flow = boost.solve(caps);
        CHECK(cut_capacity(caps, problem.edges, source_set(dynamic)) == flow);
        CHECK(source_set(dynamic) == source_set(boost));
        if (threads == 1) first_sets.push_back(source_set(dynamic));
        CHECK(source_set(dynamic) == first_sets[static_cast<std::size_t>(round)]);
        if (!in_parts) {  // one part: exactly the changes one at a time
          apply_capacity_changes(one_at_a_time, before, caps);
          one_at_a_time.resolve();
          CHECK(one_at_a_time.last_solve().augmentations == dynamic.last_solve().augmentations);
        }
      }
    }
  }
  DynamicMaxFlow dynamic;
  auto problem = random_flow_problem(rng, 10, 20);
  dynamic.build(problem.num_nodes, problem.edges);
  const LargeVector<TerminalChange> bad_node{{10, 1.0}};
  const LargeVector<EdgeChange> bad_edge{{20, 1.0, 0.0}};
  CHECK_THROWS_WITH(dynamic.change_in_parts(bad_node, {}, 1), Catch::Contains("solve() first"));
  dynamic.solve(problem.caps);
  CHECK_THROWS_WITH(dynamic.change_in_parts(bad_node, {}, 1), Catch::Contains("node 10 of 10"));
  CHECK_THROWS_WITH(dynamic.change_in_parts({}, bad_edge, 1), Catch::Contains("edge 20 of 20"));
  // In parts the changes are checked as they are sorted by part, and nothing changes either.
  dynamic.cut_into_parts(node_parts(rng, problem.num_nodes, 3, false));
  dynamic.solve_cut_in_parts(problem.caps, 2);
  const std::vector<char> solved = source_set(dynamic);
  const std::size_t augmentations = dynamic.last_solve().augmentations;
  const LargeVector<TerminalChange> good_then_bad{{0, 5.0}, {10, 1.0}};
  const LargeVector<EdgeChange> good_edge{{0, 1.0, 0.0}};
  CHECK_THROWS_WITH(dynamic.change_in_parts(good_then_bad, good_edge, 2),
                    Catch::Contains("node 10 of 10"));
  CHECK_THROWS_WITH(dynamic.change_in_parts(std::span(good_then_bad).first(1), bad_edge, 2),
                    Catch::Contains("edge 20 of 20"));
  CHECK(dynamic.last_solve().augmentations == augmentations);  // the solve's, still
  dynamic.resolve_in_parts(2);
  CHECK(dynamic.last_solve().changed_nodes == 0);
  CHECK(dynamic.last_solve().changed_edges == 0);
  CHECK(source_set(dynamic) == solved);
}

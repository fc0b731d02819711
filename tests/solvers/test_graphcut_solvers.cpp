// Alpha-expansion and alpha-beta swap against brute force on tiny models.

#include <catch2/catch.hpp>

#include <algorithm>
#include <map>
#include <tuple>

#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/adapters/graphcut/swap.hpp"
#include "support/backends.hpp"
#include "support/descent.hpp"
#include "support/random_models.hpp"
#include "support/tiny_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

constexpr VisitOrder kOrders[] = {VisitOrder::sequential, VisitOrder::random,
                                  VisitOrder::frequency};

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
        ExpansionOptions{{kOrders[trial % 3], static_cast<std::uint64_t>(trial), 0.0}});
    solver.bind(energy, random_labeling(rng, energy.num_variables(), num_labels));
    double previous = 0.0;
    descend(solver, energy, solver.quiet_steps_to_converge(energy), 500, previous,
            [&](const auto& s) { qpbo_moves += s.last_step().used_qpbo; });
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
    std::vector<double> unaries = raw.unaries().to_doubles();
    for (double& u : unaries) u += 2.0;  // tiny_model draws unaries in [-2, 4)
    const PairwiseEnergy energy(raw.num_variables(), num_labels, std::move(unaries),
                                {PairwiseTerm::potts()},
                                std::vector<Edge>(raw.edges().begin(), raw.edges().end()));
    ExpansionSolver<> solver;
    solver.bind(energy, Labeling(energy.num_variables(), 0));
    const double converged =
        run_to_convergence(solver, energy, solver.quiet_steps_to_converge(energy));
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
    SwapSolver<> solver(SwapOptions{{kOrders[trial % 3], 3}});
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
  CHECK_THROWS_WITH(ExpansionSolver<>(ExpansionOptions{{VisitOrder::sequential, 1, -1.0}}),
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
  ExpansionSolver<> expansion(ExpansionOptions{{VisitOrder::frequency}});
  expansion.bind(energy, start);
  std::vector<Label> visited;
  for (int step = 0; step < 8; ++step) {
    expansion.step();
    visited.push_back(expansion.last_step().alpha);
  }
  CHECK(visited == std::vector<Label>{2, 0, 3, 1, 2, 0, 3, 1});

  SwapSolver<> swap(SwapOptions{{VisitOrder::frequency}});
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

namespace {

/// A grid energy with integer unaries and weights, so every move's capacities are exact in
/// doubles and every minimum cut (the source set of the residual graph) is the same for any
/// backend and any flow history.
PairwiseEnergy integral_grid_energy(Rng& rng, std::size_t side, int num_labels, PairwiseTerm term) {
  std::uniform_int_distribution<int> unary(0, 9);
  std::uniform_int_distribution<int> weight(0, 4);
  std::vector<double> unaries(side * side * static_cast<std::size_t>(num_labels));
  for (double& u : unaries) u = unary(rng);
  return make_grid_energy({side, side}, Connectivity::four, num_labels, std::move(unaries),
                          std::move(term),
                          [&](VariableIndex, VariableIndex) { return weight(rng); });
}

/// Runs `steps` steps of a solver and returns every labeling it passed through. Counts the
/// steps that were solved on their move's own graph (recycled) and those that could have been:
/// a move (label or pair) gets its own graph (plain or QPBO) on its second visit of that graph,
/// so every visit from the third on (from the second on with `from_second`:
/// MoveOptions::first_move_own_graph).
template <class Solver>
std::vector<Labeling> labelings_of_run(Solver& solver, const PairwiseEnergy& energy, int steps,
                                       std::size_t* recycled_steps = nullptr,
                                       std::size_t* repeated_moves = nullptr,
                                       bool from_second = false) {
  solver.bind(energy, Labeling(energy.num_variables(), 0));
  std::vector<Labeling> labelings;
  std::map<std::tuple<Label, Label, bool>, int> visits;
  for (int s = 0; s < steps; ++s) {
    solver.step();
    const MoveStep& step = solver.last_step();
    if (recycled_steps != nullptr) *recycled_steps += step.recycled;
    if (repeated_moves != nullptr)
      *repeated_moves += ++visits[{step.alpha, step.beta, step.used_qpbo}] >= (from_second ? 2 : 3);
    labelings.emplace_back(solver.labeling().begin(), solver.labeling().end());
  }
  return labelings;
}

}  // namespace

/// A TSGO-like step term with integer costs (0, 1, 4 for |a - b| = 0, 1, >= 2): not a metric,
/// so expansion moves need QPBO, and exact in doubles.
PairwiseTerm integral_step_term(int num_labels) {
  std::vector<double> table(static_cast<std::size_t>(num_labels * num_labels));
  for (int a = 0; a < num_labels; ++a) {
    for (int b = 0; b < num_labels; ++b) {
      const int gap = std::abs(a - b);
      table[static_cast<std::size_t>(a * num_labels + b)] = gap == 0 ? 0.0 : gap == 1 ? 1.0 : 4.0;
    }
  }
  return PairwiseTerm::table(num_labels, std::move(table));
}

TEST_CASE("recycled and shared move graphs make exactly the moves of graphs solved from zero flow",
          "[expansion][swap][recycling]") {
  Rng rng(99);
  for (int trial = 0; trial < 9; ++trial) {
    const int num_labels = 3 + trial % 4;
    const PairwiseTerm terms[] = {PairwiseTerm::potts(), PairwiseTerm::truncated_linear(2.0),
                                  integral_step_term(num_labels)};
    const PairwiseEnergy energy = integral_grid_energy(rng, 12, num_labels, terms[trial % 3]);
    INFO("trial " << trial);
    ExpansionOptions recycling;  // the default: every label has its own graphs
    ExpansionOptions shared;     // one graph, re-solved from the previous move's flow
    shared.graph_memory_limit = 0;
    std::size_t recycled = 0, repeated = 0;
    std::size_t recycled_with_shared = 0;
    ExpansionSolver<DynamicMaxFlow> with_recycling(recycling);
    ExpansionSolver<DynamicMaxFlow> with_shared(shared);
    ExpansionSolver<BoostMaxFlow> boost;  // every move from zero flow
    const int steps = 6 * num_labels;
    const auto recycled_run = labelings_of_run(with_recycling, energy, steps, &recycled, &repeated);
    CHECK(recycled_run == labelings_of_run(with_shared, energy, steps, &recycled_with_shared));
    CHECK(recycled_run == labelings_of_run(boost, energy, steps));
    CHECK(recycled == repeated);
    CHECK(repeated >= static_cast<std::size_t>(steps - 4 * num_labels));
    CHECK(recycled_with_shared == 0);
    // A label's graph its own from its first move: recycled from its second move on.
    ExpansionOptions own_first;
    own_first.first_move_own_graph = true;
    ExpansionSolver<DynamicMaxFlow> with_own_first(own_first);
    std::size_t own_recycled = 0, own_repeated = 0;
    CHECK(recycled_run ==
          labelings_of_run(with_own_first, energy, steps, &own_recycled, &own_repeated, true));
    CHECK(own_recycled == own_repeated);
    CHECK(own_recycled > recycled);
    if (trial % 3 != 2) {  // swap needs a semi-metric
      std::size_t swap_recycled = 0, swap_repeated = 0;
      SwapSolver<DynamicMaxFlow> swap_recycling;  // the default: every pair has its own graphs
      SwapSolver<BoostMaxFlow> swap_boost;
      const auto swap_run =
          labelings_of_run(swap_recycling, energy, 2 * steps, &swap_recycled, &swap_repeated);
      CHECK(swap_run == labelings_of_run(swap_boost, energy, 2 * steps));
      const auto pairs = static_cast<std::size_t>(num_labels * (num_labels - 1) / 2);
      CHECK(swap_recycled == swap_repeated);
      CHECK(swap_repeated == static_cast<std::size_t>(2 * steps) - 2 * pairs);  // swap: no QPBO
    }
  }
}

TEST_CASE("the graph memory limit bounds how many labels recycle their graphs",
          "[expansion][recycling]") {
  Rng rng(3);
  const PairwiseEnergy energy = integral_grid_energy(rng, 10, 5, PairwiseTerm::potts());
  // Potts moves are submodular: one plain graph per label, with the problem it holds (d, p).
  const std::size_t per_label =
      DynamicMaxFlow::memory_bytes_for(100, 180) + (100 + 180) * sizeof(double);
  // Kept move problems have a limit of their own: none here, whatever the graphs get.
  for (const std::size_t labels_that_fit : {0, 1, 2, 3}) {
    ExpansionOptions options;
    options.problem_memory_limit = 0;
    options.graph_memory_limit = labels_that_fit * per_label + per_label / 2;
    ExpansionSolver<DynamicMaxFlow> solver(options);
    std::size_t recycled = 0;
    labelings_of_run(solver, energy, 15, &recycled);  // three sweeps of 5 labels
    CHECK(recycled == labels_that_fit);
  }
}

TEST_CASE("a full graph budget evicts only graphs idle since the requesting key's last move",
          "[recycling]") {
  using Graphs = detail::MoveGraphs<DynamicMaxFlow>;
  using detail::GraphKind;
  Graphs graphs;
  graphs.clear();
  graphs.recycle(4, 200);  // room for two graphs of 100 bytes
  bool recycled = false;
  // The key's own graph when it has one, else the shared graph of its kind.
  const auto owns = [&](std::size_t key, GraphKind kind = GraphKind::plain) {
    graphs.acquire(key, kind, 100, recycled, 1);
    return recycled;
  };
  // A repeating order over three keys with room for two: keys 0 and 1 keep their graphs and
  // key 2 never evicts them (each was used after key 2's previous move).
  for (int sweep = 0; sweep < 3; ++sweep) {
    CHECK(owns(0) == (sweep >= 2));  // first move shared, second move copies, then recycled
    CHECK(owns(1) == (sweep >= 2));
    CHECK_FALSE(owns(2));
  }
  CHECK(graphs.evictions() == 0);
  CHECK(graphs.owned_bytes() == 200);
  // Key 0 stops being used: key 2's next move comes after a move of its own since key 0's
  // last, so key 0's graph is evicted and key 2 gets a copy; from then on key 2 recycles.
  CHECK(owns(1));
  CHECK_FALSE(owns(2));
  CHECK(graphs.evictions() == 1);
  CHECK(owns(2));
  CHECK(owns(1));
  CHECK_FALSE(owns(0));  // both graphs were used since key 0's last move: nothing evicted
  CHECK(graphs.evictions() == 1);
  CHECK(graphs.owned_bytes() == 200);
  // A graph of a kind its key no longer uses is idle too: key 1's moves turn QPBO.
  CHECK_FALSE(owns(1, GraphKind::qpbo));  // its first QPBO move: shared
  CHECK(owns(2));
  CHECK_FALSE(owns(1, GraphKind::qpbo));  // evicts its own plain graph, copies
  CHECK(graphs.evictions() == 2);
  CHECK(owns(1, GraphKind::qpbo));
  CHECK(owns(2));

  // A key's graph its own from its first move (MoveOptions::first_move_own_graph), while it
  // fits without evicting anything; else from its second move, evicting idle graphs.
  graphs.clear();
  graphs.recycle(4, 200, true);
  CHECK_FALSE(owns(0));  // its own, new: solved from zero flow
  CHECK_FALSE(owns(1));
  CHECK_FALSE(owns(2));  // no room: shared
  CHECK(graphs.owned_bytes() == 200);
  CHECK(owns(0));
  CHECK(owns(1));
  CHECK_FALSE(owns(2));  // both graphs were used since key 2's last move
  CHECK(graphs.evictions() == 0);
}

TEST_CASE("patched expansion problems are bitwise the problems computed in full",
          "[expansion][recycling]") {
  Rng rng(17);
  for (int trial = 0; trial < 6; ++trial) {
    const int num_labels = 3 + trial;
    const PairwiseEnergy energy = random_grid_energy(rng, 9, 7, num_labels);  // real costs
    detail::ExpansionProblems kept, scratch;
    kept.bind(energy, std::size_t{1} << 30);
    scratch.bind(energy, 0);  // nothing kept: every problem computed in full
    REQUIRE(kept.memory_bytes() > 0);
    REQUIRE(scratch.memory_bytes() == 0);
    Labeling labeling = random_labeling(rng, energy.num_variables(), num_labels);
    std::uniform_int_distribution<Label> label(0, static_cast<Label>(num_labels - 1));
    std::uniform_int_distribution<VariableIndex> variable(
        0, static_cast<VariableIndex>(energy.num_variables() - 1));
    for (int move = 0; move < 60; ++move) {
      const Label alpha = label(rng);
      std::span<const double> d_kept, p_kept, d_full, p_full;
      kept.update(alpha, labeling, d_kept, p_kept);
      scratch.update(alpha, labeling, d_full, p_full);
      INFO("trial " << trial << ", move " << move);
      CHECK(std::equal(d_kept.begin(), d_kept.end(), d_full.begin(), d_full.end()));
      CHECK(std::equal(p_kept.begin(), p_kept.end(), p_full.begin(), p_full.end()));
      // An accepted move changes a few variables (fewer than N / 8, so the next problems of
      // the labels seen before are patched).
      std::vector<VariableIndex> changed;
      for (int k = 0; k < 3; ++k) {
        const VariableIndex v = variable(rng);
        labeling[v] = label(rng);
        changed.push_back(v);
      }
      kept.log_changes(changed);
      scratch.log_changes(changed);
    }
  }
}

TEST_CASE("expansion and swap read a float energy as the double energy of its stored costs",
          "[solver][float]") {
  Rng rng(1125);
  const PairwiseEnergy twin = integral_grid_energy(rng, 9, 5, integral_step_term(5));
  // Quarters are exact in float and make the costs non-integral.
  std::vector<double> costs = twin.unaries().to_doubles();
  for (double& c : costs) c += 0.25;
  const c2f::FloatValues stored(costs.begin(), costs.end());
  const std::vector<PairwiseTerm> terms(twin.terms().begin(), twin.terms().end());
  const std::vector<Edge> edges(twin.edges().begin(), twin.edges().end());
  const PairwiseEnergy single =
      PairwiseEnergy::with_float_unaries(twin.num_variables(), 5, stored, terms, edges);
  const PairwiseEnergy same(twin.num_variables(), 5, costs, terms, edges);
  ExpansionSolver expansion_single, expansion_double;
  CHECK(labelings_of_run(expansion_single, single, 15) ==
        labelings_of_run(expansion_double, same, 15));
  SwapSolver swap_single, swap_double;
  CHECK(labelings_of_run(swap_single, single, 20) == labelings_of_run(swap_double, same, 20));
}

// Shift moves (ExpansionOptions::shift_moves): the fusion problem is exact, a shift move makes what
// no expansion move can, and expansion with shift moves converges where neither kind helps.

#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

#include "c2f/adapters/graphcut/detail/shift_moves.hpp"
#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/core/grid.hpp"
#include "support/backends.hpp"
#include "support/descent.hpp"
#include "support/random_models.hpp"
#include "support/tiny_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// x with the variables where bit i of b is set moved to shifted[i].
Labeling fused(const Labeling& x, const Labeling& shifted, std::uint32_t b) {
  Labeling out = x;
  for (std::size_t i = 0; i < x.size(); ++i)
    if ((b >> i) & 1u) out[i] = shifted[i];
  return out;
}

/// The lowest energy of any fusion of x with x shifted by `shift` (every assignment).
double best_fusion(const PairwiseEnergy& energy, const Labeling& x, int shift) {
  Labeling shifted(x.size());
  std::vector<double> d(x.size()), p(energy.edges().size());
  detail::shift_problem(energy, x, shift, shifted, d, p);
  double best = energy.evaluate(x);
  for (std::uint32_t b = 0; b < (1u << x.size()); ++b)
    best = std::min(best, energy.evaluate(fused(x, shifted, b)));
  return best;
}

/// An anchor at label 0 (variable 0) and a chain of n variables whose unaries favour the ramp
/// 2, 3, ..., n + 1 over 1, 2, ..., n by 1.5 each, with TSGO's 0 / 1 / 6 smoothness (weight
/// 6). From the lower ramp, moving one variable up turns two steps of one label into a step of
/// two (+4), so no expansion move helps; the shift up moves the whole chain at once (+5 at the
/// anchor, -1.5 n in unaries). No two fusions tie.
PairwiseEnergy anchored_ramp(std::size_t n, int num_labels) {
  const auto labels = static_cast<std::size_t>(num_labels);
  std::vector<double> unaries((n + 1) * labels, 10.0);
  std::fill(unaries.begin(), unaries.begin() + num_labels, 100.0);
  unaries[0] = 0.0;
  for (std::size_t i = 1; i <= n; ++i) {
    unaries[i * labels + i] = 1.5;
    unaries[i * labels + i + 1] = 0.0;
  }
  std::vector<Edge> edges;
  for (std::size_t i = 0; i < n; ++i)
    edges.push_back({static_cast<VariableIndex>(i), static_cast<VariableIndex>(i + 1), 6.0, 0});
  return PairwiseEnergy(n + 1, num_labels, std::move(unaries), {PairwiseTerm::tsgo_step()},
                        std::move(edges));
}

}  // namespace

TEST_CASE("a shift move's problem is the energy of every fusion with the shifted labeling",
          "[expansion][shift]") {
  Rng rng(91);
  for (int trial = 0; trial < 120; ++trial) {
    const int num_labels = 2 + trial % 5;
    const PairwiseEnergy energy =
        trial % 2 == 0
            ? random_grid_energy(rng, 4, 3, num_labels)
            : tiny_model(rng, trial % 3, num_labels,
                         test_terms(rng, num_labels)[static_cast<std::size_t>(trial) % 4]);
    const Labeling x = random_labeling(rng, energy.num_variables(), num_labels);
    // +1, -1, +2 and -2 on both kinds of model.
    const int shift = std::array{1, -1, 2, -2}[static_cast<std::size_t>(trial / 2) % 4];
    Labeling shifted(x.size());
    std::vector<double> d(x.size()), p(energy.edges().size());
    detail::shift_problem(energy, x, shift, shifted, d, p);
    const double base = energy.evaluate(x);
    for (std::size_t i = 0; i < x.size(); ++i) {
      CHECK(shifted[i] == std::clamp(static_cast<int>(x[i]) + shift, 0, num_labels - 1));
      if (shifted[i] == x[i]) CHECK(d[i] == 0.0);
    }
    for (std::uint32_t b = 0; b < (1u << x.size()); ++b) {
      double value = base;
      for (std::size_t i = 0; i < x.size(); ++i) value += ((b >> i) & 1u) ? d[i] : 0.0;
      for (std::size_t e = 0; e < p.size(); ++e) {
        const Edge& edge = energy.edges()[e];
        if (!((b >> edge.u) & 1u) && ((b >> edge.v) & 1u)) value += p[e];
      }
      INFO("trial " << trial << ", shift " << shift << ", assignment " << b);
      CHECK(close_relative(value, energy.evaluate(fused(x, shifted, b)), 1e-9));
    }
  }
}

TEMPLATE_TEST_CASE("a shift move moves a ramp that no expansion move can", "[expansion][shift]",
                   C2F_MAXFLOW_BACKENDS) {
  const std::size_t n = 6;
  const int num_labels = 8;
  const PairwiseEnergy energy = anchored_ramp(n, num_labels);
  Labeling lower(n + 1, 0), upper(n + 1, 0);
  for (std::size_t i = 1; i <= n; ++i) {
    lower[i] = static_cast<Label>(i);
    upper[i] = static_cast<Label>(i + 1);
  }
  REQUIRE(energy.evaluate(upper) == energy.evaluate(lower) - 4.0);
  REQUIRE(best_fusion(energy, lower, 1) == energy.evaluate(upper));
  // Expansion alone stays on the lower ramp: no single move improves it.
  ExpansionSolver<TestType> expansion;
  expansion.bind(energy, lower);
  CHECK(run_to_convergence(expansion, energy, expansion.quiet_steps_to_converge(energy)) ==
        energy.evaluate(lower));
  // With shift moves the first step of the first sweep shifts everything up.
  ExpansionOptions options;
  options.shift_moves = true;
  ExpansionSolver<TestType> solver(options);
  solver.bind(energy, lower);
  CHECK(solver.step() == energy.evaluate(upper));
  CHECK(solver.last_step().shift == 1);
  CHECK(solver.last_step().changed == n);
  CHECK(std::vector<Label>(solver.labeling().begin(), solver.labeling().end()) == upper);
  CHECK(solver.step() == energy.evaluate(upper));  // the shift down finds nothing
  CHECK(solver.last_step().shift == -1);
  CHECK_FALSE(solver.last_step().improved);
  // Then one expansion move per label: a sweep is L + 2 steps.
  for (int label = 0; label < num_labels; ++label) {
    solver.step();
    CHECK(solver.last_step().shift == 0);
    CHECK(solver.last_step().alpha == static_cast<Label>(label));
  }
  solver.step();
  CHECK(solver.last_step().shift == 1);
}

TEMPLATE_TEST_CASE("expansion with shift moves descends to labelings neither kind of move improves",
                   "[expansion][shift][brute-force]", C2F_MAXFLOW_BACKENDS) {
  Rng rng(5151);
  for (int trial = 0; trial < 60; ++trial) {
    const int num_labels = 2 + trial % 3;
    // Linear smoothness makes every shift move submodular (|d + 1| + |d - 1| >= 2|d|), so each
    // is solved exactly and a converged labeling has no better fusion at all.
    const PairwiseEnergy energy =
        trial % 2 == 0
            ? tiny_model(rng, trial % 3, num_labels, PairwiseTerm::truncated_linear(100.0))
            : tiny_model(rng, trial % 3, num_labels,
                         test_terms(rng, num_labels)[static_cast<std::size_t>(trial) % 4]);
    REQUIRE(energy.num_variables() <= 9);
    ExpansionOptions options;
    options.shift_moves = true;
    options.near_radius = trial % 3 == 2 ? 1 : 0;
    options.order = trial % 4 == 1 ? VisitOrder::random : VisitOrder::sequential;
    options.seed = static_cast<std::uint64_t>(trial);
    ExpansionSolver<TestType> solver(options);
    const std::size_t sweep = static_cast<std::size_t>(num_labels) + 2;
    REQUIRE(solver.quiet_steps_to_converge(energy) == (options.near_radius > 0 ? 3 : 1) * sweep);
    solver.bind(energy, random_labeling(rng, energy.num_variables(), num_labels));
    double previous = 0.0;
    std::size_t shifts = 0;
    const std::size_t quiet =
        descend(solver, energy, solver.quiet_steps_to_converge(energy), 3000, previous,
                [&](const auto& s) { shifts += s.last_step().shift != 0; });
    REQUIRE(quiet == solver.quiet_steps_to_converge(energy));
    CHECK(shifts >= 2);
    const Labeling result(solver.labeling().begin(), solver.labeling().end());
    // Converged: no whole expansion move lowers the energy ...
    ExpansionSolver<TestType> whole;
    whole.bind(energy, result);
    for (int step = 0; step < num_labels; ++step) CHECK(whole.step() == previous);
    // ... and, where the shift moves are submodular, no fusion with a shifted labeling does.
    if (trial % 2 == 0) {
      CHECK(best_fusion(energy, result, 1) == previous);
      CHECK(best_fusion(energy, result, -1) == previous);
    }
    CHECK(previous >= brute_force_minimum(energy).energy - 1e-9);
  }
}

namespace {

/// Two variables joined by one edge of `term` (weight `weight`), zero unaries.
PairwiseEnergy one_edge(const PairwiseTerm& term, int num_labels, double weight = 1.0) {
  return PairwiseEnergy(2, num_labels,
                        std::vector<double>(2 * static_cast<std::size_t>(num_labels)), {term},
                        {{0, 1, weight, 0}});
}

/// `costs` (L x L, row-major) with labels 0 and `alpha` swapped.
std::vector<double> swapped_labels(const std::vector<double>& costs, int num_labels, int alpha) {
  const auto relabel = [&](int a) { return a == 0 ? alpha : a == alpha ? 0 : a; };
  std::vector<double> out(costs.size());
  for (int a = 0; a < num_labels; ++a)
    for (int b = 0; b < num_labels; ++b)
      out[static_cast<std::size_t>(a * num_labels + b)] =
          costs[static_cast<std::size_t>(relabel(a) * num_labels + relabel(b))];
  return out;
}

}  // namespace

TEST_CASE("a shift move's problem by bands has the bits of the serial one on any threads",
          "[expansion][shift][threads]") {
  // 150 x 120 pixels: several bands of 8192 variables and of edges.
  Rng rng(31);
  const PairwiseEnergy energy = random_grid_energy(rng, 150, 120, 6);
  const Labeling x = random_labeling(rng, energy.num_variables(), 6);
  const EdgeIncidence incidence(energy);
  for (const int shift : {1, -1, 2}) {
    Labeling shifted(x.size());
    std::vector<double> d(x.size()), p(energy.edges().size());
    detail::shift_problem(energy, x, shift, shifted, d, p);
    for (int threads = 1; threads <= 3; ++threads) {
      Labeling banded_shifted(x.size());
      std::vector<double> banded_d(x.size(), -1.0), banded_p(energy.edges().size(), -1.0);
      detail::shift_problem(energy, incidence, x, shift, banded_shifted, banded_d, banded_p,
                            threads);
      INFO("shift " << shift << ", " << threads << " threads");
      CHECK(banded_shifted == shifted);
      CHECK(banded_d == d);  // every double the same
      CHECK(banded_p == p);
    }
  }
}

TEST_CASE("expansion moves are submodular exactly where no move needs QPBO", "[expansion][shift]") {
  CHECK(expansion_moves_submodular(one_edge(PairwiseTerm::potts(), 5)));
  CHECK(expansion_moves_submodular(one_edge(PairwiseTerm::truncated_linear(2.0), 5)));
  CHECK_FALSE(expansion_moves_submodular(one_edge(PairwiseTerm::tsgo_step(), 5)));
  CHECK_FALSE(expansion_moves_submodular(one_edge(PairwiseTerm::potts(), 5, -1.0)));
  // Against the solver: from every labeling of one edge, the first move (to label 0, each
  // label in turn made label 0) needs QPBO for some start exactly when the test says no.
  Rng rng(808);
  std::uniform_real_distribution<double> cost(0.0, 2.0);
  const int num_labels = 3;
  int submodular_tables = 0;
  const int trials = 40;
  for (int trial = 0; trial < trials; ++trial) {
    std::vector<double> costs(static_cast<std::size_t>(num_labels * num_labels));
    for (int a = 0; a < num_labels; ++a)
      for (int b = 0; b < num_labels; ++b)
        costs[static_cast<std::size_t>(a * num_labels + b)] = a == b ? 0.0 : cost(rng);
    const bool submodular =
        expansion_moves_submodular(one_edge(PairwiseTerm::table(num_labels, costs), num_labels));
    bool needed_qpbo = false;
    for (int alpha = 0; alpha < num_labels; ++alpha) {
      const PairwiseEnergy energy = one_edge(
          PairwiseTerm::table(num_labels, swapped_labels(costs, num_labels, alpha)), num_labels);
      for (Label u = 0; u < num_labels; ++u) {
        for (Label v = 0; v < num_labels; ++v) {
          ExpansionSolver<DynamicMaxFlow> solver;
          solver.bind(energy, Labeling{u, v});
          solver.step();
          needed_qpbo = needed_qpbo || solver.last_step().used_qpbo;
        }
      }
    }
    INFO("trial " << trial);
    CHECK(submodular == !needed_qpbo);
    submodular_tables += submodular ? 1 : 0;
  }
  CHECK(submodular_tables > 0);  // both kinds of table were drawn
  CHECK(submodular_tables < trials);
}

TEST_CASE("shift moves unless submodular: made on energies whose expansion moves need QPBO",
          "[expansion][shift]") {
  Rng rng(909);
  const int num_labels = 6;
  const GridShape shape{5, 4};
  std::uniform_real_distribution<double> cost(0.0, 3.0);
  std::vector<double> unaries(shape.size() * static_cast<std::size_t>(num_labels));
  for (double& u : unaries) u = cost(rng);
  const auto grid = [&](const PairwiseTerm& term) {
    return make_grid_energy(shape, Connectivity::four, num_labels, unaries, term,
                            [](VariableIndex, VariableIndex) { return 1.0; });
  };
  const PairwiseEnergy metric = grid(PairwiseTerm::truncated_linear(2.0));
  const PairwiseEnergy step = grid(PairwiseTerm::tsgo_step());
  ExpansionOptions options;
  options.shift_moves_unless_submodular = true;
  CHECK_FALSE(makes_shift_moves(options, metric));
  CHECK(makes_shift_moves(options, step));
  ExpansionSolver<DynamicMaxFlow> solver(options);
  CHECK(solver.quiet_steps_to_converge(metric) == static_cast<std::size_t>(num_labels));
  CHECK(solver.quiet_steps_to_converge(step) == static_cast<std::size_t>(num_labels) + 2);
  solver.bind(step, Labeling(step.num_variables(), 0));
  CHECK(solver.shift_moves());
  solver.step();
  CHECK(solver.last_step().shift == 1);  // a sweep begins with the shift up
  solver.bind(metric, Labeling(metric.num_variables(), 0));
  CHECK_FALSE(solver.shift_moves());
  solver.step();
  CHECK(solver.last_step().shift == 0);
  // shift_moves on its own makes them everywhere.
  options.shift_moves_unless_submodular = false;
  options.shift_moves = true;
  CHECK(makes_shift_moves(options, metric));
}

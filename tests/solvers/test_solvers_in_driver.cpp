// Every solver adapter inside the coarse-to-fine driver on random energies and random refining
// partition sequences: monotone reported energies, exact final energy.

#include <catch2/catch.hpp>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/adapters/graphcut/swap.hpp"
#include "c2f/adapters/icm/icm.hpp"
#include "c2f/adapters/lbp/lbp.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/partition_list.hpp"
#include "c2f/run/solver_spec.hpp"
#include "support/tiny_models.hpp"

using namespace c2f;
using namespace c2f::test;

static_assert(AnytimeSolver<ExpansionSolver<>, PairwiseEnergy>);
static_assert(AnytimeSolver<SwapSolver<>, PairwiseEnergy>);
static_assert(AnytimeSolver<LbpSolver, PairwiseEnergy>);
static_assert(AnytimeSolver<IcmSolver, PairwiseEnergy>);
static_assert(MaxFlow<BoostMaxFlow>);

TEMPLATE_TEST_CASE("the driver with each solver: monotone energies, exact summary",
                   "[driver][solvers][property]", ExpansionSolver<>, SwapSolver<>, LbpSolver,
                   IcmSolver) {
  Rng rng(1234);
  for (int trial = 0; trial < 60; ++trial) {
    const std::size_t w = std::uniform_int_distribution<std::size_t>(3, 12)(rng);
    const std::size_t h = std::uniform_int_distribution<std::size_t>(3, 12)(rng);
    const int num_labels = std::uniform_int_distribution<int>(2, 6)(rng);
    const auto terms = test_terms(rng, num_labels);
    std::uniform_real_distribution<double> unary(0.0, 5.0), weight(0.0, 2.0);
    std::vector<double> unaries(w * h * static_cast<std::size_t>(num_labels));
    for (double& u : unaries) u = unary(rng);
    const PairwiseEnergy energy =
        make_grid_energy({w, h}, Connectivity::four, num_labels, std::move(unaries),
                         terms[static_cast<std::size_t>(trial) % terms.size()],
                         [&](VariableIndex, VariableIndex) { return weight(rng); });
    std::vector<DensePartition> levels{
        random_partition(rng, w * h, std::max<std::size_t>(1, w * h / 10))};
    levels.push_back(random_refinement(rng, levels.back(), 3));
    PartitionList provider(levels);
    TestType solver;
    Options options;
    options.plateau_steps = {4};
    options.max_steps_per_level = 60;
    std::vector<double> energies;
    const Summary summary =
        coarse_to_fine(energy, provider, solver, options, [&](const StepEvent& event) {
          CHECK(close_relative(event.energy, energy.evaluate(event.ground_labeling()), 1e-12));
          energies.push_back(event.energy);
          return ObserverDecision::continue_run;
        });
    for (std::size_t i = 1; i < energies.size(); ++i) {
      CHECK(energies[i] <= energies[i - 1] + 1e-12 * std::max(1.0, std::abs(energies[i - 1])));
    }
    CHECK(summary.levels.size() == 3);
    CHECK(summary.energy == energy.evaluate(summary.labeling));
  }
}

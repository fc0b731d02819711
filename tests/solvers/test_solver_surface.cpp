// Every shipped solver (the cooperative-cut solver too) has one surface: options with
// validate(), last_step() reporting what the step changed, quiet_steps_to_converge(); a run
// with default options converges; and a solver a SolverSpec names runs the same as one built by
// hand.

#include <catch2/catch.hpp>

#include <cmath>
#include <cstddef>
#include <type_traits>
#include <vector>

#include "c2f/adapters/coop/coop_solver.hpp"
#include "c2f/adapters/graphcut/expansion.hpp"
#include "c2f/adapters/graphcut/swap.hpp"
#include "c2f/adapters/icm/icm.hpp"
#include "c2f/adapters/lbp/lbp.hpp"
#include "c2f/core/grid.hpp"
#include "c2f/driver/coarse_to_fine.hpp"
#include "c2f/lift/partition_list.hpp"
#include "c2f/run/solver_spec.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::test;

namespace {

/// A random Potts grid energy (every solver accepts it: swap needs a semi-metric).
PairwiseEnergy potts_grid(Rng& rng, std::size_t w, std::size_t h, int num_labels) {
  std::uniform_real_distribution<double> unary(0.0, 4.0), weight(0.2, 1.5);
  std::vector<double> unaries(w * h * static_cast<std::size_t>(num_labels));
  for (double& u : unaries) u = unary(rng);
  return make_grid_energy({w, h}, Connectivity::four, num_labels, std::move(unaries),
                          PairwiseTerm::potts(),
                          [&](VariableIndex, VariableIndex) { return weight(rng); });
}

/// The energy each solver of the templated tests is tried on: a random Potts grid, and for the
/// cooperative-cut solver a random cooperative-cut grid (3 edge classes) of the same size.
template <class Solver>
struct SurfaceEnergy {
  static PairwiseEnergy make(Rng& rng, std::size_t w, std::size_t h, int num_labels) {
    return potts_grid(rng, w, h, num_labels);
  }
};
template <>
struct SurfaceEnergy<CoopSolver> {
  static CoopEnergy make(Rng& rng, std::size_t w, std::size_t h, int num_labels) {
    return random_coop_energy(rng, w, h, num_labels, 3);
  }
};

}  // namespace

TEMPLATE_TEST_CASE("last_step() reports exactly the labels a step changed and whether it improved",
                   "[solvers][surface]", ExpansionSolver<>, SwapSolver<>, LbpSolver, IcmSolver,
                   CoopSolver) {
  Rng rng(808);
  std::size_t improving = 0;
  for (int trial = 0; trial < 20; ++trial) {
    const auto energy = SurfaceEnergy<TestType>::make(rng, 7, 5, 2 + trial % 4);
    TestType solver;
    solver.bind(energy, random_labeling(rng, energy.num_variables(), energy.num_labels()));
    CHECK(solver.last_step().changed == 0);
    CHECK_FALSE(solver.last_step().improved);
    for (int step = 0; step < 12; ++step) {
      const Labeling before(solver.labeling().begin(), solver.labeling().end());
      const double energy_before = solver.energy();
      const double energy_after = solver.step();
      std::size_t differing = 0;
      for (std::size_t v = 0; v < before.size(); ++v)
        differing += before[v] != solver.labeling()[v];
      CHECK(solver.last_step().changed == differing);
      CHECK(solver.last_step().improved == (energy_after < energy_before));
      improving += solver.last_step().improved;
    }
  }
  CHECK(improving > 0);  // the property was exercised on improving steps too
}

TEST_CASE("solvers tell when they have converged, and the solver choice agrees",
          "[solvers][surface]") {
  Rng rng(7);
  const PairwiseEnergy seven = potts_grid(rng, 4, 3, 7), one = potts_grid(rng, 4, 3, 1);
  CHECK(ExpansionSolver<>().quiet_steps_to_converge(seven) == 7);
  CHECK(SwapSolver<>().quiet_steps_to_converge(seven) == 21);
  CHECK(SwapSolver<>().quiet_steps_to_converge(one) == 1);
  CHECK(LbpSolver().quiet_steps_to_converge(seven) == 4);
  CHECK(IcmSolver().quiet_steps_to_converge(seven) == 1);
  for (const SolverKind kind :
       {SolverKind::expansion, SolverKind::swap, SolverKind::lbp, SolverKind::icm}) {
    CHECK(solver_kind_from_string(to_string(kind)) == kind);
  }
  const auto expansion_steps = [&](const ExpansionOptions& options) {
    return ExpansionSolver<>(options).quiet_steps_to_converge(seven);
  };
  const auto coarse = [](const SolverSpec& spec) {
    return std::get<ExpansionOptions>(spec.coarse_options());
  };
  ExpansionOptions near;
  near.near_radius = 3;
  CHECK(expansion_steps(near) == 21);  // near moves: three sweeps
  const SolverSpec near_original = expansion_spec(near);
  CHECK(std::get<ExpansionOptions>(near_original.original).near_radius == 3);
  CHECK(coarse(near_original).near_radius == 0);  // near moves on the original only
  CHECK(coarse(expansion_spec(near, NearLevels::all)).near_radius == 3);
  for (const NearLevels levels : {NearLevels::original, NearLevels::all})
    CHECK(near_levels_from_string(to_string(levels)) == levels);
  CHECK_THROWS_WITH(
      near_levels_from_string("coarse"),
      Catch::Contains("unknown near-move levels 'coarse' (expected original or all)"));
  ExpansionOptions shift;
  shift.shift_moves = true;
  CHECK(expansion_steps(shift) == 9);  // L expansion and two shift moves
  shift.near_radius = 3;
  CHECK(expansion_steps(shift) == 27);
  CHECK_FALSE(coarse(expansion_spec(shift)).shift_moves);  // on the original problem only
  CHECK(coarse(expansion_spec(shift, NearLevels::all)).shift_moves);
  // Whole options compare: shift moves alone make coarse levels differ from the original.
  ExpansionOptions only_shift;
  only_shift.shift_moves = true;
  CHECK(expansion_spec(only_shift).coarse.has_value());
  CHECK_FALSE(expansion_spec(only_shift, NearLevels::all).coarse.has_value());
  CHECK_FALSE(expansion_spec(ExpansionOptions{}).coarse.has_value());
  for (const SolverKind kind :
       {SolverKind::expansion, SolverKind::swap, SolverKind::lbp, SolverKind::icm}) {
    CHECK(solver_kind(default_solver_options(kind)) == kind);
  }
  CHECK_THROWS_WITH(
      solver_kind_from_string("trws"),
      Catch::Contains("unknown solver 'trws' (expected expansion, swap, lbp or icm)"));
}

TEMPLATE_TEST_CASE("a run with default options ends where the solver has converged",
                   "[solvers][surface][driver]", ExpansionSolver<>, SwapSolver<>, LbpSolver,
                   IcmSolver, CoopSolver) {
  // Before the solvers said when they converge, default options ended the original problem
  // after 4 steps without decrease: with 8 labels, in the middle of a sweep.
  Rng rng(91);
  for (int trial = 0; trial < 12; ++trial) {
    const auto energy = SurfaceEnergy<TestType>::make(rng, 9, 7, 8);
    TestType solver;
    PartitionList flat;
    const Summary summary = coarse_to_fine(energy, flat, solver, Options{});
    CHECK(summary.reason == TerminationReason::converged);
    // Converged: a move-making solver's quiet steps from the result find nothing lower (BP's
    // state is its messages, not the labeling, so a restart from it proves nothing).
    if constexpr (!std::is_same_v<TestType, LbpSolver>) {
      TestType again;
      again.bind(energy, summary.labeling);
      for (std::size_t step = 0; step < again.quiet_steps_to_converge(energy); ++step)
        CHECK(again.step() >= summary.energy - 1e-9 * std::abs(summary.energy));
    }
  }
}

TEST_CASE("every solver validates its options in one shape", "[solvers][surface][validation]") {
  CHECK_THROWS_WITH(ExpansionSolver<>(ExpansionOptions{{VisitOrder::sequential, 1, -1.0}}),
                    Catch::Contains("ExpansionOptions: tolerance must be finite and >= 0"));
  CHECK_THROWS_WITH(SwapSolver<>(SwapOptions{{VisitOrder::sequential, 1, -1.0}}),
                    Catch::Contains("SwapOptions: tolerance must be finite and >= 0"));
  CHECK_THROWS_WITH(IcmSolver(IcmOptions{VisitOrder::sequential, 1, -1.0}),
                    Catch::Contains("IcmOptions: tolerance must be finite and >= 0"));
  CHECK_THROWS_WITH(IcmSolver(IcmOptions{VisitOrder::frequency}),
                    Catch::Contains("IcmOptions: order 'frequency' orders labels"));
  CHECK_THROWS_WITH(LbpSolver(LbpOptions{BpSchedule::sequential, 1.0}),
                    Catch::Contains("LbpOptions: damping must be in [0, 1)"));
  // A SolverSpec names the options' field, and keeps one solver on every level.
  SolverSpec spec{MaxFlowKind::dynamic, ExpansionOptions{{VisitOrder::frequency}}};
  CHECK(spec.validate().empty());
  spec.original = IcmOptions{VisitOrder::frequency};
  CHECK_THAT(spec.validate(), Catch::StartsWith("original: order 'frequency' orders labels"));
  spec.original = LbpOptions{};
  spec.coarse = IcmOptions{};
  CHECK(spec.validate() ==
        "coarse: options of icm for a run of lbp (the same solver on every level)");
  spec.coarse = LbpOptions{BpSchedule::parallel, 2.0};
  CHECK(spec.validate() == "coarse: damping must be in [0, 1)");
  // The max-flow in parts is our max-flow's: another backend is refused, not run serially.
  ExpansionOptions parted;
  parted.flow_parts = 4;
  CHECK(expansion_spec(parted, NearLevels::original, MaxFlowKind::dynamic).validate().empty());
  CHECK(expansion_spec(parted, NearLevels::original, MaxFlowKind::boost).validate() ==
        "maxflow: flow_parts 4 needs our max-flow ('dynamic'), and the run uses 'boost'");
#ifndef C2F_HAVE_KOLMOGOROV_MAXFLOW
  CHECK_THAT(SolverSpec{MaxFlowKind::kolmogorov}.validate(),
             Catch::StartsWith("maxflow: 'kolmogorov' is not in this build"));
#endif
}

TEST_CASE("a solver a SolverSpec names runs exactly like the one built by hand",
          "[solvers][surface][driver]") {
  Rng rng(99);
  const PairwiseEnergy energy = potts_grid(rng, 12, 9, 4);
  const std::vector<DensePartition> levels{DensePartition::from_ids(std::vector<int>(108, 0)),
                                           random_partition(rng, 108, 20)};
  Options options;
  options.plateau_steps = {3};
  options.plateau_steps_at_original = 6;
  auto by_hand = [&](auto solver) {
    PartitionList provider({levels[0], intersect(levels[0], levels[1])});
    return coarse_to_fine(energy, provider, solver, options);
  };
  auto by_name = [&](SolverOptions solver, MaxFlowKind maxflow = MaxFlowKind::dynamic) {
    PartitionList provider({levels[0], intersect(levels[0], levels[1])});
    return with_solvers(SolverSpec{maxflow, solver}, [&](auto&& solvers) {
      return coarse_to_fine(energy, provider, solvers, options);
    });
  };
  const Summary expansion = by_name(ExpansionOptions{{VisitOrder::random, 5}});
  CHECK(expansion.labeling ==
        by_hand(ExpansionSolver<>(ExpansionOptions{{VisitOrder::random, 5}})).labeling);
  CHECK(by_name(ExpansionOptions{}, MaxFlowKind::boost).labeling ==
        by_hand(ExpansionSolver<BoostMaxFlow>()).labeling);
  CHECK(by_name(SwapOptions{}).labeling == by_hand(SwapSolver<>()).labeling);
  CHECK(by_name(LbpOptions{BpSchedule::parallel, 0.25}).labeling ==
        by_hand(LbpSolver(LbpOptions{BpSchedule::parallel, 0.25})).labeling);
  const Summary icm = by_name(IcmOptions{VisitOrder::random, 3});
  CHECK(icm.labeling == by_hand(IcmSolver(IcmOptions{VisitOrder::random, 3})).labeling);
  CHECK(icm.total_steps > 0);
  CHECK_THROWS_WITH(by_name(IcmOptions{VisitOrder::frequency}),
                    Catch::StartsWith("solver.original: order 'frequency'"));
}

TEST_CASE("near moves a SolverSpec names are made where expansion_spec's levels say",
          "[solvers][surface][driver]") {
  Rng rng(77);
  const PairwiseEnergy energy = potts_grid(rng, 30, 24, 6);
  const DensePartition coarse = random_partition(rng, energy.num_variables(), 200);
  Options options;
  options.plateau_steps = {6};
  options.plateau_steps_at_original = 18;
  ExpansionOptions whole, near;
  near.near_radius = 1;
  // The energies after every step of a run on the coarse level, then the original problem.
  auto energies = [&](auto&& run) {
    std::vector<double> seen;
    PartitionList provider({coarse});
    run(provider, [&](const StepEvent& event) {
      seen.push_back(event.energy);
      return ObserverDecision::continue_run;
    });
    return seen;
  };
  auto by_name = [&](NearLevels levels, bool shift_moves = false) {
    ExpansionOptions moves;
    moves.near_radius = shift_moves ? 0 : 1;
    moves.shift_moves = shift_moves;
    return energies([&](PartitionList& provider, const Observer& observer) {
      with_solvers(expansion_spec(moves, levels), [&](auto&& solvers) {
        return coarse_to_fine(energy, provider, solvers, options, observer);
      });
    });
  };
  const std::vector<double> original_only = by_name(NearLevels::original);
  const std::vector<double> everywhere = by_name(NearLevels::all);
  CHECK(original_only == energies([&](PartitionList& provider, const Observer& observer) {
          ExpansionSolver<> coarse_solver(whole), original_solver(near);
          coarse_to_fine(energy, provider, LevelSolvers(coarse_solver, original_solver), options,
                         observer);
        }));
  CHECK(everywhere == energies([&](PartitionList& provider, const Observer& observer) {
          ExpansionSolver<> solver(near);
          coarse_to_fine(energy, provider, solver, options, observer);
        }));
  CHECK(original_only != everywhere);  // the coarse level's moves differ
  // Shift moves alone follow near_levels too (at 7474d32 the dispatch compared only the near
  // radius, so shift moves without near moves were made on every level).
  ExpansionOptions shift;
  shift.shift_moves = true;
  const std::vector<double> shift_original = by_name(NearLevels::original, true);
  CHECK(shift_original == energies([&](PartitionList& provider, const Observer& observer) {
          ExpansionSolver<> coarse_solver(whole), original_solver(shift);
          coarse_to_fine(energy, provider, LevelSolvers(coarse_solver, original_solver), options,
                         observer);
        }));
  CHECK(by_name(NearLevels::all, true) ==
        energies([&](PartitionList& provider, const Observer& observer) {
          ExpansionSolver<> solver(shift);
          coarse_to_fine(energy, provider, solver, options, observer);
        }));
}

TEST_CASE("a released expansion solver must be bound again, and then runs as a new one",
          "[solvers][surface]") {
  Rng rng(5);
  const PairwiseEnergy energy = potts_grid(rng, 10, 8, 4);
  const Labeling start = random_labeling(rng, energy.num_variables(), energy.num_labels());
  ExpansionSolver<> used, fresh;
  used.bind(energy, start);
  for (int i = 0; i < 5; ++i) used.step();
  used.release();
  CHECK_THROWS_WITH(used.step(), Catch::Contains("call bind() first"));
  used.bind(energy, start);
  fresh.bind(energy, start);
  for (int i = 0; i < 8; ++i) CHECK(used.step() == fresh.step());
  CHECK(std::vector<Label>(used.labeling().begin(), used.labeling().end()) ==
        std::vector<Label>(fresh.labeling().begin(), fresh.labeling().end()));
}

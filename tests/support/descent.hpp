#pragma once
// Running a solver to convergence in a test, checking on every step what every move-making
// solver promises: the energy never increases and always equals evaluate() of the labeling.

#include <catch2/catch.hpp>

#include <cstddef>

#include "c2f/core/pairwise_energy.hpp"

namespace c2f::test {

/// Steps until `sweep` consecutive steps lower nothing, at most max_steps; calls
/// on_step(solver) after every step. Returns the number of quiet steps at the end (== sweep
/// when it converged) and leaves the final energy in `final_energy`.
template <class Solver, class OnStep>
std::size_t descend(Solver& solver, const PairwiseEnergy& energy, std::size_t sweep, int max_steps,
                    double& final_energy, OnStep on_step) {
  double previous = solver.energy();
  std::size_t quiet = 0;
  for (int step = 0; step < max_steps && quiet < sweep; ++step) {
    const double now = solver.step();
    on_step(solver);
    CHECK(now <= previous);
    CHECK(now == energy.evaluate(solver.labeling()));
    quiet = now < previous ? 0 : quiet + 1;
    previous = now;
  }
  final_energy = previous;
  return quiet;
}

/// The same without a hook, at most 2000 steps; returns the final energy.
template <class Solver>
double run_to_convergence(Solver& solver, const PairwiseEnergy& energy, std::size_t sweep) {
  double final_energy = 0.0;
  descend(solver, energy, sweep, 2000, final_energy, [](const Solver&) {});
  return final_energy;
}

}  // namespace c2f::test

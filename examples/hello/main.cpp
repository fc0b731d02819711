// Hello, c2f: a small denoising energy minimised flat and coarse to fine with the same solver,
// then as the library runs it when nothing is named (the run layer's defaults).
// Copy this file to start: it uses the core, the driver, one solver and the run layer.
//   build/release/examples/hello/c2f-hello
#include <cstdio>
#include <random>
#include <vector>

#include "c2f/adapters/graphcut/expansion.hpp"  // c2f::graphcut
#include "c2f/core/grid.hpp"                    // c2f::core
#include "c2f/driver/coarse_to_fine.hpp"        // c2f::driver
#include "c2f/lift/partition_list.hpp"          // c2f::lift
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/run/defaults.hpp"  // c2f::run
#include "c2f/run/run.hpp"

/// A width x height image of `labels` grey levels (a bright square on a ramp) seen through
/// noise, as an energy: squared distance to the observed value per pixel and label, plus a
/// truncated-linear term between 4-neighbours.
c2f::PairwiseEnergy noisy_image_energy(std::size_t width, std::size_t height, int labels) {
  std::mt19937 rng(1);
  std::normal_distribution<double> noise(0.0, 3.0);
  std::vector<double> unaries(width * height * labels);  // unaries[v * labels + l]
  for (std::size_t y = 0; y < height; ++y) {
    for (std::size_t x = 0; x < width; ++x) {
      const bool square = x > 50 && x < 110 && y > 30 && y < 90;
      const double observed = (square ? 13.0 : 2.0 + 6.0 * x / width) + noise(rng);
      for (int l = 0; l < labels; ++l) {
        const double d = l - observed;
        unaries[(y * width + x) * labels + l] = d * d;
      }
    }
  }
  return c2f::make_grid_energy({width, height}, c2f::Connectivity::four, labels, std::move(unaries),
                               c2f::PairwiseTerm::truncated_linear(3.0),
                               [](c2f::VariableIndex, c2f::VariableIndex) { return 4.0; });
}

void print(const char* name, const c2f::Summary& summary) {
  std::printf("%-15s energy %.1f in %.3f s (%ld steps, %zu levels)\n", name, summary.energy,
              summary.seconds, summary.total_steps, summary.levels.size());
}

int main() {
  const std::size_t width = 160, height = 120;
  const c2f::PairwiseEnergy energy = noisy_image_energy(width, height, 16);
  c2f::ExpansionSolver<> solver;  // alpha-expansion; any AnytimeSolver fits here
  c2f::Options options;           // coarse levels: 4 quiet steps; the original: until converged

  // Flat: the solver on the original problem only (no levels).
  c2f::PartitionList no_levels;
  print("flat:", c2f::coarse_to_fine(energy, no_levels, solver, options));

  // Coarse to fine: colour-passing levels CP(1,1), CP(2,1), CP(3,1), then the original problem.
  c2f::ScheduleProvider levels(c2f::Schedule::parse("cp:1,1 cp:2,1 cp:3,1 flat"), {width, height});
  const c2f::Summary summary = c2f::coarse_to_fine(energy, levels, solver, options);
  print("coarse to fine:", summary);

  // The defaults: what c2f-solve and c2f.solve run when nothing is named, the schedule, moves
  // and rules measured best (docs/results.md, "Defaults"), planned within a memory budget.
  const c2f::RunDefaults defaults = c2f::pairwise_defaults();
  c2f::ScheduleProvider default_levels(c2f::Schedule::parse(defaults.grid_schedule),
                                       {width, height});
  const c2f::RunReport report = c2f::run(energy, default_levels, defaults.config(/*on_grid=*/true));
  print("defaults:", report.summary);
  // A summary's energy is the energy of its labeling on the original problem.
  const bool exact = summary.energy == energy.evaluate(summary.labeling) &&
                     report.summary.energy == energy.evaluate(report.summary.labeling);
  return exact ? 0 : 1;
}

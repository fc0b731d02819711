// Uses every component of an installed c2f through the umbrella header: a stereo schedule
// preset (vision), colour-passing levels (lift), alpha-expansion run by the run layer (graphcut,
// run) with the driver. Exits 0 only when the run finishes on the original problem with an
// energy equal to evaluate() of its labeling and no higher than the flat run's start.
#include <c2f/c2f.hpp>

#include <iostream>
#include <vector>

int main() {
  const c2f::GridShape shape{16, 12};
  std::vector<double> unaries(shape.size() * 4);
  for (std::size_t i = 0; i < unaries.size(); ++i)
    unaries[i] = static_cast<double>((i * 7919) % 17) / 4.0;
  const c2f::PairwiseEnergy energy = c2f::make_grid_energy(
      shape, c2f::Connectivity::four, 4, std::move(unaries), c2f::PairwiseTerm::tsgo_step(),
      [](c2f::VariableIndex, c2f::VariableIndex) { return 0.3125; });
  c2f::ScheduleProvider levels(c2f::vision::parse_stereo_schedule("paper"), shape);
  const c2f::RunConfig config;  // alpha-expansion within the machine's default memory budget
  const c2f::Summary summary = c2f::run(energy, levels, config).summary;
  const double start =
      energy.evaluate(c2f::initial_labeling(energy, c2f::InitialLabeling::unary_argmin));
  std::cout << "coarse-to-fine " << summary.energy << " from " << start << " in "
            << summary.levels.size() << " levels\n";
  const bool ok = summary.energy == energy.evaluate(summary.labeling) && summary.energy <= start &&
                  summary.levels.size() == 4;
  return ok ? 0 : 1;
}

// Imports the installed module and minimises a small Potts grid energy flat with expansion.
#include <cstdio>
#include <utility>
#include <vector>

import c2f;

int main() {
  const c2f::GridShape shape{6, 4};
  std::vector<double> unaries(shape.size() * 3);
  for (std::size_t v = 0; v < shape.size(); ++v)
    for (int l = 0; l < 3; ++l)
      unaries[v * 3 + l] = (v % 3 == static_cast<std::size_t>(l)) ? 0.0 : 1.0;
  const c2f::PairwiseEnergy energy = c2f::make_grid_energy(
      shape, c2f::Connectivity::four, 3, std::move(unaries), c2f::PairwiseTerm::potts(),
      [](c2f::VariableIndex, c2f::VariableIndex) { return 0.3; });
  c2f::PartitionList flat;
  c2f::ExpansionSolver<> solver;
  const c2f::Summary summary = c2f::coarse_to_fine(energy, flat, solver, c2f::Options{});
  std::printf("module consumer: energy %g after %ld steps\n", summary.energy, summary.total_steps);
  return summary.total_steps > 0 && summary.energy < energy.evaluate(c2f::Labeling(shape.size(), 0))
             ? 0
             : 1;
}

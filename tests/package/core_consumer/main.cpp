// Solves a small grid energy flat and coarse to fine with ICM over block levels, using only the
// core component's headers; exits 0 only when both runs finish with energies equal to
// evaluate() of their labelings and the coarse-to-fine run went through all three levels.
#include <c2f/adapters/icm/icm.hpp>
#include <c2f/core/grid.hpp>
#include <c2f/driver/coarse_to_fine.hpp>
#include <c2f/lift/block_hierarchy.hpp>
#include <c2f/lift/partition_list.hpp>

#include <iostream>
#include <vector>

int main() {
  const c2f::GridShape shape{8, 8};
  std::vector<double> unaries(shape.size() * 3);
  for (std::size_t i = 0; i < unaries.size(); ++i)
    unaries[i] = static_cast<double>((i * 7919) % 13);
  const c2f::PairwiseEnergy energy = c2f::make_grid_energy(
      shape, c2f::Connectivity::four, 3, std::move(unaries), c2f::PairwiseTerm::potts(),
      [](c2f::VariableIndex, c2f::VariableIndex) { return 2.0; });
  c2f::IcmSolver solver;
  c2f::PartitionList flat;
  c2f::BlockHierarchy blocks(shape, {4, 2});
  const c2f::Summary a = c2f::coarse_to_fine(energy, flat, solver, c2f::Options{});
  const c2f::Summary b = c2f::coarse_to_fine(energy, blocks, solver, c2f::Options{});
  std::cout << "flat " << a.energy << ", coarse-to-fine " << b.energy << "\n";
  const bool ok = a.energy == energy.evaluate(a.labeling) &&
                  b.energy == energy.evaluate(b.labeling) && b.levels.size() == 3;
  return ok ? 0 : 1;
}

#pragma once
// The stereo-sized synthetic energy the microbenchmarks share: a 463x370 4-connected grid
// (Middlebury 2005 at third size), 85 labels, TSGO step term, random unaries in [0, 1) and
// weights drawn from the three TSGO weight classes. Built once per process.

#include <random>

#include "c2f/core/grid.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/vision/stereo/colour_weights.hpp"

namespace c2f::bench {

inline constexpr GridShape kStereoShape{463, 370};
inline constexpr int kStereoLabels = 85;

inline const PairwiseEnergy& stereo_sized_energy() {
  static const PairwiseEnergy energy = [] {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> cost(0.0, 1.0);
    std::vector<double> unaries(kStereoShape.size() * kStereoLabels);
    for (double& u : unaries) u = cost(rng);
    std::uniform_int_distribution<int> weight_class(0, 2);
    return make_grid_energy(
        kStereoShape, Connectivity::four, kStereoLabels, std::move(unaries),
        PairwiseTerm::tsgo_step(), [&](VariableIndex, VariableIndex) {
          return vision::kTsgoWeights[static_cast<std::size_t>(weight_class(rng))];
        });
  }();
  return energy;
}

}  // namespace c2f::bench

#include "c2f/lift/threshold_partition.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "disjoint_sets.hpp"

namespace c2f {

DensePartition threshold_partition(const PairwiseEnergy& energy, GridShape shape, double tau,
                                   int radius) {
  LiftingView view;
  view.num_variables = energy.num_variables();
  view.num_labels = energy.num_labels();
  view.unaries = energy.unaries();
  return threshold_partition(view, shape, tau, radius);
}

DensePartition threshold_partition(const LiftingView& energy, GridShape shape, double tau,
                                   int radius) {
  require_grid_size(energy.num_variables, shape, "threshold_partition");
  if (!(tau >= 0.0)) throw std::invalid_argument("threshold_partition: tau must be >= 0");
  if (radius < 1) throw std::invalid_argument("threshold_partition: radius must be >= 1");
  const auto w = static_cast<long>(shape.width), h = static_cast<long>(shape.height);
  const auto L = static_cast<std::size_t>(energy.num_labels);
  detail::DisjointSets sets(shape.size());
  auto within = [&](std::size_t a, std::size_t b) {
    return energy.unaries.visit([&](auto costs) {
      const auto ra = costs.subspan(a * L, L), rb = costs.subspan(b * L, L);
      double distance = 0.0;
      for (std::size_t l = 0; l < L && distance <= tau; ++l)
        distance += std::abs(static_cast<double>(ra[l]) - static_cast<double>(rb[l]));
      return distance <= tau;
    });
  };
  for (long y = 0; y < h; ++y) {
    for (long x = 0; x < w; ++x) {
      const auto v = static_cast<std::size_t>(y * w + x);
      // The forward half of the window: each unordered pair once.
      for (long dy = 0; dy <= radius; ++dy) {
        for (long dx = -radius; dx <= radius; ++dx) {
          if (dy == 0 && dx <= 0) continue;
          const long x2 = x + dx, y2 = y + dy;
          if (x2 < 0 || x2 >= w || y2 >= h) continue;
          const auto u = static_cast<std::size_t>(y2 * w + x2);
          if (sets.find(u) != sets.find(v) && within(v, u)) sets.unite(v, u);
        }
      }
    }
  }
  return sets.partition();
}

}  // namespace c2f

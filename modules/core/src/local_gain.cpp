#include "c2f/core/local_gain.hpp"

#include <algorithm>
#include <bit>
#include <vector>

namespace c2f {

double local_gain(const PairwiseEnergy& energy, std::span<const Label> labeling,
                  std::size_t max_costs) {
  const std::size_t n = energy.num_variables();
  const auto L = static_cast<std::size_t>(energy.num_labels());
  validate_labeling(labeling, n, energy.num_labels(), "local_gain: labeling");
  if (n == 0) return 0.0;
  std::size_t stride = 1;
  if (max_costs > 0 && n * L > max_costs)
    stride = std::bit_ceil((n * L + max_costs - 1) / max_costs);
  const std::size_t skip = stride - 1;                    // v is visited when v & skip is 0
  const std::size_t visited = (n + stride - 1) / stride;  // variables 0, stride, 2 stride, ...
  std::vector<double> costs(visited * L);
  for (std::size_t i = 0; i < visited; ++i)
    for (std::size_t l = 0; l < L; ++l)
      costs[i * L + l] = energy.unary(i * stride, static_cast<Label>(l));
  for (const Edge& e : energy.edges()) {
    if ((e.u & skip) == 0) {
      double* const row = costs.data() + e.u / stride * L;
      for (std::size_t l = 0; l < L; ++l)
        row[l] += energy.pairwise_cost(e, static_cast<Label>(l), labeling[e.v]);
    }
    if ((e.v & skip) == 0) {
      double* const row = costs.data() + e.v / stride * L;
      for (std::size_t l = 0; l < L; ++l)
        row[l] += energy.pairwise_cost(e, labeling[e.u], static_cast<Label>(l));
    }
  }
  double gain = 0.0;
  for (std::size_t i = 0; i < visited; ++i) {
    const double* row = costs.data() + i * L;
    const double current = row[static_cast<std::size_t>(labeling[i * stride])];
    gain += std::max(0.0, current - *std::min_element(row, row + L));
  }
  return gain * static_cast<double>(n) / static_cast<double>(visited);
}

}  // namespace c2f

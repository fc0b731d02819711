#pragma once
// What single-variable changes could gain from a labeling: an estimate of what a solver's
// first sweep gains from it, used to judge a coarse level against the original problem
// (progress_rate in c2f/driver/rules.hpp).

#include <cstddef>
#include <span>

#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

/// Sum over variables v of max(0, local(v, x_v) - min_l local(v, l)), where local(v, l) is
/// v's unary cost of l plus the weighted terms of v's edges with every neighbour keeping its
/// label in x: what a pass of iterated conditional modes would gain if no two changes
/// interacted. With max_costs > 0 and num_variables * num_labels above it, only every s-th
/// variable is visited (s the least power of two that keeps the visited variables' costs
/// within max_costs) and their sum is scaled by N over their number: an estimate in
/// O(E + max_costs) time and O(max_costs) memory. Deterministic. Throws std::invalid_argument when
/// `labeling` is not a labeling of `energy`.
[[nodiscard]] double local_gain(const PairwiseEnergy& energy, std::span<const Label> labeling,
                                std::size_t max_costs = 0);

}  // namespace c2f

#pragma once
// The levels of an `auto:F1,F2,...` schedule, chosen from the energy.

#include <span>
#include <vector>

#include "c2f/lift/level_spec.hpp"
#include "c2f/lift/lifting_view.hpp"

namespace c2f {

/// Colour-passing levels along one refining chain (CP(1,1), then alternately raising N_L and
/// iterating, at most 16 steps): for each fraction F (increasing, in (0, 1)) the first unused
/// level whose group count is closest, in log ratio, to F times the number of variables. The
/// levels come out in refining order; fewer than the fractions when the chain runs out.
std::vector<LevelSpec> auto_levels(const LiftingView& energy, std::span<const double> fractions);

}  // namespace c2f

#include "c2f/adapters/graphcut/move_options.hpp"

#include <cmath>

namespace c2f {

std::string MoveOptions::validate() const {
  if (!std::isfinite(tolerance) || tolerance < 0.0) return "tolerance must be finite and >= 0";
  return {};
}

std::string ExpansionOptions::validate() const {
  if (std::string problem = MoveOptions::validate(); !problem.empty()) return problem;
  if (near_radius < 0) return "near_radius must be >= 0";
  if (!std::isfinite(near_sweep_gain) || near_sweep_gain < 0.0)
    return "near_sweep_gain must be finite and >= 0";
  return {};
}

}  // namespace c2f

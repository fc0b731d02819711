#include "c2f/adapters/graphcut/move_options.hpp"

#include <cmath>

namespace c2f {

std::string MoveOptions::validate() const {
  if (!std::isfinite(tolerance) || tolerance < 0.0) return "tolerance must be finite and >= 0";
  return {};
}

}  // namespace c2f

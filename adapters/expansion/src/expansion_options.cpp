#include <cmath>

#include "c2f/adapters/expansion.hpp"

namespace c2f {

std::string ExpansionOptions::validate() const {
  if (!std::isfinite(tolerance) || tolerance < 0.0) return "tolerance must be finite and >= 0";
  return {};
}

}  // namespace c2f

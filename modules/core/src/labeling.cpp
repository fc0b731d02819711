#include "c2f/core/labeling.hpp"

#include <stdexcept>
#include <string>

namespace c2f {

void validate_labeling(std::span<const Label> labeling, std::size_t num_variables, int num_labels,
                       std::string_view what) {
  if (labeling.size() != num_variables) {
    throw std::invalid_argument(
        std::string(what) + ": has " + std::to_string(labeling.size()) +
        " entries, expected num_variables = " + std::to_string(num_variables));
  }
  for (std::size_t v = 0; v < labeling.size(); ++v) {
    if (labeling[v] < 0 || labeling[v] >= num_labels) {
      throw std::invalid_argument(std::string(what) + ": label " + std::to_string(labeling[v]) +
                                  " of variable " + std::to_string(v) + " is out of range [0, " +
                                  std::to_string(num_labels) + ")");
    }
  }
}

}  // namespace c2f

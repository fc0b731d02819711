// Fuzz target: the scenes.csv parser. Any input is refused with std::invalid_argument or gives
// rows whose sizes and divisors are in range.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "c2f/vision/stereo/middlebury.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const auto rows = c2f::vision::parse_scene_table(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.csv");
    for (const auto& row : rows) {
      if (row.width < 1 || row.height < 1 || !(row.gt_divisor > 0.0) ||
          !std::isfinite(row.gt_divisor) || row.scene.empty())
        throw std::logic_error("scene table row out of range");
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

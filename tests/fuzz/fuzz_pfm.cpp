// Fuzz target: the PFM parser. Any input is refused with std::runtime_error or gives a map of
// the declared size.

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string_view>

#include "c2f/vision/stereo/disparity_io.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const cv::Mat map = c2f::vision::parse_pfm(
        std::string_view(reinterpret_cast<const char*>(data), size), "fuzz.pfm");
    if (map.type() != CV_32F || map.empty()) throw std::logic_error("PFM parsed to no map");
  } catch (const std::runtime_error&) {
  }
  return 0;
}

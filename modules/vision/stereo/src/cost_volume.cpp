#include "c2f/vision/stereo/cost_volume.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

namespace c2f::vision {

CostVolume::CostVolume(std::size_t width, std::size_t height, int labels, double fill)
    : CostVolume(width, height, labels, Unwritten{}) {
  std::fill(data_.begin(), data_.end(), static_cast<float>(fill));
}

CostVolume::CostVolume(std::size_t width, std::size_t height, int labels, Unwritten)
    : width_(width), height_(height), labels_(labels) {
  if (width == 0 || height == 0 || labels < 1) {
    throw std::invalid_argument("CostVolume: width, height and labels must be >= 1, got " +
                                std::to_string(width) + "x" + std::to_string(height) + " with " +
                                std::to_string(labels) + " labels");
  }
  data_.resize(width * height * static_cast<std::size_t>(labels));
}

}  // namespace c2f::vision

#include "c2f/vision/stereo/colour_weights.hpp"

#include <cstdlib>

namespace c2f::vision {

double tsgo_edge_weight(const cv::Mat& image, VariableIndex u, VariableIndex v) {
  const auto width = static_cast<VariableIndex>(image.cols);
  const cv::Vec3b a = image.at<cv::Vec3b>(static_cast<int>(u / width), static_cast<int>(u % width));
  const cv::Vec3b b = image.at<cv::Vec3b>(static_cast<int>(v / width), static_cast<int>(v % width));
  const int difference = std::abs(a[0] - b[0]) + std::abs(a[1] - b[1]) + std::abs(a[2] - b[2]);
  if (difference < kTsgoWeightBounds[0]) return kTsgoWeights[0];
  if (difference < kTsgoWeightBounds[1]) return kTsgoWeights[1];
  return kTsgoWeights[2];
}

}  // namespace c2f::vision

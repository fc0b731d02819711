#include "c2f/vision/stereo/absolute_difference_cost.hpp"

#include "stereo_pair_checks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace c2f::vision {

std::vector<double> absolute_difference_cost(const cv::Mat& left, const cv::Mat& right,
                                             int num_labels, double truncation) {
  detail::require_colour_pair(left, right, "absolute_difference_cost");
  if (num_labels < 1)
    throw std::invalid_argument("absolute_difference_cost: num_labels must be >= 1");
  if (!(truncation > 0.0) || !std::isfinite(truncation)) {
    throw std::invalid_argument("absolute_difference_cost: truncation must be finite and > 0");
  }
  const auto L = static_cast<std::size_t>(num_labels);
  std::vector<double> unaries(static_cast<std::size_t>(left.rows * left.cols) * L, truncation);
  for (int y = 0; y < left.rows; ++y) {
    const auto* l_row = left.ptr<cv::Vec3b>(y);
    const auto* r_row = right.ptr<cv::Vec3b>(y);
    for (int x = 0; x < left.cols; ++x) {
      double* out = unaries.data() + (static_cast<std::size_t>(y) * left.cols + x) * L;
      for (int d = 0; d < num_labels && x - d >= 0; ++d) {
        int sum = 0;
        for (int c = 0; c < 3; ++c) sum += std::abs(l_row[x][c] - r_row[x - d][c]);
        out[d] = std::min(sum / 3.0, truncation);
      }
    }
  }
  return unaries;
}

}  // namespace c2f::vision

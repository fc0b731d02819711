#include "stereo_pair_checks.hpp"

#include <stdexcept>
#include <string>

namespace c2f::vision::detail {

void require_colour_pair(const cv::Mat& left, const cv::Mat& right, const char* who) {
  if (left.type() != CV_8UC3 || right.type() != CV_8UC3) {
    throw std::invalid_argument(std::string(who) + ": images must be 8-bit 3-channel");
  }
  if (left.size() != right.size()) {
    throw std::invalid_argument(std::string(who) + ": left is " + std::to_string(left.cols) + "x" +
                                std::to_string(left.rows) + ", right is " +
                                std::to_string(right.cols) + "x" + std::to_string(right.rows));
  }
}

}  // namespace c2f::vision::detail

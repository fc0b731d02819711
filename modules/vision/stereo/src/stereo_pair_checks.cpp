#include "stereo_pair_checks.hpp"

#include <cmath>
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

void require_view_size(const cv::Mat& image, const cv::Mat& views, const std::string& what) {
  if (image.size() == views.size()) return;
  throw std::invalid_argument(what + " is " + std::to_string(image.cols) + "x" +
                              std::to_string(image.rows) + ", the views are " +
                              std::to_string(views.cols) + "x" + std::to_string(views.rows));
}

void require_known_pixel(const cv::Mat& gt, const std::string& what) {
  for (auto it = gt.begin<float>(); it != gt.end<float>(); ++it) {
    if (!std::isnan(*it)) return;
  }
  throw std::invalid_argument(what + " has no known pixel: nothing could be evaluated against it");
}

}  // namespace c2f::vision::detail

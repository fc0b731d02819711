#include "c2f/vision/image_io.hpp"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <vector>

#include <opencv2/core.hpp>

namespace c2f::vision {

namespace {
cv::Mat load(const std::string& path, int flags) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("image '" + path + "' does not exist");
  cv::Mat image = cv::imread(path, flags);
  if (image.empty()) throw std::runtime_error("image '" + path + "' could not be read as an image");
  if (image.depth() != CV_8U)
    throw std::runtime_error("image '" + path + "' is not 8 bits per channel");
  return image;
}
}  // namespace

cv::Mat load_colour_image(const std::string& path) {
  return load(path, cv::IMREAD_COLOR);
}

cv::Mat load_grey_image(const std::string& path) {
  return load(path, cv::IMREAD_GRAYSCALE);
}

cv::Mat load_single_channel_image(const std::string& path) {
  if (!std::filesystem::exists(path))
    throw std::runtime_error("image '" + path + "' does not exist");
  cv::Mat image = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (image.empty()) throw std::runtime_error("image '" + path + "' could not be read as an image");
  if (image.channels() >= 3 && image.depth() == CV_8U) {
    // Grey stored as colour (some Middlebury files): taken when the colour channels agree.
    std::vector<cv::Mat> channels;
    cv::split(image, channels);
    if (cv::countNonZero(channels[0] != channels[1]) == 0 &&
        cv::countNonZero(channels[0] != channels[2]) == 0) {
      return channels[0];
    }
  }
  if (image.channels() != 1 || (image.depth() != CV_8U && image.depth() != CV_16U)) {
    throw std::invalid_argument("image '" + path + "' has " + std::to_string(image.channels()) +
                                " channels of " + (image.depth() == CV_8U ? "8" : "other") +
                                "-bit values; expected one channel of 8 or 16 bits (or grey "
                                "stored as equal colour channels)");
  }
  return image;
}

}  // namespace c2f::vision

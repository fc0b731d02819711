#include "c2f/vision/image_io.hpp"

#include <filesystem>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>

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

}  // namespace c2f::vision

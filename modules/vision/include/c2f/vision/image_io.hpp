#pragma once
// Image loading with errors that name the file.

#include <opencv2/core.hpp>
#include <string>

namespace c2f::vision {

/// Loads an image as 8-bit 3-channel BGR (grey and palette images are converted). Throws
/// std::runtime_error naming the path when it is missing or not a readable image.
cv::Mat load_colour_image(const std::string& path);

/// Loads an image as 8-bit single channel (palette PNGs decode to their grey levels). Throws
/// std::runtime_error naming the path when it is missing or not a readable image.
cv::Mat load_grey_image(const std::string& path);

/// A single-channel image with its stored depth: 8 or 16 bits per pixel (a disparity or a
/// labeling with values above 255 stays whole); an 8-bit colour image whose channels are all
/// equal (grey stored as colour) gives its first channel. Throws std::runtime_error naming the
/// path when the file is missing or unreadable, and std::invalid_argument for other colour
/// images or depths.
cv::Mat load_single_channel_image(const std::string& path);

}  // namespace c2f::vision

#pragma once
// Image loading with errors that name the file.

#include <opencv2/core.hpp>
#include <string>

namespace c2f::vision {

/// Loads an image as 8-bit 3-channel BGR (grey and palette images are converted, an alpha
/// channel is dropped). Throws std::invalid_argument naming the path when it is missing, not a
/// readable image, or not 8 bits per channel (a 16-bit image is refused, not scaled down).
cv::Mat load_colour_image(const std::string& path);

/// load_colour_image for drawings over a transparent background (seed scribbles): a pixel
/// less than half opaque (alpha below 128) becomes white, the colour of no seed; an opaque one
/// keeps its colour. An image without alpha loads as load_colour_image loads it.
cv::Mat load_colour_image_on_white(const std::string& path);

/// Loads an image as 8-bit single channel (colour images are converted to grey; palette PNGs
/// decode to their grey levels). Throws std::invalid_argument as load_colour_image does.
cv::Mat load_grey_image(const std::string& path);

/// A single-channel image with its stored depth: 8 or 16 bits per pixel (a disparity or a
/// labeling with values above 255 stays whole); an 8-bit colour image whose channels are all
/// equal (grey stored as colour) gives its first channel. Throws std::invalid_argument naming
/// the path when the file is missing or unreadable, and for other colour images or depths.
cv::Mat load_single_channel_image(const std::string& path);

}  // namespace c2f::vision

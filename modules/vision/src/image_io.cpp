#include "c2f/vision/image_io.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

#include "c2f/support/input_file.hpp"
#include "c2f/support/text_input.hpp"

namespace c2f::vision {

namespace {

/// A PNG's size from its header (IHDR), or nullopt when `path` is no PNG.
std::optional<std::pair<std::uint32_t, std::uint32_t>> png_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  unsigned char header[24] = {};
  if (!in.read(reinterpret_cast<char*>(header), sizeof header)) return std::nullopt;
  constexpr unsigned char kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (!std::equal(std::begin(kSignature), std::end(kSignature), header)) return std::nullopt;
  auto big_endian = [&](int at) {
    return (std::uint32_t{header[at]} << 24) | (std::uint32_t{header[at + 1]} << 16) |
           (std::uint32_t{header[at + 2]} << 8) | std::uint32_t{header[at + 3]};
  };
  return std::pair{big_endian(16), big_endian(20)};
}

/// A PNM's (PBM, PGM, PPM: "P1" to "P6") size from its header, or nullopt when `path` is no PNM
/// or its header is not readable as one.
std::optional<std::pair<std::uint64_t, std::uint64_t>> pnm_size(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::string header(256, '\0');
  in.read(header.data(), static_cast<std::streamsize>(header.size()));
  header.resize(static_cast<std::size_t>(in.gcount()));
  if (header.size() < 3 || header[0] != 'P' || header[1] < '1' || header[1] > '6')
    return std::nullopt;
  std::size_t at = 2;
  std::uint64_t sides[2] = {0, 0};
  for (std::uint64_t& side : sides) {
    while (at < header.size() &&
           (std::isspace(static_cast<unsigned char>(header[at])) || header[at] == '#')) {
      if (header[at] == '#') at = header.find('\n', at);  // a comment to the line's end
      if (at == std::string::npos) return std::nullopt;
      ++at;
    }
    const std::size_t start = at;
    while (at < header.size() && std::isdigit(static_cast<unsigned char>(header[at])) &&
           at - start < 18)
      side = 10 * side + static_cast<std::uint64_t>(header[at++] - '0');
    if (at == start) return std::nullopt;
  }
  return std::pair{sides[0], sides[1]};
}

/// The image with its stored depth and channels (`flags` adds to IMREAD_ANYDEPTH; palette
/// images decode to colour).
cv::Mat load_as_stored(const std::string& path, int flags) {
  if (const std::string why = why_not_a_file(path); !why.empty())
    throw std::invalid_argument("image '" + path + "' " + why);
  // OpenCV refuses images of more than 2^30 pixels with a raw message of its own on stderr;
  // a PNG says its size first, so such a file is refused here by name.
  constexpr std::uint64_t kMaxPixels = std::uint64_t{1} << 30;
  // OpenCV also refuses a side above 2^20; a PNM header says its size as text.
  constexpr std::uint64_t kMaxSide = std::uint64_t{1} << 20;
  std::optional<std::pair<std::uint64_t, std::uint64_t>> size;
  if (const auto png = png_size(path)) size = std::pair<std::uint64_t, std::uint64_t>(*png);
  if (!size) size = pnm_size(path);
  if (size && (size->first * size->second > kMaxPixels || size->first > kMaxSide ||
               size->second > kMaxSide)) {
    throw std::invalid_argument(
        "image '" + path + "' is " + std::to_string(size->first) + "x" +
        std::to_string(size->second) +
        " pixels by its header, more than an image may have (2^30 = 1073741824 pixels, 2^20 "
        "per side)");
  }
  // Decoded, at most 4 bytes a pixel (8-bit colour and alpha; 16-bit grey takes 2).
  if (size) {
    require_input_memory(path, "image", 4.0 * static_cast<double>(size->first * size->second),
                         "decoded (" + std::to_string(size->first) + "x" +
                             std::to_string(size->second) + " pixels by its header)");
  }
  cv::Mat image;
  try {
    image = cv::imread(path, cv::IMREAD_ANYDEPTH | flags);
  } catch (const cv::Exception& error) {
    throw std::invalid_argument("image '" + path + "' could not be read as an image (OpenCV: " +
                                printable(error.err, 200) + ")");
  }
  if (image.empty())
    throw std::invalid_argument("image '" + path + "' could not be read as an image");
  return image;
}

/// Refuses anything but 8 bits per channel, which OpenCV would otherwise scale down silently.
const cv::Mat& require_8_bit(const cv::Mat& image, const std::string& path) {
  if (image.depth() != CV_8U) {
    throw std::invalid_argument("image '" + path + "' has " +
                                std::to_string(8 * image.elemSize1()) +
                                "-bit channels; expected 8 bits per channel");
  }
  return image;
}

}  // namespace

cv::Mat load_colour_image(const std::string& path) {
  // ANYCOLOR keeps grey as grey and drops alpha; EXIF orientation is applied as by default.
  const cv::Mat image = require_8_bit(load_as_stored(path, cv::IMREAD_ANYCOLOR), path);
  cv::Mat colour;
  switch (image.channels()) {
    case 1:
      cv::cvtColor(image, colour, cv::COLOR_GRAY2BGR);
      return colour;
    case 3:
      return image;
    case 4:
      cv::cvtColor(image, colour, cv::COLOR_BGRA2BGR);
      return colour;
    default:
      throw std::invalid_argument("image '" + path + "' has " + std::to_string(image.channels()) +
                                  " channels; expected grey or colour");
  }
}

cv::Mat load_colour_image_on_white(const std::string& path) {
  const cv::Mat image = require_8_bit(load_as_stored(path, cv::IMREAD_UNCHANGED), path);
  if (image.channels() != 4) return load_colour_image(path);
  cv::Mat colour(image.size(), CV_8UC3);
  for (int y = 0; y < image.rows; ++y) {
    for (int x = 0; x < image.cols; ++x) {
      const auto& pixel = image.at<cv::Vec4b>(y, x);
      colour.at<cv::Vec3b>(y, x) =
          pixel[3] < 128 ? cv::Vec3b(255, 255, 255) : cv::Vec3b(pixel[0], pixel[1], pixel[2]);
    }
  }
  return colour;
}

cv::Mat load_grey_image(const std::string& path) {
  const cv::Mat image = require_8_bit(load_as_stored(path, cv::IMREAD_ANYCOLOR), path);
  cv::Mat grey;
  switch (image.channels()) {
    case 1:
      return image;
    case 3:
      cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
      return grey;
    case 4:
      cv::cvtColor(image, grey, cv::COLOR_BGRA2GRAY);
      return grey;
    default:
      throw std::invalid_argument("image '" + path + "' has " + std::to_string(image.channels()) +
                                  " channels; expected grey or colour");
  }
}

cv::Mat load_single_channel_image(const std::string& path) {
  cv::Mat image = load_as_stored(path, cv::IMREAD_UNCHANGED);
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

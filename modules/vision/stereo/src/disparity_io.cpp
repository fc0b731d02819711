#include "c2f/vision/stereo/disparity_io.hpp"

#include <algorithm>
#include <bit>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <string_view>

#include "c2f/support/input_file.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/vision/image_io.hpp"
#include "c2f/vision/partition_image.hpp"

namespace c2f::vision {

namespace {
void require_float(const cv::Mat& disparity, const char* who) {
  if (disparity.type() != CV_32F || disparity.empty()) {
    throw std::invalid_argument(std::string(who) +
                                ": the disparity map must be a non-empty CV_32F image");
  }
}
}  // namespace

cv::Mat labels_to_disparity(std::span<const Label> labeling, GridShape shape) {
  if (labeling.size() != shape.size()) {
    throw std::invalid_argument("labels_to_disparity: " + std::to_string(labeling.size()) +
                                " labels for a " + std::to_string(shape.width) + "x" +
                                std::to_string(shape.height) + " grid");
  }
  cv::Mat disparity(static_cast<int>(shape.height), static_cast<int>(shape.width), CV_32F);
  for (int y = 0; y < disparity.rows; ++y) {
    const Label* row = labeling.data() + static_cast<std::size_t>(y) * shape.width;
    std::transform(row, row + shape.width, disparity.ptr<float>(y),
                   [](Label label) { return static_cast<float>(label); });
  }
  return disparity;
}

void write_pfm(const std::string& path, const cv::Mat& disparity) {
  require_float(disparity, "write_pfm");
  std::ofstream out(path, std::ios::binary);
  if (!out) throw std::runtime_error("cannot open '" + path + "' for writing");
  out << "Pf\n" << disparity.cols << ' ' << disparity.rows << "\n-1\n";
  static_assert(std::endian::native == std::endian::little,
                "PFM writer assumes a little-endian machine");
  for (int y = disparity.rows - 1; y >= 0; --y) {
    for (int x = 0; x < disparity.cols; ++x) {
      float value = disparity.at<float>(y, x);
      if (std::isnan(value)) value = std::numeric_limits<float>::infinity();
      out.write(reinterpret_cast<const char*>(&value), sizeof value);
    }
  }
  out.close();
  if (!out) {
    std::filesystem::remove(path);
    throw std::runtime_error("writing '" + path + "' failed");
  }
}

namespace {

/// The next whitespace-separated header token of a PFM file at `at`, which moves past it.
std::string_view pfm_token(std::string_view bytes, std::size_t& at) {
  while (at < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[at]))) ++at;
  const std::size_t start = at;
  while (at < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[at])) &&
         at - start < 64)
    ++at;
  return bytes.substr(start, at - start);
}

}  // namespace

cv::Mat parse_pfm(std::string_view bytes, const std::string& source) {
  const auto malformed = [&](const std::string& what) {
    return std::runtime_error("'" + source + "' is not a single-channel PFM file: " + what);
  };
  std::size_t at = 0;
  if (pfm_token(bytes, at) != "Pf") throw malformed("expected the header 'Pf'");
  const std::string_view width_text = pfm_token(bytes, at), height_text = pfm_token(bytes, at),
                         scale_text = pfm_token(bytes, at);
  const std::optional<long long> width = parse_integer(width_text),
                                 height = parse_integer(height_text);
  const std::optional<double> scale = parse_real(scale_text);
  constexpr long long kMaxSide = 1 << 16;
  if (!width || !height || *width < 1 || *height < 1 || *width > kMaxSide || *height > kMaxSide)
    throw malformed("expected a width and a height in [1, 65536], got '" + std::string(width_text) +
                    "' and '" + std::string(height_text) + "'");
  if (!scale || *scale == 0.0)
    throw malformed("expected a finite non-zero scale, got '" + std::string(scale_text) + "'");
  // Exactly one whitespace byte ends the header; the rest is width x height floats.
  if (at >= bytes.size() || !std::isspace(static_cast<unsigned char>(bytes[at])))
    throw malformed("no data after the header");
  ++at;
  const auto expected = static_cast<std::size_t>(*width * *height * 4);
  const std::size_t given = bytes.size() - at;
  if (given != expected) {
    throw std::runtime_error("'" + source + "' holds " + std::to_string(given) +
                             " bytes of data after its header, expected " +
                             std::to_string(expected) + " (" + std::to_string(*width) + "x" +
                             std::to_string(*height) + " floats)");
  }
  const bool swap = *scale > 0.0;  // positive scale: big-endian data
  cv::Mat disparity(static_cast<int>(*height), static_cast<int>(*width), CV_32F);
  for (int y = disparity.rows - 1; y >= 0; --y) {
    for (int x = 0; x < disparity.cols; ++x, at += 4) {
      unsigned char four[4];
      std::memcpy(four, bytes.data() + at, 4);
      if (swap) std::swap(four[0], four[3]), std::swap(four[1], four[2]);
      float value;
      std::memcpy(&value, four, 4);
      disparity.at<float>(y, x) =
          std::isinf(value) ? std::numeric_limits<float>::quiet_NaN() : value;
    }
  }
  return disparity;
}

cv::Mat read_pfm(const std::string& path) {
  // The largest PFM an image may be: 2^30 pixels of 3 floats, and its header.
  constexpr std::size_t kMaxPfmBytes = (std::size_t{12} << 30) + 4096;
  std::string bytes;
  try {
    // The file's bytes and the map they decode to, of the same size.
    bytes = read_input_file(path, "PFM file", std::min(kMaxPfmBytes, input_memory_limit() / 2));
  } catch (const std::invalid_argument& error) {
    throw std::runtime_error(error.what());  // read_pfm's contract: runtime_error
  }
  return parse_pfm(bytes, path);
}

void write_disparity_png16(const std::string& path, const cv::Mat& disparity) {
  require_float(disparity, "write_disparity_png16");
  cv::Mat scaled(disparity.size(), CV_16U);
  for (int y = 0; y < disparity.rows; ++y) {
    for (int x = 0; x < disparity.cols; ++x) {
      const float d = disparity.at<float>(y, x);
      scaled.at<std::uint16_t>(y, x) =
          std::isnan(d) || d <= 0.0F
              ? 0
              : static_cast<std::uint16_t>(std::min(65535.0, std::round(256.0 * d)));
    }
  }
  write_image(path, scaled);
}

cv::Mat read_disparity_png16(const std::string& path) {
  if (const std::string why = why_not_a_file(path); !why.empty())
    throw std::runtime_error("disparity PNG '" + path + "' " + why);
  const cv::Mat raw = cv::imread(path, cv::IMREAD_UNCHANGED);
  if (raw.empty() || raw.type() != CV_16U)
    throw std::runtime_error("'" + path + "' is not a 16-bit single-channel PNG");
  cv::Mat disparity(raw.size(), CV_32F);
  for (int y = 0; y < raw.rows; ++y) {
    for (int x = 0; x < raw.cols; ++x) {
      const std::uint16_t v = raw.at<std::uint16_t>(y, x);
      disparity.at<float>(y, x) =
          v == 0 ? std::numeric_limits<float>::quiet_NaN() : static_cast<float>(v / 256.0);
    }
  }
  return disparity;
}

cv::Mat colourise_disparity(const cv::Mat& disparity, double max_disparity) {
  require_float(disparity, "colourise_disparity");
  if (!(max_disparity > 0.0))
    throw std::invalid_argument("colourise_disparity: max_disparity must be > 0");
  cv::Mat grey(disparity.size(), CV_8U), colour;
  for (int y = 0; y < disparity.rows; ++y) {
    for (int x = 0; x < disparity.cols; ++x) {
      const float d = disparity.at<float>(y, x);
      grey.at<uchar>(y, x) =
          std::isnan(d) ? 0 : cv::saturate_cast<uchar>(255.0 * d / max_disparity);
    }
  }
  cv::applyColorMap(grey, colour, cv::COLORMAP_JET);
  for (int y = 0; y < disparity.rows; ++y) {
    for (int x = 0; x < disparity.cols; ++x) {
      if (std::isnan(disparity.at<float>(y, x))) colour.at<cv::Vec3b>(y, x) = {0, 0, 0};
    }
  }
  return colour;
}

cv::Mat error_map(const cv::Mat& disparity, const cv::Mat& gt, const cv::Mat& nonoccluded,
                  double threshold) {
  require_float(disparity, "error_map");
  if (gt.type() != CV_32F || gt.size() != disparity.size()) {
    throw std::invalid_argument("error_map: the GT must be CV_32F of the disparity's size");
  }
  cv::Mat map(disparity.size(), CV_8UC3, cv::Scalar(0, 0, 0));
  for (int y = 0; y < gt.rows; ++y) {
    for (int x = 0; x < gt.cols; ++x) {
      const float truth = gt.at<float>(y, x);
      if (std::isnan(truth)) continue;
      const bool occluded = !nonoccluded.empty() && nonoccluded.at<uchar>(y, x) != 255;
      if (std::abs(disparity.at<float>(y, x) - truth) > threshold) {
        map.at<cv::Vec3b>(y, x) = occluded ? cv::Vec3b(0, 0, 140) : cv::Vec3b(0, 0, 255);
      } else {
        map.at<cv::Vec3b>(y, x) = occluded ? cv::Vec3b(90, 90, 90) : cv::Vec3b(190, 190, 190);
      }
    }
  }
  return map;
}

std::optional<BadPixelRates> write_disparity_outputs(const std::string& dir,
                                                     std::span<const Label> labeling,
                                                     const StereoScene& scene, int num_labels) {
  const std::filesystem::path out(dir);
  const cv::Mat disparity = labels_to_disparity(labeling, scene.shape());
  write_pfm((out / "disparity.pfm").string(), disparity);
  write_disparity_png16((out / "disparity.png").string(), disparity);
  write_image((out / "disparity-colour.png").string(),
              colourise_disparity(disparity, num_labels - 1));
  if (scene.gt.empty()) return std::nullopt;
  write_image((out / "error.png").string(), error_map(disparity, scene.gt, scene.nonoccluded));
  return bad_pixel_rates(disparity, scene.gt, scene.nonoccluded);
}

}  // namespace c2f::vision

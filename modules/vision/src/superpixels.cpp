#include "c2f/vision/superpixels.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>

#include "slic_clustering.hpp"

namespace c2f::vision {

cv::Mat lab_of_bgr(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.type() != CV_8UC3)
    throw std::invalid_argument("lab_of_bgr: the image must be non-empty 8-bit 3-channel");
  static const std::array<float, 256> linear = [] {
    std::array<float, 256> table{};
    for (int v = 0; v < 256; ++v) {
      const double c = v / 255.0;
      table[static_cast<std::size_t>(v)] =
          static_cast<float>(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return table;
  }();
  constexpr float kEpsilon = 0.008856F;  // (6/29)^3
  const auto f = [](float t) { return t > kEpsilon ? std::cbrt(t) : 7.787F * t + 16.0F / 116.0F; };
  const auto to_byte = [](float value) { return cv::saturate_cast<std::uint8_t>(value); };
  cv::Mat lab(bgr.size(), CV_8UC3);
  for (int y = 0; y < bgr.rows; ++y) {
    const cv::Vec3b* in = bgr.ptr<cv::Vec3b>(y);
    cv::Vec3b* out = lab.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; ++x) {
      const float b = linear[in[x][0]], g = linear[in[x][1]], r = linear[in[x][2]];
      const float fx = f((0.412453F * r + 0.357580F * g + 0.180423F * b) / 0.950456F);
      const float yy = 0.212671F * r + 0.715160F * g + 0.072169F * b;
      const float fy = f(yy);
      const float fz = f((0.019334F * r + 0.119193F * g + 0.950227F * b) / 1.088754F);
      const float lightness = yy > kEpsilon ? 116.0F * fy - 16.0F : 903.3F * yy;
      out[x] = {to_byte(lightness * 255.0F / 100.0F), to_byte(500.0F * (fx - fy) + 128.0F),
                to_byte(200.0F * (fy - fz) + 128.0F)};
    }
  }
  return lab;
}

namespace {

void require_colour_image(const cv::Mat& image) {
  if (image.empty() || image.type() != CV_8UC3) {
    throw std::invalid_argument("slic_partition: the image must be non-empty 8-bit 3-channel");
  }
}

/// slic_partition of the image whose CIE Lab (lab_of_bgr) is `lab`.
DensePartition slic_partition_of_lab(const cv::Mat& lab, int region_size,
                                     const SlicOptions& options, int threads) {
  if (region_size < 2) throw std::invalid_argument("slic_partition: region size must be >= 2");
  // A region larger than the image's shorter side leaves at most a strip of superpixels: a
  // mistake in the schedule, refused by name.
  if (region_size > std::min(lab.cols, lab.rows)) {
    throw std::invalid_argument("slic_partition: region size " + std::to_string(region_size) +
                                " is larger than the " + std::to_string(lab.cols) + "x" +
                                std::to_string(lab.rows) + " image's shorter side");
  }
  if (options.iterations < 1) {
    throw std::invalid_argument("slic_partition: iterations must be >= 1, got " +
                                std::to_string(options.iterations));
  }
  if (options.min_element_percent < 0 || options.min_element_percent > 100) {
    throw std::invalid_argument("slic_partition: min_element_percent must be in [0, 100], got " +
                                std::to_string(options.min_element_percent));
  }
  if (options.algorithm == SlicAlgorithm::slic &&
      !(std::isfinite(options.ruler) && options.ruler > 0.0F)) {
    throw std::invalid_argument("slic_partition: SLIC's ruler must be finite and > 0, got " +
                                std::to_string(options.ruler));
  }
  return DensePartition::from_ids(detail::slic_labels(lab, region_size, options, threads));
}

}  // namespace

DensePartition slic_partition(const cv::Mat& image, int region_size, const SlicOptions& options,
                              int threads) {
  require_colour_image(image);
  return slic_partition_of_lab(lab_of_bgr(image), region_size, options, threads);
}

std::vector<DensePartition> slic_hierarchy(const cv::Mat& image,
                                           const std::vector<int>& region_sizes,
                                           const SlicOptions& options, int threads) {
  if (region_sizes.empty()) throw std::invalid_argument("slic_hierarchy: no region sizes");
  for (std::size_t i = 1; i < region_sizes.size(); ++i) {
    if (region_sizes[i] >= region_sizes[i - 1]) {
      throw std::invalid_argument(
          "slic_hierarchy: region sizes must decrease (coarsest first), got " +
          std::to_string(region_sizes[i - 1]) + " then " + std::to_string(region_sizes[i]));
    }
  }
  require_colour_image(image);
  const cv::Mat lab = lab_of_bgr(image);
  std::vector<DensePartition> levels;
  for (const int size : region_sizes) {
    DensePartition superpixels = slic_partition_of_lab(lab, size, options, threads);
    if (levels.empty()) {
      levels.push_back(std::move(superpixels));
      continue;
    }
    levels.push_back(intersect(levels.back(), superpixels));
  }
  return levels;
}

namespace {

/// What a slic_source keeps between its calls.
struct SlicCache {
  cv::Mat image;
  SlicOptions options;
  cv::Mat lab;  ///< converted on the first call (on the run's clock) and kept

  DensePartition superpixels(int region_size, int threads) {
    if (lab.empty()) {
      require_colour_image(image);
      lab = lab_of_bgr(image);
    }
    return slic_partition_of_lab(lab, region_size, options, threads);
  }
};

}  // namespace

SuperpixelSource slic_source(const cv::Mat& image, SlicOptions options) {
  auto cache = std::make_shared<SlicCache>();
  cache->image = image.clone();
  cache->options = options;
  return [cache = std::move(cache)](int region_size, int threads) {
    return cache->superpixels(region_size, threads);
  };
}

}  // namespace c2f::vision

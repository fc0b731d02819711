#include "c2f/vision/superpixels.hpp"
#include "c2f/support/enum_names.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <exception>
#include <map>
#include <memory>
#include <opencv2/core/utility.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/slic.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>

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
                                     const SlicOptions& options) {
  if (region_size < 2) throw std::invalid_argument("slic_partition: region size must be >= 2");
  // OpenCV's SLIC reads out of bounds for regions much larger than the image; a region larger
  // than the image's shorter side is refused.
  if (region_size > std::min(lab.cols, lab.rows)) {
    throw std::invalid_argument("slic_partition: region size " + std::to_string(region_size) +
                                " is larger than the " + std::to_string(lab.cols) + "x" +
                                std::to_string(lab.rows) + " image's shorter side");
  }
  const int algorithm =
      options.algorithm == SlicAlgorithm::slic ? cv::ximgproc::SLIC : cv::ximgproc::SLICO;
  auto slic = cv::ximgproc::createSuperpixelSLIC(lab, algorithm, region_size, options.ruler);
  slic->iterate(options.iterations);
  slic->enforceLabelConnectivity(options.min_element_percent);
  cv::Mat labels;
  slic->getLabels(labels);
  std::vector<std::int64_t> ids(static_cast<std::size_t>(labels.rows) * labels.cols);
  for (int y = 0; y < labels.rows; ++y) {
    const int* row = labels.ptr<int>(y);
    for (int x = 0; x < labels.cols; ++x)
      ids[static_cast<std::size_t>(y) * labels.cols + x] = row[x];
  }
  return DensePartition::from_ids(ids);
}

}  // namespace

DensePartition slic_partition(const cv::Mat& image, int region_size, const SlicOptions& options) {
  require_colour_image(image);
  return slic_partition_of_lab(lab_of_bgr(image), region_size, options);
}

std::vector<DensePartition> slic_hierarchy(const cv::Mat& image,
                                           const std::vector<int>& region_sizes,
                                           const SlicOptions& options) {
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
    DensePartition superpixels = slic_partition_of_lab(lab, size, options);
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
  std::vector<int> together;  ///< sizes computed at once on the first call for one of them
  bool together_done = false;
  cv::Mat lab;  ///< converted on the first call (on the run's clock) and kept
  std::map<int, DensePartition> ready;
  std::map<int, std::exception_ptr> failed;

  DensePartition superpixels(int region_size) {
    if (lab.empty()) {
      require_colour_image(image);
      lab = lab_of_bgr(image);
    }
    if (!together_done && std::ranges::find(together, region_size) != together.end()) {
      together_done = true;
      compute_together();
    }
    if (const auto error = failed.find(region_size); error != failed.end()) {
      const std::exception_ptr thrown = error->second;
      failed.erase(error);
      std::rethrow_exception(thrown);
    }
    if (const auto done = ready.find(region_size); done != ready.end()) {
      DensePartition partition = std::move(done->second);
      ready.erase(done);
      return partition;
    }
    return slic_partition_of_lab(lab, region_size, options);
  }

  /// One size per task of OpenCV's own parallel loop: OpenCV runs a parallel loop nested in
  /// another serially, so each size's SLIC runs on the thread of its task.
  void compute_together() {
    const auto count = static_cast<int>(together.size());
    std::vector<std::optional<DensePartition>> results(together.size());
    std::vector<std::exception_ptr> errors(together.size());
    cv::parallel_for_(
        cv::Range(0, count),
        [&](const cv::Range& range) {
          for (int i = range.start; i < range.end; ++i) {
            const auto k = static_cast<std::size_t>(i);
            try {
              results[k] = slic_partition_of_lab(lab, together[k], options);
            } catch (...) {
              errors[k] = std::current_exception();
            }
          }
        },
        count);
    for (std::size_t k = 0; k < together.size(); ++k) {
      if (errors[k]) {
        failed.emplace(together[k], errors[k]);
      } else {
        ready.emplace(together[k], std::move(*results[k]));
      }
    }
  }
};

SuperpixelSource source_of(std::shared_ptr<SlicCache> cache) {
  return [cache = std::move(cache)](int region_size) { return cache->superpixels(region_size); };
}

}  // namespace

SuperpixelSource slic_source(const cv::Mat& image, SlicOptions options) {
  auto cache = std::make_shared<SlicCache>();
  cache->image = image.clone();
  cache->options = options;
  return source_of(std::move(cache));
}

SuperpixelSource slic_source(const cv::Mat& image, SlicOptions options, const Schedule& schedule) {
  auto cache = std::make_shared<SlicCache>();
  cache->image = image.clone();
  cache->options = options;
  for (const LevelSpec& level : schedule.levels) {
    if (const auto* slic = std::get_if<SlicLevel>(&level.partition);
        slic != nullptr &&
        std::ranges::find(cache->together, slic->region_size) == cache->together.end())
      cache->together.push_back(slic->region_size);
  }
  if (cache->together.size() < 2) cache->together.clear();  // nothing to compute at once
  return source_of(std::move(cache));
}

}  // namespace c2f::vision

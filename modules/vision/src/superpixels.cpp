#include "c2f/vision/superpixels.hpp"
#include "c2f/support/enum_names.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <opencv2/ximgproc/slic.hpp>
#include <stdexcept>
#include <string>

namespace c2f::vision {

DensePartition slic_partition(const cv::Mat& image, int region_size, const SlicOptions& options) {
  if (image.empty() || image.type() != CV_8UC3) {
    throw std::invalid_argument("slic_partition: the image must be non-empty 8-bit 3-channel");
  }
  if (region_size < 2) throw std::invalid_argument("slic_partition: region size must be >= 2");
  // OpenCV's SLIC reads out of bounds for regions much larger than the image; a region larger
  // than the image's shorter side is refused.
  if (region_size > std::min(image.cols, image.rows)) {
    throw std::invalid_argument("slic_partition: region size " + std::to_string(region_size) +
                                " is larger than the " + std::to_string(image.cols) + "x" +
                                std::to_string(image.rows) + " image's shorter side");
  }
  cv::Mat lab;
  cv::cvtColor(image, lab, cv::COLOR_BGR2Lab);
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
  std::vector<DensePartition> levels;
  for (const int size : region_sizes) {
    DensePartition superpixels = slic_partition(image, size, options);
    if (levels.empty()) {
      levels.push_back(std::move(superpixels));
      continue;
    }
    levels.push_back(intersect(levels.back(), superpixels));
  }
  return levels;
}

SuperpixelSource slic_source(const cv::Mat& image, SlicOptions options) {
  return [image = image.clone(), options](int region_size) {
    return slic_partition(image, region_size, options);
  };
}

}  // namespace c2f::vision

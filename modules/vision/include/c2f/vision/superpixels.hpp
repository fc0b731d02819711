#pragma once
// SLIC / SLICO superpixels as partitions (our own clustering, on several threads).

#include <opencv2/core.hpp>
#include <string_view>
#include <vector>

#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/schedule_provider.hpp"

namespace c2f::vision {

enum class SlicAlgorithm { slic, slico };

struct SlicOptions {
  SlicAlgorithm algorithm = SlicAlgorithm::slico;
  float ruler = 10.0F;  ///< compactness (SLIC only; SLICO adapts it)
  int iterations = 10;  ///< clustering rounds (>= 1)
  int min_element_percent =
      25;  ///< enforce connectivity: merge segments smaller than this % of the region
};

/// CIE L*a*b* (D65) of an 8-bit sRGB image in BGR order, in 8-bit channels scaled as OpenCV's
/// COLOR_BGR2Lab scales them (L * 255 / 100, a + 128, b + 128). OpenCV interpolates a table
/// that it builds on its first call in a process (about 0.1 s here), which a coarse-to-fine run
/// would pay on its clock; this computes each pixel directly, within 1 of OpenCV's but for dark
/// colours, where OpenCV's a* and b* are up to 2 off.
/// Throws std::invalid_argument for an empty or non-8-bit-3-channel image.
cv::Mat lab_of_bgr(const cv::Mat& bgr);

/// Superpixels of an 8-bit colour image with the given region size (pixels per side), as a
/// partition of its pixels (v = y * width + x): SLIC or SLICO clustering of its Lab colours
/// (lab_of_bgr) and positions, each superpixel 4-connected (the algorithm:
/// src/slic_clustering.hpp). On min(resolved_threads(threads), rows) threads, with the same
/// result for every count. Throws std::invalid_argument for an empty or non-8-bit-3-channel
/// image, region_size < 2, a region larger than the image's shorter side, iterations < 1,
/// min_element_percent outside [0, 100], or (SLIC) a ruler that is not finite and positive.
DensePartition slic_partition(const cv::Mat& image, int region_size,
                              const SlicOptions& options = {}, int threads = 0);

/// Superpixels for each region size (coarsest first), nested explicitly: every level's group is
/// (previous level's group, own superpixel), so each level refines the one before it. Throws
/// std::invalid_argument when the sizes are empty or do not decrease.
std::vector<DensePartition> slic_hierarchy(const cv::Mat& image,
                                           const std::vector<int>& region_sizes,
                                           const SlicOptions& options = {}, int threads = 0);

/// A SuperpixelSource for ScheduleProvider (slic:S levels) on this image: slic_partition of
/// each size a level asks for, on the threads it names. The image is copied, and converted to
/// Lab once, on the first call (on the run's clock).
SuperpixelSource slic_source(const cv::Mat& image, SlicOptions options = {});

}  // namespace c2f::vision

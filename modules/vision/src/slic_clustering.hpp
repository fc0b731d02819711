#pragma once
// SLIC and SLICO superpixels (Achanta et al., "SLIC superpixels compared to state-of-the-art
// superpixel methods", TPAMI 2012) of a CIE Lab image, on several threads with the same result
// for every thread count. Internal to the vision module: superpixels.hpp is the interface.

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "c2f/vision/superpixels.hpp"

namespace c2f::vision::detail {

/// One superpixel id per pixel (v = y * width + x), ids 0..count-1, every superpixel
/// 4-connected, of an 8-bit 3-channel Lab image (lab_of_bgr).
///
/// The clustering: centres start on a grid of region_size steps (round(width / S) by
/// round(height / S) of them, at the cells' centres), each moved to the lowest colour gradient
/// in its 3x3 neighbourhood. Each iteration gives every pixel the centre of least distance
/// among those within region_size of it in x and y (ties: the lower centre index),
///   D = dc^2 / m_k^2 + ds^2 / S^2,
/// dc the Lab distance, ds the image distance, m_k = options.ruler for SLIC and, for SLICO, the
/// largest dc of centre k's pixels in the iteration before (at least 10); then moves each centre
/// to its pixels' mean. Connectivity: 4-connected pieces of one superpixel are numbered in scan
/// order, and a piece smaller than options.min_element_percent % of S^2 joins the piece numbered
/// before it that touches its first pixel.
///
/// Rows are split among min(resolved_threads(threads), rows) threads; each pixel's distances
/// are computed in the same order on any count, so the result depends on none of them. The
/// caller checks the image, the region size and the options (superpixels.cpp).
std::vector<std::int32_t> slic_labels(const cv::Mat& lab, int region_size,
                                      const SlicOptions& options, int threads);

}  // namespace c2f::vision::detail

#pragma once
// The simplest stereo data term: truncated absolute colour difference, a baseline cost volume
// for benchmarks and tests (the TSGO cost lives beside it).

#include <opencv2/core.hpp>
#include <vector>

namespace c2f::vision {

/// unaries[(y * width + x) * num_labels + d] = min(mean over channels of
/// |left(x, y) - right(x - d, y)|, truncation) for x - d >= 0, and `truncation` where the
/// match leaves the right image. Left pixel (x, y) with disparity d matches right (x - d, y).
/// Throws std::invalid_argument when the images differ in size or are not 8-bit 3-channel, or
/// when num_labels < 1 or truncation <= 0.
std::vector<double> absolute_difference_cost(const cv::Mat& left, const cv::Mat& right,
                                             int num_labels, double truncation);

}  // namespace c2f::vision

#pragma once
// A synthetic stereo pair with known disparity: random colour texture, a background plane at
// one disparity and a foreground rectangle at a larger one (so part of the background is
// occluded in the right view).

#include <filesystem>
#include <opencv2/core.hpp>

namespace c2f::test {

struct SyntheticPair {
  cv::Mat left, right;  ///< 8-bit BGR
  cv::Mat gt;           ///< CV_32F left-view disparity
  cv::Mat nonoccluded;  ///< CV_8U, 255 where the left pixel is visible in the right view
};

SyntheticPair synthetic_pair(int width, int height, int background_disparity,
                             int foreground_disparity, unsigned seed);

/// synthetic_pair written into `dir` (created) as left.png, right.png and gt.png (8-bit, 4 x
/// the disparity: --gt-divisor 4); returns the pair.
SyntheticPair write_synthetic_pair(const std::filesystem::path& dir, int width, int height,
                                   int background_disparity, int foreground_disparity,
                                   unsigned seed);

}  // namespace c2f::test

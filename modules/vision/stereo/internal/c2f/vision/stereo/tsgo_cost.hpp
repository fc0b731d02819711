#pragma once
// TSGO step 1 (Mozerov and van de Weijer, "Accurate stereo matching by two-step energy
// minimization", TIP 2015), as the authors' released stereo code computes it, constants
// included. Each stage is a function of its own:
//
//   equalise_photometry -> gradient_scale + gradient_planes -> gradient_matching_cost
//   -> robust_transform -> fill_left_border -> cross_bilateral_filter (tsgo_bilateral.hpp)
//
// Images are 8-bit BGR (OpenCV's order, the same planar B, G, R order the reference uses).
// Internal to the stereo library (not installed): the public entry point is tsgo_cost.

#include <array>
#include <opencv2/core.hpp>

#include "c2f/vision/stereo/cost_volume.hpp"

namespace c2f::vision {

struct EqualisedPair {
  cv::Mat left, right;
  bool applied = false;  ///< true when the images were remapped
};

/// Per channel, the means m1, m2 and standard deviations s1, s2 of the two images are
/// compared; if for any channel |m1 - m2| * 2 / (m1 + m2) or |s1 - s2| * 2 / (s1 + s2)
/// exceeds `tolerance` (0.16), both images are remapped channel by channel to the average mean
/// and standard deviation: v' = (v - m_i) / s_i * s + m, clamped to [0, 255] and truncated.
/// Otherwise they are returned unchanged. Throws std::invalid_argument for images that are
/// not 8-bit 3-channel of one size.
EqualisedPair equalise_photometry(const cv::Mat& left, const cv::Mat& right,
                                  double tolerance = 0.16);

/// x (index 2c) and y (index 2c + 1) gradients of channel c (B, G, R) after the signed square
/// root, before scaling: gx = 4 (dx + (dx1 + dy1) / sqrt2), gy = 4 (dy + (dy1 - dx1) / sqrt2)
/// with dx = I(x+1,y) - I(x-1,y), dy = I(x,y+1) - I(x,y-1), dx1 = (I(x+1,y-1) - I(x-1,y+1)) /
/// sqrt2, dy1 = (I(x+1,y+1) - I(x-1,y-1)) / sqrt2 and coordinates clamped at the borders.
/// Six CV_64F planes. Rows are computed on `threads` threads (0: the machine's cores); every
/// value is the same for any count, as in the stages below.
std::array<cv::Mat, 6> signed_sqrt_gradients(const cv::Mat& image, int threads = 1);

/// mul = sigma_colour / sigma_gradient of an image: sigma_colour = sqrt(mean over pixels of the
/// summed squared deviations of the 3 channels from their means), sigma_gradient = sqrt(mean
/// over pixels of the summed squares of the 6 signed-square-rooted gradient planes). (The
/// reference reads the gradient planes that mul then scales; we take them after the signed
/// square root.) Returns 1 for an image without gradients. The gradients are computed on
/// `threads` threads (as signed_sqrt_gradients); the sums are OpenCV's, in one thread.
double gradient_scale(const cv::Mat& image, int threads = 1);
/// As above with the image's signed_sqrt_gradients given (computed once for scale and planes).
double gradient_scale(const cv::Mat& image, const std::array<cv::Mat, 6>& gradients);

/// The six gradient byte planes: clamp(mul * signed_sqrt_gradient + 128, 0, 255), truncated.
/// Rows are computed on `threads` threads; every value is the same for any count.
std::array<cv::Mat, 6> gradient_planes(const cv::Mat& image, double mul, int threads = 1);
/// As above from the image's signed_sqrt_gradients.
std::array<cv::Mat, 6> gradient_planes(const std::array<cv::Mat, 6>& gradients, double mul,
                                       int threads = 1);

/// C0(x, y, d) = min(sum over the 6 planes of |left(x, y) - right(x - d, y)|, truncation) for
/// valid (x, d); invalid cells are set to NaN (fill_left_border replaces them). Rows are
/// computed on `threads` threads (0: the machine's cores); each cell is the same for any count.
CostVolume gradient_matching_cost(const std::array<cv::Mat, 6>& left,
                                  const std::array<cv::Mat, 6>& right, int labels,
                                  double truncation = 360.0, int threads = 1);

/// The Abramowitz-Stegun 7.1.26 approximation of erf (absolute error < 1.5e-7), as TSGO uses.
double erf_approximation(double x);

struct RobustTransformParameters {
  double mean_minimum;  ///< mm: mean over pixels of the per-pixel minimum over valid d
  double mean_excess;   ///< avmin: mean over valid cells of (cost - the pixel's minimum)
  double slope;         ///< t = threshold * (avmin - mm)^2, times 0.91 when t > 2.5
};

/// Replaces every valid cell by C1 = (1 + erf(t (C0 - mm) / mm)) / 2, in (0, 1), with the data-
/// driven parameters above (threshold 0.00095). Invalid (NaN) cells stay NaN. Throws
/// std::invalid_argument when mm is 0 (every pixel has a perfect match), where the transform is
/// undefined. The parameters' sums run per row, then over rows in order (exact for integer
/// costs); the cells are transformed on `threads` threads (0: the machine's cores), integer
/// costs by a table of the same expression. Each value is the same for any count.
RobustTransformParameters robust_transform(CostVolume& volume, double threshold = 0.00095,
                                           int threads = 1);

/// For d > x (the match leaves the right image) copies the cost of the first pixel of the row
/// where d is valid: cost(x, y, d) = cost(d, y, d); when d >= width, no pixel has d valid and
/// the last pixel's cost at its largest valid disparity is used: cost(width-1, y, width-1).
void fill_left_border(CostVolume& volume);

}  // namespace c2f::vision

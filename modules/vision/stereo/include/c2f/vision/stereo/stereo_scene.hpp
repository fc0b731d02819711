#pragma once
// A stereo problem as the tools load it: two views, and ground truth with a non-occluded mask
// when there is any; from a pair of files or a Middlebury scene (middlebury.hpp).

#include <opencv2/core.hpp>
#include <string>

#include "c2f/core/grid.hpp"

namespace c2f::vision {

/// How a dataset scores a disparity map, in its own convention. A pixel with known GT g is bad
/// when |d - g| > absolute and, when relative > 0, also |d - g| > relative * g.
struct ErrorMeasure {
  std::string name = "bad 1";  ///< what reports call it: "bad 1", "bad 2.0 (full size)", "D1"
  double absolute = 1.0;       ///< pixels at the scene's size
  double relative = 0.0;       ///< a fraction of the true disparity (KITTI: 0.05); 0 = none
  /// True when the threshold is defined at the dataset's own size, so that downscale() divides
  /// it too (Middlebury 2014, KITTI); false for "bad 1 at the size solved" (2001-2006).
  bool follows_downscale = false;

  [[nodiscard]] bool is_bad(double disparity, double truth) const noexcept;
  bool operator==(const ErrorMeasure&) const = default;
};

struct StereoScene {
  std::string name;
  cv::Mat left, right;  ///< 8-bit BGR
  cv::Mat gt;           ///< CV_32F left-view disparity, NaN = unknown; empty without GT
  cv::Mat nonoccluded;  ///< CV_8U mask, 255 = evaluate as non-occluded; empty when not available
  std::string nonoccluded_source;  ///< "official mask", "left-right check" or "none"
  ErrorMeasure measure;            ///< the dataset's error convention (default: bad 1)
  std::string gt_convention;       ///< how a GT given by hand was read (ground_truth.hpp); or empty
  int disparity_range = 0;         ///< the dataset's label count (calib.txt ndisp); 0: unknown

  /// The pixel grid of the views.
  [[nodiscard]] GridShape shape() const noexcept {
    return {static_cast<std::size_t>(left.cols), static_cast<std::size_t>(left.rows)};
  }
};

/// The files of a stereo pair given by hand. Empty paths are absent inputs.
struct StereoPairFiles {
  std::string left, right;  ///< the views (required)
  std::string gt;           ///< left-view GT: a PFM or a PNG, read by load_ground_truth
  double gt_divisor = 0.0;  ///< GT PNG value per disparity pixel; 0: by the file (ground_truth.hpp)
  std::string gt_right;     ///< right-view GT, for a left-right occlusion mask
  std::string mask;         ///< official non-occluded mask (255 = evaluate); wins over gt_right
};

/// The label count a run of `scene` uses without a count of its own: the scene's disparity
/// range when it has one (>= 2), else `fallback`.
[[nodiscard]] int label_count(const StereoScene& scene, int fallback) noexcept;

/// Loads a pair: the views (named by the file stem of `left`), the GT read by what it holds
/// (load_ground_truth: the measure its dataset scores by comes with it), the non-occluded mask
/// (official mask, else the left-right check when gt_right is given) and, when a Middlebury
/// 2014 calib.txt lies beside the left view, its ndisp as the disparity range. Throws
/// std::invalid_argument naming the input when sizes differ or a mask comes without GT, and
/// std::runtime_error naming the path for an unreadable file.
StereoScene load_stereo_pair(const StereoPairFiles& files);

/// The scene shrunk by an integer factor: views by area averaging, GT and mask by nearest
/// neighbour, GT disparities divided by the factor, the disparity range too (rounded up), and
/// the measure's threshold when it follows the downscale. Factor 1 returns the scene unchanged.
/// Throws std::invalid_argument for a factor < 1 or views that would be smaller than 2x2.
StereoScene downscale(StereoScene scene, int factor);

}  // namespace c2f::vision

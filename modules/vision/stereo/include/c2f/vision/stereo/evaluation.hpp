#pragma once
// Error rates of a disparity map against ground truth: the fixed bad 0.5/1/2 table, and the
// scene's own measure (Middlebury 2014's bad 2.0 at full size, KITTI's D1).

#include <array>
#include <functional>
#include <opencv2/core.hpp>
#include <span>
#include <string>

#include "c2f/core/labeling.hpp"
#include "c2f/vision/stereo/stereo_scene.hpp"

namespace c2f::vision {

struct BadPixelRates {
  static constexpr std::array<double, 3> thresholds{0.5, 1.0, 2.0};
  std::array<double, 3>
      nonoccluded{};            ///< fraction of evaluated non-occluded pixels with |d - gt| > t
  std::array<double, 3> all{};  ///< fraction of pixels with known GT with |d - gt| > t
  std::size_t nonoccluded_pixels =
      0;  ///< 0 when no mask was given (nonoccluded rates are then NaN)
  std::size_t known_pixels = 0;
  /// The reference implementation's number: pixels with known GT and |d - gt| > 1, divided by
  /// all pixels (unknown ones included), for comparison with its published errors.
  double reference_variant = 0.0;

  /// "bad1 nonocc 12.34%, all 15.67%" style summary.
  [[nodiscard]] std::string brief() const;
};

/// Compares `disparity` (CV_32F) with `gt` (CV_32F, NaN = unknown) over known-GT pixels, and
/// over `nonoccluded` (CV_8U, 255 = evaluate; may be empty). Throws std::invalid_argument on
/// type or size mismatch.
BadPixelRates bad_pixel_rates(const cv::Mat& disparity, const cv::Mat& gt,
                              const cv::Mat& nonoccluded);

/// The scene's measure (scene.measure) over its non-occluded and over all pixels with GT.
struct SceneErrors {
  double nonoccluded = 0.0;  ///< NaN without a mask
  double all = 0.0;
  std::size_t nonoccluded_pixels = 0, known_pixels = 0;

  /// "D1: all 4.56%" or "bad 2.0 (full size) (> 0.5 px here): nonocc 1.23%, all 4.56%".
  [[nodiscard]] std::string brief(const ErrorMeasure& measure) const;
};

/// Scores `disparity` (CV_32F) by the scene's measure. Throws std::invalid_argument when the
/// scene has no GT or the sizes differ.
SceneErrors scene_errors(const cv::Mat& disparity, const StereoScene& scene);

/// The dataset's own error line for a labeling of `scene` (labels = disparities): "D1 ...: all
/// 4.56%"; "" for a scene scored by the default bad 1 or without GT (BadPixelRates cover those).
std::string scene_error_line(std::span<const Label> labeling, const StereoScene& scene);

/// The error a trace records for a labeling of `scene` (labels = disparities): the rate of bad
/// pixels by the scene's measure (bad 1 unless the dataset has its own) over the non-occluded
/// pixels when the scene has a mask, else over all pixels with known GT. Serves TraceWriter's
/// error column and the benchmarks' deadlines. Throws std::invalid_argument when the scene has
/// no GT.
std::function<double(std::span<const Label>)> bad_pixel_error(const StereoScene& scene);

}  // namespace c2f::vision

#pragma once
// Ground-truth disparity files given by hand (c2f-stereo LEFT RIGHT --gt FILE,
// c2f.read_stereo_pair) are recognised by their content, never silently misread: Middlebury 2014's
// PFM, KITTI 2015's 16-bit PNG and the earlier Middlebury PNGs each get their own unknown-pixel
// convention and the dataset's own error measure.

#include <opencv2/core.hpp>
#include <string>

#include "c2f/vision/stereo/stereo_scene.hpp"

namespace c2f::vision {

struct GroundTruth {
  cv::Mat disparity;       ///< CV_32F; NaN where the GT is unknown
  ErrorMeasure measure;    ///< the dataset's measure (ErrorMeasure{}: bad 1 and its variants)
  std::string convention;  ///< how the file was read, for summaries
};

/// Reads the GT file `path` by what it holds:
/// - a PFM ("Pf" header; Middlebury 2014's disp0GT.pfm): infinity is unknown; scored by
///   bad 2.0 at full size, halved in a folder named trainingH/testH and quartered in
///   trainingQ/testQ (at another folder: bad 2.0 at the file's own size);
/// - a 16-bit PNG with `divisor` 0 (KITTI 2015's disp_occ_0): value / 256, 0 unknown, D1;
/// - any PNG with `divisor` > 0: value / divisor, 0 unknown, bad 1;
/// - an 8-bit PNG with `divisor` 0: the value itself, 0 unknown, bad 1.
/// Throws std::invalid_argument naming the file for an 8-bit PNG and a divisor above 255 (every
/// disparity would be below one pixel: KITTI's GT is 16-bit), for a PFM holding an implausible
/// disparity (require_plausible_disparities: its scale's sign, the byte order, is wrong), for a
/// GT with no known pixel, and for what is no readable GT.
GroundTruth load_ground_truth(const std::string& path, double divisor);

/// Throws std::invalid_argument naming `what` and the first such pixel when a known disparity
/// of `gt` (CV_32F, NaN unknown) is neither 0 nor in [1e-6, 65536]: no dataset has one, and a
/// PFM read in the wrong byte order gives such values (denormals or huge numbers).
void require_plausible_disparities(const cv::Mat& gt, const std::string& what);

}  // namespace c2f::vision

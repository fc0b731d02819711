#pragma once
// Disparity maps in and out: PFM (float, Middlebury convention), 16-bit PNG (value x 256),
// colourised pictures and error maps. Writers throw std::runtime_error naming the path; a file
// that cannot be completed is removed rather than left half written.

#include <opencv2/core.hpp>
#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "c2f/core/grid.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/vision/stereo/evaluation.hpp"
#include "c2f/vision/stereo/stereo_scene.hpp"

namespace c2f::vision {

/// Disparity = label, as CV_32F of the grid's shape. Throws std::invalid_argument on size mismatch.
cv::Mat labels_to_disparity(std::span<const Label> labeling, GridShape shape);

/// PFM as Middlebury writes it: "Pf", width height, scale -1 (little-endian), rows bottom to
/// top; unknown values (NaN) are written as +infinity. Input CV_32F.
void write_pfm(const std::string& path, const cv::Mat& disparity);
/// Reads a single-channel PFM ("Pf", either endianness); infinities become NaN. Throws
/// std::runtime_error naming the path for a missing or malformed file.
cv::Mat read_pfm(const std::string& path);
/// The PFM in `bytes` (a whole file): header "Pf", width and height in [1, 65536], a finite
/// non-zero scale, one whitespace byte, then exactly width x height floats (trailing data is
/// an error). Throws std::runtime_error naming `source` and what was expected.
cv::Mat parse_pfm(std::string_view bytes, const std::string& source);

/// 16-bit PNG with value round(256 * d), 0 for unknown (NaN) or negative values.
void write_disparity_png16(const std::string& path, const cv::Mat& disparity);
/// Reads a 16-bit disparity PNG back (value / 256; 0 becomes NaN).
cv::Mat read_disparity_png16(const std::string& path);

/// A colour picture of a disparity map (JET colour map over [0, max_disparity], unknown black).
cv::Mat colourise_disparity(const cv::Mat& disparity, double max_disparity);

/// Error map: black where GT is unknown, red where |d - gt| > threshold, grey elsewhere
/// (darker for occluded pixels when a non-occluded mask is given).
cv::Mat error_map(const cv::Mat& disparity, const cv::Mat& gt, const cv::Mat& nonoccluded,
                  double threshold = 1.0);

/// Writes the pictures of a result into the folder `dir`: disparity.pfm, disparity.png
/// (16-bit), disparity-colour.png (colours over [0, num_labels - 1]) and, when the scene has
/// GT, error.png. Returns the bad-pixel rates against the GT (nullopt without GT).
std::optional<BadPixelRates> write_disparity_outputs(const std::string& dir,
                                                     std::span<const Label> labeling,
                                                     const StereoScene& scene, int num_labels);

}  // namespace c2f::vision

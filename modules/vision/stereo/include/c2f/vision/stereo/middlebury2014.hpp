#pragma once
// Middlebury 2014 scenes (MiddEval3 layout, as in ../shared/data/middlebury2014): im0.png and
// im1.png (left and right views), calib.txt (ndisp: the disparity range), disp0GT.pfm (left-view
// GT, +inf unknown) and mask0nocc.png (255 non-occluded, 128 occluded, 0 no GT). Scored as the
// benchmark scores them: bad 2.0 in full-size pixels, over non-occluded and over all pixels.

#include <opencv2/core.hpp>
#include <string>
#include <string_view>

#include "c2f/vision/stereo/stereo_scene.hpp"

namespace c2f::vision {

/// MiddEval3's three resolutions: full (F), half (H) and quarter (Q) size.
enum class Middlebury2014Size { full = 1, half = 2, quarter = 4 };

/// The benchmark's measure at a resolution: bad 2.0 at full size, so 1.0 at half and 0.5 at
/// quarter size (it follows a further downscale).
ErrorMeasure middlebury2014_measure(Middlebury2014Size size);

/// ndisp from the text of a calib.txt (lines key=value; other keys are ignored). Throws
/// std::invalid_argument naming `source` and the line when ndisp is missing, repeated, or not
/// an integer in [1, 65536].
int parse_ndisp(std::string_view calibration, const std::string& source);

/// A mask0nocc.png: CV_8U, 255 where the pixel is non-occluded, else 0. Throws
/// std::invalid_argument naming the file for a grey value other than 0, 128 and 255 and for a
/// mask with no non-occluded pixel.
cv::Mat load_middlebury2014_mask(const std::string& path);

/// The scene in folder `dir`, named by the folder: views, disparity range (calib.txt), and
/// the GT and mask when the files are there (a mask needs the GT). Throws naming the file that
/// is missing, unreadable or of another size than the views.
StereoScene load_middlebury2014_scene(const std::string& dir,
                                      Middlebury2014Size size = Middlebury2014Size::quarter);

}  // namespace c2f::vision

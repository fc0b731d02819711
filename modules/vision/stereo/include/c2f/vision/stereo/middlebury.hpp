#pragma once
// Middlebury scenes as laid out in ../shared/data (see its README): left/right views, GT
// disparity PNGs with a per-year divisor (0 = unknown), official masks (2001/2003), right-view
// GT (2003/2005/2006) for a left-right occlusion check, and scenes.csv describing them.

#include <opencv2/core.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "c2f/vision/stereo/stereo_scene.hpp"

namespace c2f::vision {

/// One row of scenes.csv.
struct SceneRow {
  int year = 0;
  std::string scene;
  std::string dir;  ///< relative to the data root
  int width = 0, height = 0;
  double gt_divisor = 0.0;
  std::vector<std::string> files;
};

/// Reads scenes.csv (header year,scene,dir,width,height,scale,gt_divisor,...,files,...).
/// Throws std::invalid_argument naming the path and line for a missing file or malformed row.
std::vector<SceneRow> read_scene_table(const std::string& path);
/// The scene table in `text` (a whole file), strictly: every row has the header's field count,
/// year, width and height are integers (sides in [1, 65536]), gt_divisor a finite number > 0,
/// names are non-empty and unique. Throws std::invalid_argument naming `source`, the line and
/// the field.
std::vector<SceneRow> parse_scene_table(std::string_view text, const std::string& source);

/// A GT disparity PNG divided by `divisor`, as CV_32F; unknown pixels (stored 0) are NaN.
/// Palette PNGs decode to their grey levels. Throws std::invalid_argument for divisor <= 0 and
/// for a GT with no known pixel (nothing could be evaluated), std::runtime_error naming the
/// path for an unreadable file.
cv::Mat load_gt_disparity(const std::string& path, double divisor);

/// Non-occluded pixels by the left-right check: a left pixel with known GT d is occluded when
/// x - round(d) leaves the image, the right GT there is unknown, or |d - dR(x - round(d))| > 1.
/// CV_8U, 255 = non-occluded with known GT. Throws std::invalid_argument on size mismatch.
cv::Mat left_right_nonoccluded(const cv::Mat& gt_left, const cv::Mat& gt_right);

/// An official mask PNG (nonocc.png): 255 = evaluate, 0 = occluded. CV_8U with values 0 or 255.
/// Throws std::invalid_argument naming the file for any other grey value (a colour image, a
/// half-tone) and for a mask with no pixel to evaluate.
cv::Mat load_mask(const std::string& path);

/// Loads a scene row from the data root: views, GT (divisor from the row), and the
/// non-occluded mask: the official nonocc.png when present, else the left-right check when
/// disp_right.png is present. Throws naming the missing file.
StereoScene load_scene(const SceneRow& row, const std::string& data_root);

/// Where Debian's opencv-doc package puts its sample images.
inline constexpr const char* kOpencvDocData = "/usr/share/doc/opencv-doc/examples/data";
/// The name of the full-size Aloe pair opencv-doc ships (1282x1110, GT in pixels, no mask).
inline constexpr const char* kOpencvDocAloe = "opencv-doc/aloe";
/// Its label count (StereoScene::disparity_range): 256, the full-size Middlebury 2006 range (its
/// GT reaches about 230 px).
inline constexpr int kOpencvDocAloeLabels = 256;

/// The scene called `name` under DATA_ROOT: "middlebury2014/SCENE" (a quarter-size MiddEval3
/// folder, middlebury2014.hpp), "kitti2015/ID" (a KITTI 2015 training pair, kitti2015.hpp),
/// "opencv-doc/aloe" (kOpencvDocAloe, read from kOpencvDocData whatever DATA_ROOT is), else
/// load_scene for the row of DATA_ROOT/scenes.csv named `name`. Throws std::invalid_argument
/// naming the scene, the table and the names it has when there is no such row, and
/// std::runtime_error naming the path of a file that cannot be read.
StereoScene load_named_scene(const std::string& data_root, const std::string& name);

}  // namespace c2f::vision

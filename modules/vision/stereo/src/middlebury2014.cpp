#include "c2f/vision/stereo/middlebury2014.hpp"

#include <filesystem>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "c2f/support/input_file.hpp"
#include "c2f/support/number_text.hpp"
#include "c2f/support/text_input.hpp"
#include "c2f/vision/image_io.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"
#include "c2f/vision/stereo/ground_truth.hpp"
#include "stereo_pair_checks.hpp"

namespace c2f::vision {

ErrorMeasure middlebury2014_measure(Middlebury2014Size size) {
  const int factor = static_cast<int>(size);
  return {"bad 2.0 (full size)", 2.0 / factor, 0.0, true};
}

int parse_ndisp(std::string_view calibration, const std::string& source) {
  std::istringstream in{std::string(without_byte_order_mark(calibration))};
  std::string line;
  int ndisp = 0;
  for (int number = 1; std::getline(in, line); ++number) {
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (line.rfind("ndisp=", 0) != 0) continue;
    const std::string value = line.substr(6);
    const std::optional<long long> parsed = parse_integer(value);
    const auto where = "calibration '" + source + "' line " + std::to_string(number) + ": ";
    if (ndisp != 0) throw std::invalid_argument(where + "ndisp is given twice");
    if (!parsed || *parsed < 2 || *parsed > 65536) {
      throw std::invalid_argument(where +
                                  "ndisp: expected an integer in [2, 65536] (one label "
                                  "is no stereo), got '" +
                                  printable(value) + "'");
    }
    ndisp = static_cast<int>(*parsed);
  }
  if (ndisp == 0) throw std::invalid_argument("calibration '" + source + "' has no ndisp= line");
  return ndisp;
}

cv::Mat load_middlebury2014_mask(const std::string& path) {
  const cv::Mat mask = load_grey_image(path);
  std::size_t nonoccluded = 0;
  for (int y = 0; y < mask.rows; ++y) {
    for (int x = 0; x < mask.cols; ++x) {
      const int v = mask.at<uchar>(y, x);
      if (v != 0 && v != 128 && v != 255) {
        throw std::invalid_argument(
            "mask '" + path + "' has the grey value " + std::to_string(v) + " at (" +
            std::to_string(x) + ", " + std::to_string(y) +
            "): expected 255 (non-occluded), 128 (occluded) and 0 (no ground truth)");
      }
      nonoccluded += v == 255;
    }
  }
  if (nonoccluded == 0)
    throw std::invalid_argument("mask '" + path + "' has no non-occluded pixel (value 255)");
  return mask == 255;
}

StereoScene load_middlebury2014_scene(const std::string& dir, Middlebury2014Size size) {
  const std::filesystem::path folder(dir);
  const auto file = [&](const char* name) { return (folder / name).string(); };
  if (!std::filesystem::is_directory(folder))
    throw std::invalid_argument("Middlebury 2014 scene '" + dir + "' is not a folder");
  StereoScene scene;
  scene.name = folder.filename().empty() ? folder.parent_path().filename().string()
                                         : folder.filename().string();
  scene.left = load_colour_image(file("im0.png"));
  scene.right = load_colour_image(file("im1.png"));
  detail::require_view_size(scene.right, scene.left, file("im1.png"));
  scene.disparity_range = parse_ndisp(
      read_input_file(file("calib.txt"), "calibration", kMaxTextInputBytes), file("calib.txt"));
  scene.measure = middlebury2014_measure(size);
  scene.nonoccluded_source = "none";
  const bool has_gt = std::filesystem::exists(folder / "disp0GT.pfm");
  const bool has_mask = std::filesystem::exists(folder / "mask0nocc.png");
  if (has_mask && !has_gt)
    throw std::invalid_argument("'" + file("mask0nocc.png") +
                                "' needs the GT disp0GT.pfm beside it");
  if (!has_gt) return scene;
  try {
    scene.gt = read_pfm(file("disp0GT.pfm"));
  } catch (const std::runtime_error& error) {
    throw std::invalid_argument(error.what());
  }
  require_plausible_disparities(scene.gt, "GT '" + file("disp0GT.pfm") + "'");
  detail::require_view_size(scene.gt, scene.left, file("disp0GT.pfm"));
  detail::require_known_pixel(scene.gt, file("disp0GT.pfm"));
  if (has_mask) {
    scene.nonoccluded = load_middlebury2014_mask(file("mask0nocc.png"));
    detail::require_view_size(scene.nonoccluded, scene.left, file("mask0nocc.png"));
    scene.nonoccluded_source = "official mask";
  }
  return scene;
}

}  // namespace c2f::vision

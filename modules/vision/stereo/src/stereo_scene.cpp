#include "c2f/vision/stereo/stereo_scene.hpp"

#include <opencv2/imgproc.hpp>

#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <system_error>

#include "c2f/support/input_file.hpp"
#include "c2f/vision/image_io.hpp"
#include "c2f/vision/stereo/ground_truth.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "c2f/vision/stereo/middlebury2014.hpp"

namespace c2f::vision {

namespace {

std::string size_text(const cv::Mat& image) {
  return std::to_string(image.cols) + "x" + std::to_string(image.rows);
}

}  // namespace

bool ErrorMeasure::is_bad(double disparity, double truth) const noexcept {
  const double error = std::abs(disparity - truth);
  // Written as "not within" so that a NaN disparity counts as bad.
  return !(error <= absolute) && (relative <= 0.0 || !(error <= relative * truth));
}

int label_count(const StereoScene& scene, int fallback) noexcept {
  return scene.disparity_range >= 2 ? scene.disparity_range : fallback;
}

StereoScene load_stereo_pair(const StereoPairFiles& files) {
  if ((!files.gt_right.empty() || !files.mask.empty()) && files.gt.empty())
    throw std::invalid_argument("a right-view GT or a mask needs the left-view GT");
  StereoScene scene;
  scene.name = std::filesystem::path(files.left).stem().string();
  scene.left = load_colour_image(files.left);
  scene.right = load_colour_image(files.right);
  if (scene.left.size() != scene.right.size()) {
    throw std::invalid_argument("LEFT is " + size_text(scene.left) + ", RIGHT is " +
                                size_text(scene.right) + ": the views must have one size");
  }
  scene.nonoccluded_source = "none";
  // A Middlebury 2014 folder's calib.txt beside the left view gives the label count (read
  // through the input layer, which refuses one that is no regular file by name).
  const std::filesystem::path calibration =
      std::filesystem::path(files.left).parent_path() / "calib.txt";
  std::error_code absent;
  if (std::filesystem::exists(std::filesystem::symlink_status(calibration, absent))) {
    scene.disparity_range =
        parse_ndisp(read_input_file(calibration.string(), "calibration", kMaxTextInputBytes),
                    calibration.string());
  }
  if (files.gt.empty()) return scene;
  GroundTruth truth = load_ground_truth(files.gt, files.gt_divisor);
  scene.gt = std::move(truth.disparity);
  scene.measure = truth.measure;
  scene.gt_convention = std::move(truth.convention);
  if (scene.gt.size() != scene.left.size()) {
    throw std::invalid_argument("GT '" + files.gt + "' is " + size_text(scene.gt) +
                                ", the views are " + size_text(scene.left));
  }
  if (!files.mask.empty()) {
    scene.nonoccluded = load_mask(files.mask);
    scene.nonoccluded_source = "official mask";
  } else if (!files.gt_right.empty()) {
    scene.nonoccluded = left_right_nonoccluded(
        scene.gt, load_ground_truth(files.gt_right, files.gt_divisor).disparity);
    scene.nonoccluded_source = "left-right check";
  }
  if (!scene.nonoccluded.empty() && scene.nonoccluded.size() != scene.gt.size())
    throw std::invalid_argument("the non-occluded mask does not have the views' size");
  return scene;
}

StereoScene downscale(StereoScene scene, int factor) {
  if (factor < 1) throw std::invalid_argument("downscale: the factor must be >= 1");
  if (factor == 1) return scene;
  const cv::Size size(scene.left.cols / factor, scene.left.rows / factor);
  if (size.width < 2 || size.height < 2) {
    throw std::invalid_argument("downscale: " + size_text(scene.left) + " views shrunk by " +
                                std::to_string(factor) + " would be smaller than 2x2");
  }
  if (scene.disparity_range > 0 && (scene.disparity_range + factor - 1) / factor < 2) {
    throw std::invalid_argument("downscale: the scene's " + std::to_string(scene.disparity_range) +
                                " disparities shrunk by " + std::to_string(factor) +
                                " leave fewer than 2 labels; a factor below " +
                                std::to_string(scene.disparity_range) + " is needed");
  }
  cv::resize(scene.left, scene.left, size, 0, 0, cv::INTER_AREA);
  cv::resize(scene.right, scene.right, size, 0, 0, cv::INTER_AREA);
  if (!scene.gt.empty()) {
    cv::resize(scene.gt, scene.gt, size, 0, 0, cv::INTER_NEAREST);
    scene.gt /= factor;
  }
  if (!scene.nonoccluded.empty())
    cv::resize(scene.nonoccluded, scene.nonoccluded, size, 0, 0, cv::INTER_NEAREST);
  if (scene.measure.follows_downscale) scene.measure.absolute /= factor;
  scene.disparity_range = (scene.disparity_range + factor - 1) / factor;
  return scene;
}

}  // namespace c2f::vision

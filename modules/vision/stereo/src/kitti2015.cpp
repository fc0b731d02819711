#include "c2f/vision/stereo/kitti2015.hpp"

#include <filesystem>
#include <stdexcept>

#include "c2f/vision/image_io.hpp"
#include "c2f/vision/stereo/ground_truth.hpp"
#include "c2f/vision/stereo/middlebury.hpp"
#include "stereo_pair_checks.hpp"

namespace c2f::vision {

ErrorMeasure kitti_d1_measure() {
  return {"D1", 3.0, 0.05, true};
}

StereoScene load_kitti2015_pair(const std::string& root, const std::string& id) {
  if (id.empty() || id.find('/') != std::string::npos || id == "." || id == "..")
    throw std::invalid_argument("KITTI pair '" + id + "': expected a name such as 000000_10");
  const std::filesystem::path training = std::filesystem::path(root) / "training";
  const auto file = [&](const char* folder) {
    return (training / folder / (id + ".png")).string();
  };
  StereoScene scene;
  scene.name = "kitti2015/" + id;
  scene.left = load_colour_image(file("image_2"));
  scene.right = load_colour_image(file("image_3"));
  detail::require_view_size(scene.right, scene.left, file("image_3"));
  scene.measure = kitti_d1_measure();
  scene.disparity_range = kKittiDefaultLabels;
  scene.nonoccluded_source = "none (KITTI scores all pixels with GT)";
  if (std::filesystem::exists(file("disp_occ_0"))) {
    // Disparity x 256, 0 unknown (NaN); an 8-bit PNG is refused (no divisor above 255 on it).
    scene.gt = load_ground_truth(file("disp_occ_0"), 256.0).disparity;
    detail::require_view_size(scene.gt, scene.left, file("disp_occ_0"));
  }
  return scene;
}

}  // namespace c2f::vision

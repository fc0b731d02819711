#include "c2f/vision/segmentation/segmentation_io.hpp"

#include <filesystem>
#include <stdexcept>

#include "c2f/vision/image_io.hpp"
#include "c2f/vision/partition_image.hpp"

namespace c2f::vision {

cv::Mat label_image(std::span<const Label> labeling, const SegmentationScene& scene) {
  if (labeling.size() != scene.image.total())
    throw std::invalid_argument("label_image: the labeling does not cover the image");
  cv::Mat picture(scene.image.size(), CV_8UC3);
  for (std::size_t i = 0; i < labeling.size(); ++i)
    picture.at<cv::Vec3b>(static_cast<int>(i)) =
        scene.palette[static_cast<std::size_t>(labeling[i])];
  return picture;
}

Labeling read_label_image(const std::string& path, const SegmentationScene& scene) {
  const cv::Mat picture = load_colour_image(path);
  if (picture.size() != scene.image.size()) {
    throw std::invalid_argument("labeling '" + path + "' is " + std::to_string(picture.cols) + "x" +
                                std::to_string(picture.rows) + ", the image " +
                                std::to_string(scene.image.cols) + "x" +
                                std::to_string(scene.image.rows));
  }
  const std::vector<int> labels = labels_by_colour(picture, scene.palette, "labeling", path);
  return Labeling(labels.begin(), labels.end());
}

cv::Mat segmentation_overlay(std::span<const Label> labeling, const SegmentationScene& scene) {
  const cv::Mat colours = label_image(labeling, scene);
  cv::Mat picture;
  cv::addWeighted(scene.image, 0.5, colours, 0.5, 0.0, picture);
  const int w = scene.image.cols, h = scene.image.rows;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto i = static_cast<std::size_t>(y * w + x);
      const bool right = x + 1 < w && labeling[i] != labeling[i + 1];
      const bool down = y + 1 < h && labeling[i] != labeling[i + static_cast<std::size_t>(w)];
      if (right || down) picture.at<cv::Vec3b>(y, x) = cv::Vec3b(255, 255, 255);
    }
  }
  return picture;
}

double pixel_error(std::span<const Label> labeling, std::span<const int> truth) {
  if (labeling.size() != truth.size())
    throw std::invalid_argument("pixel_error: the labeling and the truth differ in size");
  std::size_t scored = 0, wrong = 0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (truth[i] == kNoLabel) continue;
    ++scored;
    wrong += labeling[i] != truth[i];
  }
  if (scored == 0) throw std::invalid_argument("pixel_error: the truth scores no pixel");
  return static_cast<double>(wrong) / static_cast<double>(scored);
}

std::function<double(std::span<const Label>)> pixel_error_function(const SegmentationScene& scene) {
  if (scene.truth.empty()) throw std::invalid_argument("pixel_error_function: the scene has no GT");
  return [&scene](std::span<const Label> labeling) { return pixel_error(labeling, scene.truth); };
}

std::optional<double> write_segmentation_outputs(const std::string& dir,
                                                 std::span<const Label> labeling,
                                                 const SegmentationScene& scene) {
  const std::filesystem::path out(dir);
  write_image((out / "labels.png").string(), label_image(labeling, scene));
  write_image((out / "overlay.png").string(), segmentation_overlay(labeling, scene));
  if (scene.truth.empty()) return std::nullopt;
  return pixel_error(labeling, scene.truth);
}

}  // namespace c2f::vision

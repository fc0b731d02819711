// Fuzz target: seed scribbles and GT labelings. The input gives a small image's width and
// height, a convention, and the pixels of the seeds (and GT); any of them is refused with
// std::invalid_argument or gives a scene whose seeds and truth are labels of its palette.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <stdexcept>

#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace {

/// The next `rows x cols` image of `type` from the input (zeros once it runs out).
cv::Mat take_image(const std::uint8_t*& data, std::size_t& size, int rows, int cols, int type) {
  cv::Mat image(rows, cols, type, cv::Scalar::all(0));
  const std::size_t bytes = image.total() * image.elemSize();
  const std::size_t taken = bytes < size ? bytes : size;
  std::copy(data, data + taken, image.data);
  data += taken;
  size -= taken;
  return image;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 3) return 0;
  const int cols = 1 + data[0] % 16, rows = 1 + data[1] % 16;
  c2f::vision::SegmentationFiles files{"image.png", "seeds.png", "", {}};
  files.convention = static_cast<c2f::vision::SeedConvention>(data[2] % 3);
  const bool with_gt =
      (data[2] / 3) % 2 == 1 || files.convention == c2f::vision::SeedConvention::labels_from_gt;
  data += 3;
  size -= 3;
  c2f::vision::SegmentationImages images;
  images.image = cv::Mat(rows, cols, CV_8UC3, cv::Scalar(90, 120, 150));
  images.seeds = take_image(data, size, rows, cols, CV_8UC3);
  if (with_gt) {
    files.gt = "gt.png";
    images.gt =
        take_image(data, size, rows, cols,
                   files.convention == c2f::vision::SeedConvention::binary ? CV_8UC1 : CV_8UC3);
  }
  try {
    const auto scene = c2f::vision::segmentation_scene_from_images(images, files);
    const int labels = scene.num_labels();
    for (const int seed : scene.seeds) {
      if (seed != c2f::vision::kNoLabel && (seed < 0 || seed >= labels))
        throw std::logic_error("a seed outside the palette");
    }
    for (const int truth : scene.truth) {
      if (truth != c2f::vision::kNoLabel && (truth < 0 || truth >= labels))
        throw std::logic_error("a GT label outside the palette");
    }
  } catch (const std::invalid_argument&) {
  }
  return 0;
}

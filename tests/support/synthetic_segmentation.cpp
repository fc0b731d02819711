#include "support/synthetic_segmentation.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <random>

namespace c2f::test {

SegmentationFilesOnDisk write_synthetic_segmentation(const std::filesystem::path& dir, int width,
                                                     int height, std::uint64_t seed,
                                                     double noise_deviation) {
  std::filesystem::create_directories(dir);
  SegmentationFilesOnDisk files;
  files.image = (dir / "image.png").string();
  files.seeds = (dir / "seeds.png").string();
  files.gt = (dir / "gt.png").string();
  // Ascending (R, G, B): (0, 0, 255) < (0, 255, 0) < (255, 0, 0); stored BGR.
  files.colours[0] = cv::Vec3b(255, 0, 0);
  files.colours[1] = cv::Vec3b(0, 255, 0);
  files.colours[2] = cv::Vec3b(0, 0, 255);
  const cv::Vec3b appearance[3] = {cv::Vec3b(40, 60, 200), cv::Vec3b(60, 190, 70),
                                   cv::Vec3b(200, 90, 50)};
  cv::Mat gt(height, width, CV_8UC3), image(height, width, CV_8UC3);
  cv::Mat seeds(height, width, CV_8UC3, cv::Scalar(255, 255, 255));
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, noise_deviation);
  const cv::Point centre(width * 2 / 3, height / 2);
  const int radius = std::min(width, height) / 4;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const int dx = x - centre.x, dy = y - centre.y;
      const int label = x < width / 3 ? 0 : dx * dx + dy * dy < radius * radius ? 1 : 2;
      gt.at<cv::Vec3b>(y, x) = files.colours[label];
      for (int c = 0; c < 3; ++c) {
        image.at<cv::Vec3b>(y, x)[c] =
            cv::saturate_cast<std::uint8_t>(appearance[label][c] + noise(rng));
      }
    }
  }
  cv::line(seeds, {width / 8, height / 4}, {width / 8, height * 3 / 4},
           cv::Scalar(files.colours[0]), 2);
  cv::line(seeds, {centre.x - radius / 2, centre.y}, {centre.x + radius / 2, centre.y},
           cv::Scalar(files.colours[1]), 2);
  cv::line(seeds, {width / 2, 1}, {width - 2, 1}, cv::Scalar(files.colours[2]), 2);
  cv::imwrite(files.image, image);
  cv::imwrite(files.seeds, seeds);
  cv::imwrite(files.gt, gt);
  return files;
}

}  // namespace c2f::test

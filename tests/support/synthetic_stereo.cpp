#include "synthetic_stereo.hpp"

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

namespace c2f::test {

SyntheticPair synthetic_pair(int width, int height, int background_disparity,
                             int foreground_disparity, unsigned seed) {
  cv::RNG rng(seed);
  // Texture wider than the views so shifted content exists for every pixel: the right view's
  // background reads column xr + background_disparity + foreground_disparity.
  cv::Mat texture(height, width + background_disparity + foreground_disparity, CV_8UC3);
  cv::Mat foreground(height, width + foreground_disparity, CV_8UC3);
  rng.fill(texture, cv::RNG::UNIFORM, 0, 256);
  rng.fill(foreground, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(texture, texture, {3, 3}, 0.7);
  cv::GaussianBlur(foreground, foreground, {3, 3}, 0.7);
  const cv::Rect object(width / 3, height / 4, width / 3, height / 2);  // in left-view coordinates
  SyntheticPair pair{cv::Mat(height, width, CV_8UC3), cv::Mat(height, width, CV_8UC3),
                     cv::Mat(height, width, CV_32F),
                     cv::Mat(height, width, CV_8U, cv::Scalar(255))};
  // Scene coordinates: a left pixel x with disparity d shows scene point x (texture column
  // x + foreground_disparity keeps indices positive); the right view shows it at x - d.
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const bool on_object = object.contains({x, y});
      pair.left.at<cv::Vec3b>(y, x) = on_object
                                          ? foreground.at<cv::Vec3b>(y, x)
                                          : texture.at<cv::Vec3b>(y, x + foreground_disparity);
      pair.gt.at<float>(y, x) =
          static_cast<float>(on_object ? foreground_disparity : background_disparity);
    }
    for (int xr = 0; xr < width; ++xr) {
      // The object occupies right columns [object.x - fd, object.x + object.width - fd).
      const int object_left = object.x - foreground_disparity;
      const bool on_object = y >= object.y && y < object.y + object.height && xr >= object_left &&
                             xr < object_left + object.width;
      pair.right.at<cv::Vec3b>(y, xr) =
          on_object ? foreground.at<cv::Vec3b>(y, xr + foreground_disparity)
                    : texture.at<cv::Vec3b>(y, xr + background_disparity + foreground_disparity);
    }
    for (int x = 0; x < width; ++x) {
      const int d = static_cast<int>(pair.gt.at<float>(y, x));
      const int xr = x - d;
      const int object_left = object.x - foreground_disparity;
      const bool covered = !object.contains({x, y}) && y >= object.y &&
                           y < object.y + object.height && xr >= object_left &&
                           xr < object_left + object.width;
      if (xr < 0 || covered) pair.nonoccluded.at<uchar>(y, x) = 0;
    }
  }
  return pair;
}

SyntheticPair write_synthetic_pair(const std::filesystem::path& dir, int width, int height,
                                   int background_disparity, int foreground_disparity,
                                   unsigned seed) {
  SyntheticPair pair =
      synthetic_pair(width, height, background_disparity, foreground_disparity, seed);
  std::filesystem::create_directories(dir);
  cv::imwrite((dir / "left.png").string(), pair.left);
  cv::imwrite((dir / "right.png").string(), pair.right);
  cv::Mat gt8;
  pair.gt.convertTo(gt8, CV_8U, 4.0);
  cv::imwrite((dir / "gt.png").string(), gt8);
  return pair;
}

}  // namespace c2f::test

#include <catch2/catch.hpp>

#include <opencv2/core.hpp>

#include "c2f/vision/image_io.hpp"
#include "c2f/vision/stereo/absolute_difference_cost.hpp"

using namespace c2f::vision;

TEST_CASE("absolute-difference costs match hand computation", "[vision][cost]") {
  // One row of 3 pixels; right is left shifted by one pixel to the left (disparity 1).
  cv::Mat left(1, 3, CV_8UC3), right(1, 3, CV_8UC3);
  left.at<cv::Vec3b>(0, 0) = {10, 10, 10};
  left.at<cv::Vec3b>(0, 1) = {40, 40, 40};
  left.at<cv::Vec3b>(0, 2) = {90, 60, 30};
  right.at<cv::Vec3b>(0, 0) = {40, 40, 40};
  right.at<cv::Vec3b>(0, 1) = {90, 60, 30};
  right.at<cv::Vec3b>(0, 2) = {0, 0, 0};
  const auto costs = absolute_difference_cost(left, right, 2, 25.0);
  REQUIRE(costs.size() == 6);
  CHECK(costs[0] == 25.0);  // pixel 0, d = 0: |10 - 40| = 30, truncated
  CHECK(costs[1] == 25.0);  // pixel 0, d = 1: leaves the image
  CHECK(costs[2] == 25.0);  // pixel 1, d = 0: (50 + 20 + 10) / 3 = 26.67, truncated
  CHECK(costs[3] == 0.0);   // pixel 1, d = 1: matches right pixel 0
  CHECK(costs[4] == 25.0);  // pixel 2, d = 0: (90 + 60 + 30) / 3 = 60, truncated
  CHECK(costs[5] == 0.0);   // pixel 2, d = 1: matches right pixel 1
}

TEST_CASE("cost volume and image loading reject bad input", "[vision][validation]") {
  const cv::Mat a(2, 3, CV_8UC3, cv::Scalar(0, 0, 0)), b(2, 4, CV_8UC3, cv::Scalar(0, 0, 0));
  CHECK_THROWS_WITH(absolute_difference_cost(a, b, 4, 10.0),
                    Catch::Contains("left is 3x2, right is 4x2"));
  CHECK_THROWS_WITH(absolute_difference_cost(a, a, 0, 10.0),
                    Catch::Contains("num_labels must be >= 1"));
  CHECK_THROWS_WITH(absolute_difference_cost(a, a, 4, 0.0),
                    Catch::Contains("truncation must be finite and > 0"));
  CHECK_THROWS_WITH(load_colour_image("/nonexistent/left.png"),
                    Catch::Contains("'/nonexistent/left.png' does not exist"));
  CHECK_THROWS_WITH(load_grey_image("/etc/hostname"),
                    Catch::Contains("could not be read as an image"));
}

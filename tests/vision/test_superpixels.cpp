#include <catch2/catch.hpp>

#include <opencv2/imgproc.hpp>

#include "c2f/lift/connected_components.hpp"
#include "c2f/lift/schedule_provider.hpp"
#include "c2f/vision/partition_image.hpp"
#include "c2f/vision/superpixels.hpp"
#include "support/random_models.hpp"

using namespace c2f;
using namespace c2f::vision;

namespace {
cv::Mat quadrants() {
  cv::Mat image(48, 64, CV_8UC3, cv::Scalar(30, 30, 200));
  cv::rectangle(image, {32, 0, 32, 24}, cv::Scalar(200, 40, 40), cv::FILLED);
  cv::rectangle(image, {0, 24, 32, 24}, cv::Scalar(40, 200, 40), cv::FILLED);
  cv::rectangle(image, {32, 24, 32, 24}, cv::Scalar(220, 220, 220), cv::FILLED);
  return image;
}
}  // namespace

TEST_CASE("lab_of_bgr is OpenCV's 8-bit Lab within rounding", "[vision][slic]") {
  // Every 8-bit colour on a 4-step lattice of the cube, and the cube's corners. OpenCV's 8-bit
  // path interpolates a table: in dark colours its a* and b* are up to 2 off (BGR (0, 4, 0):
  // a* = -1.6 exactly, so 126.4 scaled; OpenCV gives 128, this 126).
  cv::Mat colours(1, 64 * 64 * 64 + 8, CV_8UC3);
  int k = 0;
  for (int b = 0; b < 256; b += 4)
    for (int g = 0; g < 256; g += 4)
      for (int r = 0; r < 256; r += 4) colours.at<cv::Vec3b>(0, k++) = cv::Vec3b(b, g, r);
  for (int corner = 0; corner < 8; ++corner) {
    colours.at<cv::Vec3b>(0, k++) =
        cv::Vec3b(corner & 1 ? 255 : 0, corner & 2 ? 255 : 0, corner & 4 ? 255 : 0);
  }
  cv::Mat reference;
  cv::cvtColor(colours, reference, cv::COLOR_BGR2Lab);
  const cv::Mat ours = lab_of_bgr(colours);
  cv::Mat difference;
  cv::absdiff(ours, reference, difference);
  double largest = 0.0;
  cv::minMaxLoc(difference.reshape(1), nullptr, &largest);
  CHECK(largest <= 2.0);
  const cv::Mat off_by_two = difference.reshape(1) >= 2;
  CHECK(static_cast<std::size_t>(cv::countNonZero(off_by_two)) <= difference.total() * 3 / 1000);
  CHECK_THROWS_AS(lab_of_bgr(cv::Mat(4, 4, CV_8UC1)), std::invalid_argument);
}

TEST_CASE("SLIC superpixels follow colour edges and nest in a schedule", "[vision][slic]") {
  const cv::Mat image = quadrants();
  const DensePartition superpixels = slic_partition(image, 8);
  CHECK(superpixels.num_variables() == 48 * 64);
  CHECK(superpixels.num_groups() > 4);
  CHECK(superpixels == slic_partition(image, 8));  // deterministic
  // No superpixel straddles two flat quadrants.
  for (std::size_t g = 0; g < superpixels.num_groups(); ++g) {
    const auto members = superpixels.members(g);
    const auto quadrant = [](VariableIndex v) { return (v % 64 >= 32) + 2 * (v / 64 >= 24); };
    for (const VariableIndex v : members) CHECK(quadrant(v) == quadrant(members[0]));
  }
  c2f::test::Rng rng(1);
  const PairwiseEnergy energy = c2f::test::random_grid_energy(rng, 64, 48, 3);
  ScheduleProvider provider(Schedule::parse("slic:24 slic:12 slic:6"), {64, 48},
                            slic_source(image));
  auto a = provider.next(energy), b = provider.next(energy), c = provider.next(energy);
  REQUIRE((a && b && c));
  CHECK(b->is_refinement_of(*a));
  CHECK(c->is_refinement_of(*b));
  CHECK(a->num_groups() < c->num_groups());
  const auto hierarchy = slic_hierarchy(image, {24, 12, 6});
  REQUIRE(hierarchy.size() == 3);
  CHECK(hierarchy[1].is_refinement_of(hierarchy[0]));
  CHECK(hierarchy[2].is_refinement_of(hierarchy[1]));
  CHECK_THROWS_WITH(slic_hierarchy(image, {12, 24}), Catch::Contains("region sizes must decrease"));
  CHECK_THROWS_WITH(slic_partition(image, 1), Catch::Contains("region size must be >= 2"));
  CHECK_THROWS_WITH(slic_partition(cv::Mat(), 8), Catch::Contains("non-empty 8-bit 3-channel"));
  SlicOptions bad;
  bad.iterations = 0;
  CHECK_THROWS_WITH(slic_partition(image, 8, bad), Catch::Contains("iterations must be >= 1"));
  bad = {};
  bad.min_element_percent = 101;
  CHECK_THROWS_WITH(slic_partition(image, 8, bad), Catch::Contains("min_element_percent"));
  bad = {};
  bad.algorithm = SlicAlgorithm::slic;
  bad.ruler = 0.0F;
  CHECK_THROWS_WITH(slic_partition(image, 8, bad), Catch::Contains("ruler must be finite"));
  // Regions larger than the image are refused by name.
  CHECK_THROWS_WITH(
      slic_partition(image, 49),
      Catch::Contains("region size 49 is larger than the 64x48 image's shorter side"));
  CHECK(slic_partition(image, 48).num_variables() == 64 * 48);
}

TEST_CASE("SLIC superpixels are the same on every thread count, and connected", "[vision][slic]") {
  cv::Mat image = quadrants();
  cv::RNG noise(3);
  cv::Mat speckle(image.size(), CV_8UC3);
  noise.fill(speckle, cv::RNG::UNIFORM, 0, 40);
  image += speckle;
  for (const SlicAlgorithm algorithm : {SlicAlgorithm::slico, SlicAlgorithm::slic}) {
    SlicOptions options;
    options.algorithm = algorithm;
    for (const int size : {16, 8, 4}) {
      const DensePartition one = slic_partition(image, size, options, 1);
      CHECK(slic_partition(image, size, options, 2) == one);
      CHECK(slic_partition(image, size, options, 3) == one);
      // Every superpixel is one 4-connected piece: splitting them into pieces adds none.
      CHECK(connected_components(one, {64, 48}).num_groups() == one.num_groups());
      // SLICO: about (64 / size) x (48 / size) of them, pieces below a quarter of size^2
      // merged. (SLIC's fixed compactness lets the speckle split clusters into pieces, which
      // merge into fewer superpixels.)
      if (algorithm == SlicAlgorithm::slico) {
        CHECK(one.num_groups() >= static_cast<std::size_t>((64 / size) * (48 / size)) / 2);
      }
    }
  }
  // A source builds what slic_partition builds, on the threads its level names.
  const SuperpixelSource source = slic_source(image);
  CHECK(source(8, 2) == slic_partition(image, 8));
  CHECK(source(12, 1) == slic_partition(image, 12));
  CHECK_THROWS_WITH(source(49, 1), Catch::Contains("region size 49 is larger than the 64x48"));
  CHECK_THROWS_WITH(slic_source(cv::Mat(4, 4, CV_8UC1))(16, 1),
                    Catch::Contains("non-empty 8-bit 3-channel"));
}

TEST_CASE("partition pictures colour the largest groups and group means", "[vision][render]") {
  // Groups: 0 has 3 pixels, 1 has 2, 2 has 1 (a 3x2 grid).
  const DensePartition partition({0, 0, 1, 0, 1, 2}, 3);
  const cv::Mat largest = render_largest_groups(partition, {3, 2}, 2);
  REQUIRE(largest.size() == cv::Size(3, 2));
  const cv::Vec3b first = largest.at<cv::Vec3b>(0, 0), second = largest.at<cv::Vec3b>(0, 2);
  CHECK(first != cv::Vec3b(0, 0, 0));
  CHECK(second != cv::Vec3b(0, 0, 0));
  CHECK(first != second);
  CHECK(largest.at<cv::Vec3b>(1, 0) == first);
  CHECK(largest.at<cv::Vec3b>(1, 2) == cv::Vec3b(0, 0, 0));  // group 2 is not among the 2 largest

  cv::Mat image(2, 3, CV_8UC3, cv::Scalar(0, 0, 0));
  image.at<cv::Vec3b>(0, 0) = {30, 0, 0};
  image.at<cv::Vec3b>(0, 1) = {60, 0, 0};
  image.at<cv::Vec3b>(1, 0) = {90, 0, 0};
  const cv::Mat means = render_group_means(partition, image);
  CHECK(means.at<cv::Vec3b>(0, 1) == cv::Vec3b(60, 0, 0));  // (30 + 60 + 90) / 3
  CHECK_THROWS_WITH(render_group_means(partition, cv::Mat(3, 3, CV_8UC3)),
                    Catch::Contains("the image has 9"));
  CHECK_THROWS_WITH(write_image("/nonexistent-dir/p.png", means),
                    Catch::Contains("/nonexistent-dir/p.png"));
}

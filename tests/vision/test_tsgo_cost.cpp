// TSGO step 1, stage by stage, on tiny images where the expected values follow by hand.

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numeric>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "c2f/vision/stereo/tsgo_bilateral.hpp"
#include "c2f/vision/stereo/tsgo_cost.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"

using namespace c2f;
using namespace c2f::vision;

TEST_CASE("photometric equalisation remaps both images to the average statistics",
          "[stereo][tsgo]") {
  // Left: values 90 and 110 in every channel (mean 100, std 10); right: 140 and 160 (mean 150).
  cv::Mat left(1, 2, CV_8UC3), right(1, 2, CV_8UC3);
  left.at<cv::Vec3b>(0, 0) = {90, 90, 90};
  left.at<cv::Vec3b>(0, 1) = {110, 110, 110};
  right.at<cv::Vec3b>(0, 0) = {140, 140, 140};
  right.at<cv::Vec3b>(0, 1) = {160, 160, 160};
  const EqualisedPair pair = equalise_photometry(left, right);
  CHECK(pair.applied);  // |100 - 150| * 2 / 250 = 0.4 > 0.16
  // Both map to mean 125, std 10: 115 and 135.
  CHECK(pair.left.at<cv::Vec3b>(0, 0) == cv::Vec3b(115, 115, 115));
  CHECK(pair.left.at<cv::Vec3b>(0, 1) == cv::Vec3b(135, 135, 135));
  CHECK(pair.right.at<cv::Vec3b>(0, 0) == cv::Vec3b(115, 115, 115));
  CHECK(pair.right.at<cv::Vec3b>(0, 1) == cv::Vec3b(135, 135, 135));
  // Within tolerance: unchanged.
  const EqualisedPair same = equalise_photometry(left, left);
  CHECK_FALSE(same.applied);
  CHECK(cv::norm(same.left, left, cv::NORM_L1) == 0.0);
  CHECK_THROWS_WITH(equalise_photometry(left, cv::Mat(1, 3, CV_8UC3)),
                    Catch::Contains("left is 2x1, right is 3x1"));
}

TEST_CASE("gradient features of a ramp follow the formula", "[stereo][tsgo]") {
  // Horizontal ramp I(x) = x in every channel: dx = 2, dy = 0, dx1 = dy1 = 2 / sqrt2, so
  // gx = 4 (2 + 2) = 16 (signed sqrt 4) and gy = 0 in the interior.
  cv::Mat ramp(3, 5, CV_8UC3);
  for (int x = 0; x < 5; ++x) {
    for (int y = 0; y < 3; ++y) ramp.at<cv::Vec3b>(y, x) = cv::Vec3b(x, x, x);
  }
  const auto gradients = signed_sqrt_gradients(ramp);
  CHECK(gradients[0].at<double>(1, 2) == Approx(4.0));
  CHECK(gradients[1].at<double>(1, 2) == Approx(0.0).margin(1e-12));
  CHECK(gradients[4].at<double>(1, 2) == Approx(4.0));  // channel R, x gradient
  // Clamped borders: at x = 0, dx = I(1) - I(0) = 1, dx1 = dy1 = 1 / sqrt2: gx = 4 (1 + 1) = 8.
  CHECK(gradients[0].at<double>(1, 0) == Approx(std::sqrt(8.0)));
  const auto planes = gradient_planes(ramp, 2.0);
  CHECK(planes[0].at<uchar>(1, 2) == 136);  // 2 * 4 + 128
  CHECK(planes[1].at<uchar>(1, 2) == 128);
  const cv::Mat flat(4, 4, CV_8UC3, cv::Scalar(50, 60, 70));
  CHECK(gradient_scale(flat) == 1.0);  // no gradients: neutral scale
  for (const cv::Mat& plane : gradient_planes(flat, 3.0))
    CHECK(cv::countNonZero(plane != 128) == 0);
}

TEST_CASE("the matching cost sums six plane differences and truncates", "[stereo][tsgo]") {
  std::array<cv::Mat, 6> left, right;
  for (std::size_t p = 0; p < 6; ++p) {
    left[p] = cv::Mat(1, 3, CV_8U, cv::Scalar(100));
    right[p] = cv::Mat(1, 3, CV_8U, cv::Scalar(100));
  }
  left[0].at<uchar>(0, 2) = 130;  // pixel 2 differs by 30 in plane 0 from right pixels 0..2
  right[3].at<uchar>(0, 1) = 40;  // right pixel 1 differs by 60 in plane 3
  const CostVolume volume = gradient_matching_cost(left, right, 3, 80.0);
  CHECK(volume.at(2, 0, 0) == 30.0);  // right pixel 2
  CHECK(volume.at(2, 0, 1) == 80.0);  // right pixel 1: 30 + 60 = 90, truncated to 80
  CHECK(volume.at(2, 0, 2) == 30.0);  // right pixel 0
  CHECK(volume.at(1, 0, 0) == 60.0);
  CHECK(std::isnan(volume.at(0, 0, 1)));  // leaves the right image
}

TEST_CASE("the matching cost is the definition at every cell, on any thread count",
          "[stereo][tsgo][threads]") {
  // Random planes (fixed seed), more labels than columns at the left border and a truncation
  // that some sums exceed: every valid cell is min(sum of |left - right|, truncation), every
  // invalid one (d > x) NaN, for 1 and 3 threads.
  cv::RNG rng(17);
  std::array<cv::Mat, 6> left, right;
  for (std::size_t p = 0; p < 6; ++p) {
    left[p] = cv::Mat(5, 23, CV_8U);
    right[p] = cv::Mat(5, 23, CV_8U);
    rng.fill(left[p], cv::RNG::UNIFORM, 0, 256);
    rng.fill(right[p], cv::RNG::UNIFORM, 0, 256);
  }
  const int labels = 9;
  const double truncation = 400.0;
  for (const int threads : {1, 3}) {
    const CostVolume volume = gradient_matching_cost(left, right, labels, truncation, threads);
    int truncated = 0;
    for (int y = 0; y < 5; ++y) {
      for (int x = 0; x < 23; ++x) {
        for (int d = 0; d < labels; ++d) {
          const float cost = volume.at(static_cast<std::size_t>(x), static_cast<std::size_t>(y), d);
          if (d > x) {
            CHECK(std::isnan(cost));
            continue;
          }
          int sum = 0;
          for (std::size_t p = 0; p < 6; ++p)
            sum += std::abs(left[p].at<uchar>(y, x) - right[p].at<uchar>(y, x - d));
          truncated += sum > truncation;
          CHECK(cost == static_cast<float>(std::min<double>(sum, truncation)));
        }
      }
    }
    CHECK(truncated > 0);
  }
}

TEST_CASE("the erf approximation is within its published error", "[stereo][tsgo]") {
  for (double x = -4.0; x <= 4.0; x += 0.01)
    CHECK(std::abs(erf_approximation(x) - std::erf(x)) < 1.5e-7);
}

TEST_CASE("the robust transform uses the documented data-driven slope", "[stereo][tsgo]") {
  // One row, 3 pixels, 2 labels; valid cells: (0,0)=20, (1,0)=10, (1,1)=50, (2,0)=70, (2,1)=30.
  CostVolume volume(3, 1, 2, std::nan(""));
  volume.at(0, 0, 0) = 20;
  volume.at(1, 0, 0) = 10;
  volume.at(1, 0, 1) = 50;
  volume.at(2, 0, 0) = 70;
  volume.at(2, 0, 1) = 30;
  const RobustTransformParameters p = robust_transform(volume, 0.001);
  const double mm = (20 + 10 + 30) / 3.0;                // 20
  const double avmin = (0 + 0 + 40 + 40 + 0) / 5.0;      // 16
  const double t = 0.001 * (avmin - mm) * (avmin - mm);  // 0.016 (< 2.5: not scaled)
  CHECK(p.mean_minimum == Approx(mm));
  CHECK(p.mean_excess == Approx(avmin));
  CHECK(p.slope == Approx(t));
  CHECK(volume.at(1, 0, 1) == Approx((1 + erf_approximation(t * (50 - mm) / mm)) / 2));
  CHECK(volume.at(0, 0, 0) == Approx(0.5));  // cost == mm
  CHECK(std::isnan(volume.at(0, 0, 1)));
  CostVolume perfect(2, 1, 1, 0.0);
  CHECK_THROWS_WITH(robust_transform(perfect),
                    Catch::Contains("every pixel matches some disparity perfectly"));
}

TEST_CASE("the left border takes the first valid pixel's cost", "[stereo][tsgo]") {
  CostVolume volume(3, 1, 4, std::nan(""));
  for (std::size_t x = 0; x < 3; ++x) {
    for (int d = 0; d <= static_cast<int>(x); ++d) volume.at(x, 0, d) = 10.0 * x + d;
  }
  fill_left_border(volume);
  CHECK(volume.at(0, 0, 1) == volume.at(1, 0, 1));  // 11
  CHECK(volume.at(0, 0, 2) == volume.at(2, 0, 2));  // 22
  CHECK(volume.at(1, 0, 2) == 22.0);
  CHECK(volume.at(0, 0, 3) == 22.0);  // d = 3 is valid nowhere: last pixel, largest valid d
  for (double value : volume.data()) CHECK_FALSE(std::isnan(value));
}

TEST_CASE("median cut splits by G, R, B and divides ties in raster order", "[stereo][tsgo]") {
  // Four pixels; level 0 splits on G, level 1 on R.
  cv::Mat image(1, 4, CV_8UC3);
  image.at<cv::Vec3b>(0, 0) = {0, 10, 200};
  image.at<cv::Vec3b>(0, 1) = {0, 10, 100};
  image.at<cv::Vec3b>(0, 2) = {0, 50, 0};
  image.at<cv::Vec3b>(0, 3) = {0, 50, 30};
  const ColourClusters clusters = median_cut_clusters(image, 2);
  REQUIRE(clusters.means.size() == 4);
  // G splits {0, 1} from {2, 3}; R then orders each half.
  CHECK(clusters.cluster_of == std::vector<int>{1, 0, 2, 3});
  CHECK(clusters.means[1] == cv::Vec3d(0, 10, 200));
  // All pixels equal: halves in raster order.
  const cv::Mat grey(1, 4, CV_8UC3, cv::Scalar(7, 7, 7));
  CHECK(median_cut_clusters(grey, 1).cluster_of == std::vector<int>{0, 0, 1, 1});
}

TEST_CASE("median cut gives the clusters of a plain comparison sort on any thread count",
          "[stereo][tsgo][threads]") {
  // A noisy image with few distinct values, so that many ties are divided in raster order.
  cv::Mat image(37, 53, CV_8UC3);
  cv::RNG rng(27);
  rng.fill(image, cv::RNG::UNIFORM, 0, 6);
  const int levels = 7;
  // The definition, directly: each level sorts each cluster by (channel value, pixel index).
  std::vector<int> order(image.total());
  std::iota(order.begin(), order.end(), 0);
  std::vector<std::size_t> bounds{0, order.size()};
  for (int level = 0; level < levels; ++level) {
    const int c = (level + 1) % 3;
    std::vector<std::size_t> next{0};
    for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
      std::sort(order.begin() + static_cast<std::ptrdiff_t>(bounds[k]),
                order.begin() + static_cast<std::ptrdiff_t>(bounds[k + 1]), [&](int a, int b) {
                  const int va = image.at<cv::Vec3b>(a / image.cols, a % image.cols)[c];
                  const int vb = image.at<cv::Vec3b>(b / image.cols, b % image.cols)[c];
                  return va < vb || (va == vb && a < b);
                });
      next.push_back(bounds[k] + (bounds[k + 1] - bounds[k]) / 2);
      next.push_back(bounds[k + 1]);
    }
    bounds = std::move(next);
  }
  std::vector<int> expected(order.size());
  for (std::size_t k = 0; k + 1 < bounds.size(); ++k) {
    for (std::size_t i = bounds[k]; i < bounds[k + 1]; ++i)
      expected[static_cast<std::size_t>(order[i])] = static_cast<int>(k);
  }
  for (const int threads : {1, 2, 3}) {
    INFO(threads << " threads");
    CHECK(median_cut_clusters(image, levels, threads).cluster_of == expected);
  }
}

TEST_CASE("the cross-bilateral filter keeps constants and does not mix distant colours",
          "[stereo][tsgo]") {
  // Left half black, right half white; cost 0.2 on black pixels, 0.8 on white ones.
  cv::Mat guide(20, 40, CV_8UC3, cv::Scalar(0, 0, 0));
  guide(cv::Rect(20, 0, 20, 20)).setTo(cv::Scalar(255, 255, 255));
  CostVolume volume(40, 20, 2, 0.0);
  for (std::size_t y = 0; y < 20; ++y) {
    for (std::size_t x = 0; x < 40; ++x) {
      volume.at(x, y, 0) = x < 20 ? 0.2 : 0.8;
      volume.at(x, y, 1) = 0.5;
    }
  }
  BilateralOptions options;
  options.cell = 6;
  options.cluster_levels = 4;
  cross_bilateral_filter(volume, guide, options);
  for (std::size_t y = 0; y < 20; ++y) {
    for (std::size_t x = 0; x < 40; ++x) {
      // Constant to a few float roundings.
      CHECK(volume.at(x, y, 0) == Approx(x < 20 ? 0.2 : 0.8).epsilon(1e-6));
      CHECK(volume.at(x, y, 1) == Approx(0.5).epsilon(1e-6));
    }
  }
  CHECK_THROWS_WITH(cross_bilateral_filter(volume, cv::Mat(5, 5, CV_8UC3), options),
                    Catch::Contains("(40x20)"));
}

TEST_CASE("the TSGO energy uses colour weight classes and the chosen smoothness",
          "[stereo][tsgo]") {
  cv::Mat left(1, 3, CV_8UC3, cv::Scalar(100, 100, 100));
  left.at<cv::Vec3b>(0, 1) = {104, 100, 100};  // D = 4 to pixel 0: class 0.3125
  left.at<cv::Vec3b>(0, 2) = {124, 100, 100};  // D = 20 to pixel 1: class 0.125
  TsgoCost cost{CostVolume(3, 1, 3, 0.5), left, false};
  TsgoOptions options;
  options.labels = 3;
  const PairwiseEnergy energy = tsgo_energy(cost, options);
  REQUIRE(energy.edges().size() == 2);
  CHECK(energy.edges()[0].weight == 0.3125);
  CHECK(energy.edges()[1].weight == 0.125);
  CHECK(energy.terms()[0].kind() == TermKind::tsgo_step);
  options.smoothness = StereoSmoothness::truncated_linear;
  const PairwiseEnergy linear =
      tsgo_energy(TsgoCost{CostVolume(3, 1, 3, 0.5), left, false}, options);
  CHECK(linear.terms()[0].kind() == TermKind::truncated_linear);
  options.labels = 1;
  CHECK_THAT(options.validate(), Catch::Contains("labels must be >= 2, got 1"));
}

TEST_CASE("TSGO step 1 gives the same volume, bit for bit, on any number of threads",
          "[stereo][tsgo][threads]") {
  // 37 labels: three label blocks of the bilateral filter, the last one short.
  cv::Mat left(40, 64, CV_8UC3), right(40, 64, CV_8UC3);
  cv::RNG random(11);
  random.fill(left, cv::RNG::UNIFORM, 0, 256);
  random.fill(right, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(left, left, cv::Size(5, 5), 1.5);
  cv::GaussianBlur(right, right, cv::Size(5, 5), 1.5);
  c2f::vision::TsgoOptions options;
  options.labels = 37;
  options.bilateral.cell = 6;
  options.threads = 1;
  const auto one = c2f::vision::tsgo_cost(left, right, options).volume.data();
  for (const int threads : {2, 3, 8, 0}) {
    options.threads = threads;
    const auto many = c2f::vision::tsgo_cost(left, right, options).volume.data();
    INFO(threads << " threads");
    REQUIRE(many.size() == one.size());
    CHECK(std::memcmp(many.data(), one.data(), one.size() * sizeof(float)) == 0);
  }
  // Cells of 18 pixels: 4 grid node rows, so 8 threads make a team of 4, one row each.
  options.bilateral.cell = 18;
  options.threads = 1;
  const auto coarse_one = c2f::vision::tsgo_cost(left, right, options).volume.data();
  options.threads = 8;
  const auto coarse_many = c2f::vision::tsgo_cost(left, right, options).volume.data();
  CHECK(std::memcmp(coarse_many.data(), coarse_one.data(), coarse_one.size() * sizeof(float)) == 0);
  options.threads = -1;
  CHECK_THROWS_WITH(c2f::vision::tsgo_cost(left, right, options),
                    Catch::Contains("threads must be >= 0"));
}

namespace {

/// The cross-bilateral filter as its contract states it, on a dense grid of every node and
/// cluster, with values and arithmetic in `Value`: in float, the oracle for the filter's sparse
/// storage (the same terms in the same order); in double, the filter without float rounding.
template <typename Value>
void dense_cross_bilateral_filter(c2f::vision::CostVolume& volume, const cv::Mat& guide,
                                  const c2f::vision::BilateralOptions& options) {
  const auto clusters = c2f::vision::median_cut_clusters(guide, options.cluster_levels);
  const std::size_t q = clusters.means.size(), w = volume.width(), h = volume.height();
  const auto cell = static_cast<std::size_t>(options.cell);
  const std::size_t gw = (w - 1) / cell + 2, gh = (h - 1) / cell + 2;
  const Value taps[5] = {Value(std::exp(-2.0)), Value(std::exp(-0.5)), Value(1.0),
                         Value(std::exp(-0.5)), Value(std::exp(-2.0))};
  const double cutoff = options.cutoff_sigmas * options.colour_sigma;
  const auto smooth = [&](const std::vector<Value>& slice) {
    std::vector<Value> grid(gw * gh * q, Value(0)), pass(gw * gh * q, Value(0));
    const auto at = [&](std::vector<Value>& g, std::size_t x, std::size_t y,
                        std::size_t c) -> Value& { return g[(y * gw + x) * q + c]; };
    for (std::size_t p = 0; p < w * h; ++p) {
      const double sx = static_cast<double>(p % w) / static_cast<double>(cell);
      const double sy = static_cast<double>(p / w) / static_cast<double>(cell);
      const auto gx = static_cast<std::size_t>(sx), gy = static_cast<std::size_t>(sy);
      const double fx = sx - static_cast<double>(gx), fy = sy - static_cast<double>(gy);
      const auto c = static_cast<std::size_t>(clusters.cluster_of[p]);
      at(grid, gx, gy, c) += Value((1 - fx) * (1 - fy)) * slice[p];
      at(grid, gx + 1, gy, c) += Value(fx * (1 - fy)) * slice[p];
      at(grid, gx, gy + 1, c) += Value((1 - fx) * fy) * slice[p];
      at(grid, gx + 1, gy + 1, c) += Value(fx * fy) * slice[p];
    }
    for (int axis = 0; axis < 2; ++axis) {  // y, then x
      std::fill(pass.begin(), pass.end(), Value(0));
      for (std::size_t y = 0; y < gh; ++y)
        for (std::size_t x = 0; x < gw; ++x)
          for (std::size_t c = 0; c < q; ++c)
            for (int t = -2; t <= 2; ++t) {
              const long sx = static_cast<long>(x) + (axis == 1 ? t : 0);
              const long sy = static_cast<long>(y) + (axis == 0 ? t : 0);
              if (sx < 0 || sy < 0 || sx >= static_cast<long>(gw) || sy >= static_cast<long>(gh))
                continue;
              at(pass, x, y, c) += taps[t + 2] * at(grid, static_cast<std::size_t>(sx),
                                                    static_cast<std::size_t>(sy), c);
            }
      grid.swap(pass);
    }
    std::vector<Value> mixed(grid.size(), Value(0));
    for (std::size_t n = 0; n < gw * gh; ++n)
      for (std::size_t a = 0; a < q; ++a) {
        if (clusters.sizes[a] == 0) continue;
        Value sum = 0;
        for (std::size_t b = 0; b < q; ++b) {
          if (clusters.sizes[b] == 0) continue;
          const double distance = cv::norm(clusters.means[a] - clusters.means[b]);
          if (distance > cutoff) continue;
          const double r = std::round(distance);
          sum += Value(std::exp(-r * r / (2.0 * options.colour_sigma * options.colour_sigma))) *
                 grid[n * q + b];
        }
        mixed[n * q + a] = sum;
      }
    std::vector<Value> out(w * h);
    for (std::size_t p = 0; p < w * h; ++p) {
      const double sx = static_cast<double>(p % w) / static_cast<double>(cell);
      const double sy = static_cast<double>(p / w) / static_cast<double>(cell);
      const auto gx = static_cast<std::size_t>(sx), gy = static_cast<std::size_t>(sy);
      const double fx = sx - static_cast<double>(gx), fy = sy - static_cast<double>(gy);
      const auto c = static_cast<std::size_t>(clusters.cluster_of[p]);
      out[p] = Value((1 - fx) * (1 - fy)) * at(mixed, gx, gy, c) +
               Value(fx * (1 - fy)) * at(mixed, gx + 1, gy, c) +
               Value((1 - fx) * fy) * at(mixed, gx, gy + 1, c) +
               Value(fx * fy) * at(mixed, gx + 1, gy + 1, c);
    }
    return out;
  };
  const std::vector<Value> denominator = smooth(std::vector<Value>(w * h, Value(1)));
  for (int d = 0; d < volume.labels(); ++d) {
    std::vector<Value> slice(w * h);
    for (std::size_t p = 0; p < w * h; ++p) slice[p] = volume.at(p % w, p / w, d);
    const std::vector<Value> out = smooth(slice);
    for (std::size_t p = 0; p < w * h; ++p) {
      volume.at(p % w, p / w, d) =
          static_cast<float>(static_cast<double>(out[p]) / static_cast<double>(denominator[p]));
    }
  }
}

}  // namespace

TEST_CASE("the bilateral filter's sparse grid gives the dense grid's volume, bit for bit",
          "[stereo][tsgo][bilateral]") {
  cv::Mat guide(30, 44, CV_8UC3);
  cv::RNG random(5);
  random.fill(guide, cv::RNG::UNIFORM, 0, 256);
  cv::GaussianBlur(guide, guide, cv::Size(7, 7), 2.0);  // clusters with range neighbours
  c2f::vision::BilateralOptions options;
  options.cell = 5;
  options.cluster_levels = 7;
  options.colour_sigma = 4.0;  // several neighbours per cluster
  // 16 labels: one full block, the denominator alone; 19: a full block and a short one whose
  // spare lane holds the denominator.
  for (const int labels : {16, 19}) {
    c2f::vision::CostVolume volume(44, 30, labels);
    for (std::size_t y = 0; y < 30; ++y)
      for (std::size_t x = 0; x < 44; ++x)
        for (int d = 0; d < labels; ++d)
          volume.at(x, y, d) = static_cast<float>(random.uniform(0.0, 1.0));
    c2f::vision::CostVolume in_double = volume;
    dense_cross_bilateral_filter<double>(in_double, guide, options);
    for (const int threads : {1, 2}) {
      options.threads = threads;
      c2f::vision::CostVolume sparse = volume, dense = volume;
      c2f::vision::cross_bilateral_filter(sparse, guide, options);
      dense_cross_bilateral_filter<float>(dense, guide, options);
      INFO(labels << " labels, " << threads << " threads");
      CHECK(std::memcmp(sparse.data().data(), dense.data().data(),
                        dense.data().size() * sizeof(float)) == 0);
      CHECK(sparse.data() != volume.data());  // it did filter
      // Float arithmetic against the same filter in double: a few roundings of a float apart.
      double largest = 0.0;
      for (std::size_t i = 0; i < sparse.data().size(); ++i) {
        const double exact = in_double.data()[i];
        largest = std::max(largest, std::abs(sparse.data()[i] - exact) / exact);
      }
      CHECK(largest < 1e-6);
      CHECK(largest > 0.0);  // float arithmetic did round
    }
  }
}

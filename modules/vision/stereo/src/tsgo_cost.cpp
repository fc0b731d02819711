#include "c2f/vision/stereo/tsgo_cost.hpp"

#include "c2f/support/parallel_for.hpp"
#include "stereo_pair_checks.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace c2f::vision {

namespace {

double signed_sqrt(double v) {
  return v < 0.0 ? -std::sqrt(-v) : std::sqrt(v);
}

}  // namespace

EqualisedPair equalise_photometry(const cv::Mat& left, const cv::Mat& right, double tolerance) {
  detail::require_colour_pair(left, right, "equalise_photometry");
  cv::Scalar m1, s1, m2, s2;
  cv::meanStdDev(left, m1, s1);
  cv::meanStdDev(right, m2, s2);
  auto relative = [](double a, double b) {
    return a + b > 0.0 ? std::abs(a - b) * 2.0 / (a + b) : 0.0;
  };
  bool differ = false;
  for (int c = 0; c < 3; ++c)
    differ = differ || relative(m1[c], m2[c]) > tolerance || relative(s1[c], s2[c]) > tolerance;
  EqualisedPair result{left.clone(), right.clone(), differ};
  if (!differ) return result;
  auto remap = [](cv::Mat& image, const cv::Scalar& mean, const cv::Scalar& stddev,
                  const cv::Scalar& target_mean, const cv::Scalar& target_std) {
    for (int y = 0; y < image.rows; ++y) {
      auto* row = image.ptr<cv::Vec3b>(y);
      for (int x = 0; x < image.cols; ++x) {
        for (int c = 0; c < 3; ++c) {
          const double scale = stddev[c] > 0.0 ? target_std[c] / stddev[c] : 1.0;
          const double value = (row[x][c] - mean[c]) * scale + target_mean[c];
          row[x][c] =
              static_cast<uchar>(std::clamp(value, 0.0, 255.0));  // truncation, as the reference
        }
      }
    }
  };
  const cv::Scalar mean = (m1 + m2) * 0.5, stddev = (s1 + s2) * 0.5;
  remap(result.left, m1, s1, mean, stddev);
  remap(result.right, m2, s2, mean, stddev);
  return result;
}

std::array<cv::Mat, 6> signed_sqrt_gradients(const cv::Mat& image, int threads) {
  if (image.type() != CV_8UC3 || image.empty()) {
    throw std::invalid_argument(
        "signed_sqrt_gradients: the image must be non-empty 8-bit 3-channel");
  }
  const int w = image.cols, h = image.rows;
  std::array<cv::Mat, 6> planes;
  for (auto& plane : planes) plane = cv::Mat(h, w, CV_64F);
  const double root2 = std::sqrt(2.0);
  auto at = [&](int x, int y, int c) {
    return static_cast<double>(
        image.at<cv::Vec3b>(std::clamp(y, 0, h - 1), std::clamp(x, 0, w - 1))[c]);
  };
  parallel_for(
      static_cast<std::size_t>(h),
      [&](std::size_t row) {
        const auto y = static_cast<int>(row);
        for (int x = 0; x < w; ++x) {
          for (int c = 0; c < 3; ++c) {
            const double dx = at(x + 1, y, c) - at(x - 1, y, c);
            const double dy = at(x, y + 1, c) - at(x, y - 1, c);
            const double dx1 = (at(x + 1, y - 1, c) - at(x - 1, y + 1, c)) / root2;
            const double dy1 = (at(x + 1, y + 1, c) - at(x - 1, y - 1, c)) / root2;
            planes[2 * c].at<double>(y, x) = signed_sqrt(4.0 * (dx + (dx1 + dy1) / root2));
            planes[2 * c + 1].at<double>(y, x) = signed_sqrt(4.0 * (dy + (dy1 - dx1) / root2));
          }
        }
      },
      threads);
  return planes;
}

double gradient_scale(const cv::Mat& image, int threads) {
  return gradient_scale(image, signed_sqrt_gradients(image, threads));
}

double gradient_scale(const cv::Mat& image, const std::array<cv::Mat, 6>& gradients) {
  cv::Scalar mean, stddev;
  cv::meanStdDev(image, mean, stddev);
  const double sigma_colour =
      std::sqrt(stddev[0] * stddev[0] + stddev[1] * stddev[1] + stddev[2] * stddev[2]);
  double squares = 0.0;
  for (const cv::Mat& plane : gradients) squares += cv::sum(plane.mul(plane))[0];
  const double sigma_gradient = std::sqrt(squares / static_cast<double>(image.total()));
  return sigma_gradient > 0.0 ? sigma_colour / sigma_gradient : 1.0;
}

std::array<cv::Mat, 6> gradient_planes(const cv::Mat& image, double mul, int threads) {
  return gradient_planes(signed_sqrt_gradients(image, threads), mul, threads);
}

std::array<cv::Mat, 6> gradient_planes(const std::array<cv::Mat, 6>& gradients, double mul,
                                       int threads) {
  const int rows = gradients[0].rows, cols = gradients[0].cols;
  std::array<cv::Mat, 6> planes;
  for (cv::Mat& plane : planes) plane = cv::Mat(rows, cols, CV_8U);
  parallel_for(
      static_cast<std::size_t>(rows),
      [&](std::size_t row) {
        const auto y = static_cast<int>(row);
        for (std::size_t p = 0; p < planes.size(); ++p) {
          for (int x = 0; x < cols; ++x) {
            planes[p].at<uchar>(y, x) = static_cast<uchar>(
                std::clamp(mul * gradients[p].at<double>(y, x) + 128.0, 0.0, 255.0));
          }
        }
      },
      threads);
  return planes;
}

namespace {

/// Each pixel's 6 plane values side by side in 8 bytes, raster order: a cost reads one run of
/// bytes per view instead of one byte from each of 12 planes.
using PackedPlanes = std::vector<std::array<std::uint8_t, 8>>;

PackedPlanes packed(const std::array<cv::Mat, 6>& planes, int threads) {
  const auto w = static_cast<std::size_t>(planes[0].cols);
  PackedPlanes pixels(w * static_cast<std::size_t>(planes[0].rows));
  parallel_for(
      static_cast<std::size_t>(planes[0].rows),
      [&](std::size_t y) {
        for (std::size_t p = 0; p < planes.size(); ++p) {
          const uchar* row = planes[p].ptr<uchar>(static_cast<int>(y));
          for (std::size_t x = 0; x < w; ++x) pixels[y * w + x][p] = row[x];
        }
      },
      threads);
  return pixels;
}

}  // namespace

CostVolume gradient_matching_cost(const std::array<cv::Mat, 6>& left,
                                  const std::array<cv::Mat, 6>& right, int labels,
                                  double truncation, int threads) {
  for (std::size_t p = 0; p < 6; ++p) {
    if (left[p].type() != CV_8U || right[p].type() != CV_8U || left[p].size() != left[0].size() ||
        right[p].size() != left[0].size()) {
      throw std::invalid_argument("gradient_matching_cost: planes must be 8-bit and of one size");
    }
  }
  const auto w = static_cast<std::size_t>(left[0].cols), h = static_cast<std::size_t>(left[0].rows);
  const PackedPlanes left_pixels = packed(left, threads), right_pixels = packed(right, threads);
  // A sum of 6 byte differences is at most 6 * 255: every cost is looked up, computed once per
  // sum by the one expression.
  std::array<float, 6 * 255 + 1> cost_of_sum{};
  for (std::size_t sum = 0; sum < cost_of_sum.size(); ++sum)
    cost_of_sum[sum] = static_cast<float>(std::min(static_cast<double>(sum), truncation));
  const auto label_count = static_cast<std::size_t>(labels);
  // Every cell is written here, each row by the thread that computes it.
  CostVolume volume(w, h, labels, CostVolume::Unwritten{});
  parallel_for(
      h,
      [&](std::size_t y) {
        for (std::size_t x = 0; x < w; ++x) {
          const std::array<std::uint8_t, 8>& l = left_pixels[y * w + x];
          float* costs = &volume.at(x, y, 0);
          const std::size_t valid = volume.valid_labels(x);
          // The left values held in registers across the labels (a loop over the 6 planes
          // compiles to reloads from the stack and took 3 times as long).
          const int l0 = l[0], l1 = l[1], l2 = l[2], l3 = l[3], l4 = l[4], l5 = l[5];
          for (std::size_t d = 0; d < valid; ++d) {
            const std::array<std::uint8_t, 8>& r = right_pixels[y * w + x - d];
            const int sum = std::abs(l0 - r[0]) + std::abs(l1 - r[1]) + std::abs(l2 - r[2]) +
                            std::abs(l3 - r[3]) + std::abs(l4 - r[4]) + std::abs(l5 - r[5]);
            costs[d] = cost_of_sum[static_cast<std::size_t>(sum)];
          }
          std::fill(costs + valid, costs + label_count, std::numeric_limits<float>::quiet_NaN());
        }
      },
      threads);
  return volume;
}

double erf_approximation(double x) {
  constexpr double p = 0.3275911, a1 = 0.254829592, a2 = -0.284496736, a3 = 1.421413741,
                   a4 = -1.453152027, a5 = 1.061405429;
  const double sign = x < 0.0 ? -1.0 : 1.0;
  x = std::abs(x);
  const double t = 1.0 / (1.0 + p * x);
  const double y = 1.0 - (((((a5 * t + a4) * t) + a3) * t + a2) * t + a1) * t * std::exp(-x * x);
  return sign * y;
}

RobustTransformParameters robust_transform(CostVolume& volume, double threshold, int threads) {
  const std::size_t pixels = volume.width() * volume.height();
  // Each row's sums over its pixels in raster order, on `threads` threads; then the rows' sums
  // in row order. Fixed for any thread count; with integer costs (the default truncation) every
  // partial sum is exact, so this is also the one raster-order sum.
  struct RowSums {
    double minimum = 0.0, excess = 0.0;
    std::size_t cells = 0;
  };
  std::vector<RowSums> rows(volume.height());
  parallel_for(
      volume.height(),
      [&](std::size_t y) {
        RowSums& row = rows[y];
        for (std::size_t x = 0; x < volume.width(); ++x) {
          double minimum = std::numeric_limits<double>::infinity();
          for (int d = 0; d < volume.labels() && volume.valid(x, d); ++d)
            minimum = std::min(minimum, static_cast<double>(volume.at(x, y, d)));
          row.minimum += minimum;
          for (int d = 0; d < volume.labels() && volume.valid(x, d); ++d) {
            row.excess += static_cast<double>(volume.at(x, y, d)) - minimum;
            ++row.cells;
          }
        }
      },
      threads);
  double sum_minimum = 0.0, sum_excess = 0.0;
  std::size_t valid_cells = 0;
  for (const RowSums& row : rows) {
    sum_minimum += row.minimum;
    sum_excess += row.excess;
    valid_cells += row.cells;
  }
  RobustTransformParameters parameters{};
  parameters.mean_minimum = sum_minimum / static_cast<double>(pixels);
  parameters.mean_excess = sum_excess / static_cast<double>(valid_cells);
  if (!(parameters.mean_minimum > 0.0)) {
    throw std::invalid_argument(
        "every pixel matches some disparity perfectly (are the two views identical, or "
        "uniform?): TSGO's robust transform divides by the mean best matching cost, which is 0; "
        "give two views of a textured scene");
  }
  const double spread = parameters.mean_excess - parameters.mean_minimum;
  parameters.slope = threshold * spread * spread;
  if (parameters.slope > 2.5) parameters.slope *= 0.91;
  const double mm = parameters.mean_minimum;
  const auto transformed = [&](double cost) {
    return static_cast<float>((1.0 + erf_approximation(parameters.slope * (cost - mm) / mm)) / 2.0);
  };
  // Matching costs are small integers (sums of byte differences): those are looked up, computed
  // once each by the same expression; any other value is computed where it is.
  constexpr std::size_t kTabulated = 2048;
  std::vector<float> table(kTabulated);
  for (std::size_t c = 0; c < kTabulated; ++c) table[c] = transformed(static_cast<double>(c));
  parallel_for(
      volume.height(),
      [&](std::size_t y) {
        for (std::size_t x = 0; x < volume.width(); ++x) {
          for (int d = 0; d < volume.labels() && volume.valid(x, d); ++d) {
            float& cost = volume.at(x, y, d);
            const bool tabulated =
                cost >= 0.0f && cost < static_cast<float>(kTabulated) && cost == std::floor(cost);
            cost = tabulated ? table[static_cast<std::size_t>(cost)]
                             : transformed(static_cast<double>(cost));
          }
        }
      },
      threads);
  return parameters;
}

void fill_left_border(CostVolume& volume) {
  const std::size_t w = volume.width();
  for (std::size_t y = 0; y < volume.height(); ++y) {
    for (std::size_t x = 0; x < w; ++x) {
      for (int d = static_cast<int>(x) + 1; d < volume.labels(); ++d) {
        const std::size_t source = std::min(static_cast<std::size_t>(d), w - 1);
        volume.at(x, y, d) = volume.at(source, y, std::min(d, static_cast<int>(source)));
      }
    }
  }
}

}  // namespace c2f::vision

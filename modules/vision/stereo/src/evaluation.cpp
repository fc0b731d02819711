#include "c2f/vision/stereo/evaluation.hpp"

#include "c2f/vision/stereo/disparity_io.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace c2f::vision {

std::string BadPixelRates::brief() const {
  char text[200];
  if (nonoccluded_pixels == 0) {
    std::snprintf(text, sizeof text,
                  "bad>1: all %.2f%% (bad>0.5 %.2f%%, bad>2 %.2f%%; no occlusion mask)",
                  100 * all[1], 100 * all[0], 100 * all[2]);
  } else {
    std::snprintf(text, sizeof text,
                  "bad>1: nonocc %.2f%%, all %.2f%% (bad>0.5 %.2f%%/%.2f%%, bad>2 %.2f%%/%.2f%%)",
                  100 * nonoccluded[1], 100 * all[1], 100 * nonoccluded[0], 100 * all[0],
                  100 * nonoccluded[2], 100 * all[2]);
  }
  return text;
}

BadPixelRates bad_pixel_rates(const cv::Mat& disparity, const cv::Mat& gt,
                              const cv::Mat& nonoccluded) {
  if (disparity.type() != CV_32F || gt.type() != CV_32F || disparity.size() != gt.size()) {
    throw std::invalid_argument(
        "bad_pixel_rates: disparity and GT must be CV_32F maps of one size");
  }
  const bool masked = !nonoccluded.empty();
  if (masked && (nonoccluded.type() != CV_8U || nonoccluded.size() != gt.size())) {
    throw std::invalid_argument(
        "bad_pixel_rates: the non-occluded mask must be CV_8U of the GT's size");
  }
  BadPixelRates rates;
  std::array<std::size_t, 3> bad_all{}, bad_nonocc{};
  std::size_t reference_bad = 0;
  for (int y = 0; y < gt.rows; ++y) {
    for (int x = 0; x < gt.cols; ++x) {
      const float truth = gt.at<float>(y, x);
      if (std::isnan(truth)) continue;
      const double error = std::abs(static_cast<double>(disparity.at<float>(y, x)) - truth);
      const bool evaluate_nonocc = masked && nonoccluded.at<uchar>(y, x) == 255;
      ++rates.known_pixels;
      rates.nonoccluded_pixels += evaluate_nonocc;
      for (std::size_t t = 0; t < 3; ++t) {
        const bool bad = !(error <= BadPixelRates::thresholds[t]);
        bad_all[t] += bad;
        bad_nonocc[t] += bad && evaluate_nonocc;
      }
      reference_bad += !(error <= 1.0);
    }
  }
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (std::size_t t = 0; t < 3; ++t) {
    rates.all[t] = rates.known_pixels
                       ? static_cast<double>(bad_all[t]) / static_cast<double>(rates.known_pixels)
                       : nan;
    rates.nonoccluded[t] =
        rates.nonoccluded_pixels
            ? static_cast<double>(bad_nonocc[t]) / static_cast<double>(rates.nonoccluded_pixels)
            : nan;
  }
  rates.reference_variant = static_cast<double>(reference_bad) / static_cast<double>(gt.total());
  return rates;
}

std::function<double(std::span<const Label>)> bad_pixel_error(const StereoScene& scene) {
  if (scene.gt.empty()) throw std::invalid_argument("bad_pixel_error: the scene has no GT");
  return [&scene, shape = scene.shape()](std::span<const Label> labeling) {
    const BadPixelRates rates =
        bad_pixel_rates(labels_to_disparity(labeling, shape), scene.gt, scene.nonoccluded);
    return scene.nonoccluded.empty() ? rates.all[1] : rates.nonoccluded[1];
  };
}

}  // namespace c2f::vision

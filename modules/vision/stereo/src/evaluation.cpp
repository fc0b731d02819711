#include "c2f/vision/stereo/evaluation.hpp"

#include "c2f/support/number_text.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace c2f::vision {

std::string BadPixelRates::brief() const {
  if (nonoccluded_pixels == 0) {
    return c_format("bad>1: all %.2f%% (bad>0.5 %.2f%%, bad>2 %.2f%%; no occlusion mask)",
                    100 * all[1], 100 * all[0], 100 * all[2]);
  }
  return c_format("bad>1: nonocc %.2f%%, all %.2f%% (bad>0.5 %.2f%%/%.2f%%, bad>2 %.2f%%/%.2f%%)",
                  100 * nonoccluded[1], 100 * all[1], 100 * nonoccluded[0], 100 * all[0],
                  100 * nonoccluded[2], 100 * all[2]);
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

std::string SceneErrors::brief(const ErrorMeasure& measure) const {
  std::string bound;
  if (measure.relative > 0.0) {
    bound = c_format(" (> %g px and > %g%% here)", measure.absolute, 100 * measure.relative);
  } else if (measure.follows_downscale) {
    bound = c_format(" (> %g px here)", measure.absolute);
  }
  if (nonoccluded_pixels == 0)
    return c_format("%s%s: all %.2f%%", measure.name.c_str(), bound.c_str(), 100 * all);
  return c_format("%s%s: nonocc %.2f%%, all %.2f%%", measure.name.c_str(), bound.c_str(),
                  100 * nonoccluded, 100 * all);
}

std::string scene_error_line(std::span<const Label> labeling, const StereoScene& scene) {
  if (scene.gt.empty() || scene.measure == ErrorMeasure{}) return {};
  return scene_errors(labels_to_disparity(labeling, scene.shape()), scene).brief(scene.measure);
}

SceneErrors scene_errors(const cv::Mat& disparity, const StereoScene& scene) {
  if (scene.gt.empty()) throw std::invalid_argument("scene_errors: the scene has no GT");
  if (disparity.type() != CV_32F || disparity.size() != scene.gt.size())
    throw std::invalid_argument("scene_errors: the disparity must be CV_32F of the GT's size");
  const bool masked = !scene.nonoccluded.empty();
  SceneErrors errors;
  std::size_t bad_all = 0, bad_nonoccluded = 0;
  for (int y = 0; y < scene.gt.rows; ++y) {
    const float* truth = scene.gt.ptr<float>(y);
    const float* d = disparity.ptr<float>(y);
    const uchar* mask = masked ? scene.nonoccluded.ptr<uchar>(y) : nullptr;
    for (int x = 0; x < scene.gt.cols; ++x) {
      if (std::isnan(truth[x])) continue;
      const bool bad = scene.measure.is_bad(d[x], truth[x]);
      const bool nonoccluded = masked && mask[x] == 255;
      ++errors.known_pixels;
      errors.nonoccluded_pixels += nonoccluded;
      bad_all += bad;
      bad_nonoccluded += bad && nonoccluded;
    }
  }
  const auto rate = [](std::size_t bad, std::size_t pixels) {
    return pixels ? static_cast<double>(bad) / static_cast<double>(pixels)
                  : std::numeric_limits<double>::quiet_NaN();
  };
  errors.all = rate(bad_all, errors.known_pixels);
  errors.nonoccluded = rate(bad_nonoccluded, errors.nonoccluded_pixels);
  return errors;
}

std::function<double(std::span<const Label>)> bad_pixel_error(const StereoScene& scene) {
  if (scene.gt.empty()) throw std::invalid_argument("bad_pixel_error: the scene has no GT");
  return [&scene, shape = scene.shape()](std::span<const Label> labeling) {
    const SceneErrors errors = scene_errors(labels_to_disparity(labeling, shape), scene);
    return scene.nonoccluded.empty() ? errors.all : errors.nonoccluded;
  };
}

}  // namespace c2f::vision

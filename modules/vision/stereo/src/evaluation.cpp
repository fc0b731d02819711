#include "c2f/vision/stereo/evaluation.hpp"

#include "c2f/support/number_text.hpp"
#include "c2f/vision/stereo/disparity_io.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

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

namespace {

/// bad_pixel_error's count, prepared once per scene: a trace scores every step, and building a
/// disparity map and testing the measure at every pixel took about a tenth of a 2014 Q run's
/// time. The labels a pixel's measure does not count as bad form one interval (is_bad grows
/// with |d - g|), found once by is_bad itself at its ends, so a labeling's rate is a count of
/// labels outside their pixel's interval: the same counts as scene_errors, so the same rate.
class LabelErrorRate {
 public:
  explicit LabelErrorRate(const StereoScene& scene) : size_(scene.shape().size()) {
    if (scene.gt.type() != CV_32F || scene.gt.cols != scene.left.cols ||
        scene.gt.rows != scene.left.rows) {
      throw std::invalid_argument("bad_pixel_error: the GT must be CV_32F of the views' size");
    }
    const bool masked = !scene.nonoccluded.empty();
    for (int y = 0; y < scene.gt.rows; ++y) {
      const float* truth = scene.gt.ptr<float>(y);
      const uchar* mask = masked ? scene.nonoccluded.ptr<uchar>(y) : nullptr;
      for (int x = 0; x < scene.gt.cols; ++x) {
        if (std::isnan(truth[x]) || (masked && mask[x] != 255)) continue;
        const auto index = static_cast<std::size_t>(y) * static_cast<std::size_t>(scene.gt.cols) +
                           static_cast<std::size_t>(x);
        pixels_.push_back(good_labels(scene.measure, truth[x], index));
      }
    }
  }

  /// The share of the pixels the rate is over whose label `labeling` gives is bad (NaN when
  /// there are none, as scene_errors).
  double operator()(std::span<const Label> labeling) const {
    if (labeling.size() != size_) {
      throw std::invalid_argument("bad_pixel_error: " + std::to_string(labeling.size()) +
                                  " labels for a scene of " + std::to_string(size_) + " pixels");
    }
    std::size_t bad = 0;
    for (const Pixel& pixel : pixels_) {
      const Label label = labeling[pixel.index];
      bad += label < pixel.lowest_good || label > pixel.highest_good;
    }
    return pixels_.empty() ? std::numeric_limits<double>::quiet_NaN()
                           : static_cast<double>(bad) / static_cast<double>(pixels_.size());
  }

 private:
  struct Pixel {
    std::size_t index;
    Label lowest_good, highest_good;  // empty when lowest_good > highest_good
  };

  /// The labels l with !measure.is_bad(l, truth), an interval: bounded by the measure's
  /// threshold around a finite truth, then moved to where is_bad itself changes (at most a step
  /// of rounding each way); every label or none for an infinite one.
  static Pixel good_labels(const ErrorMeasure& measure, float truth, std::size_t index) {
    constexpr double kFar = 1 << 30;  // beyond every label a trace sees
    const double g = truth;
    const auto good = [&](double label) { return !measure.is_bad(label, g); };
    if (!std::isfinite(g)) {
      const bool all = good(0.0);
      return {index, all ? std::numeric_limits<Label>::min() : 1,
              all ? std::numeric_limits<Label>::max() : 0};
    }
    const double bound = measure.relative > 0.0 ? std::max(measure.absolute, measure.relative * g)
                                                : measure.absolute;
    double low = std::clamp(std::ceil(g - bound), -kFar, kFar);
    double high = std::clamp(std::floor(g + bound), -kFar, kFar);
    for (int step = 0; step < 2; ++step) {
      if (low > -kFar && good(low - 1)) low -= 1;
      if (high < kFar && good(high + 1)) high += 1;
    }
    for (int step = 0; step < 2; ++step) {
      if (low <= high && !good(low)) low += 1;
      if (low <= high && !good(high)) high -= 1;
    }
    if (low > high) return {index, 1, 0};
    return {index, static_cast<Label>(low), static_cast<Label>(high)};
  }

  std::size_t size_;
  std::vector<Pixel> pixels_;
};

}  // namespace

std::function<double(std::span<const Label>)> bad_pixel_error(const StereoScene& scene) {
  if (scene.gt.empty()) throw std::invalid_argument("bad_pixel_error: the scene has no GT");
  return [rate = std::make_shared<const LabelErrorRate>(scene)](std::span<const Label> labeling) {
    return (*rate)(labeling);
  };
}

}  // namespace c2f::vision

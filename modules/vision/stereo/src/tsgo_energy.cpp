#include "c2f/vision/stereo/tsgo_energy.hpp"

#include "c2f/support/enum_names.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "c2f/core/grid.hpp"
#include "c2f/support/memory_need.hpp"
#include "c2f/support/parallel_for.hpp"
#include "c2f/vision/stereo/colour_weights.hpp"
#include "c2f/vision/stereo/tsgo_bilateral.hpp"
#include "c2f/vision/stereo/tsgo_cost.hpp"

namespace c2f::vision {

std::string_view to_string(StereoSmoothness smoothness) {
  return smoothness == StereoSmoothness::tsgo_step ? "tsgo_step" : "truncated_linear";
}

StereoSmoothness stereo_smoothness_from_string(std::string_view text) {
  constexpr StereoSmoothness kAll[] = {StereoSmoothness::tsgo_step,
                                       StereoSmoothness::truncated_linear};
  return enum_from_string(text, kAll, "smoothness");
}

std::string TsgoOptions::validate() const {
  if (labels < 2) return "labels must be >= 2, got " + std::to_string(labels);
  if (!(equalise_tolerance >= 0.0)) return "equalise_tolerance must be >= 0";
  if (!(cost_truncation > 0.0)) return "cost_truncation must be > 0";
  if (!(transform_threshold > 0.0)) return "transform_threshold must be > 0";
  if (bilateral.cell < 1) return "bilateral.cell must be >= 1";
  if (threads < 0)
    return "threads must be >= 0 (0: the machine's cores), got " + std::to_string(threads);
  if (!(bilateral.colour_sigma > 0.0)) return "bilateral.colour_sigma must be > 0";
  if (!(truncation > 0.0) || !std::isfinite(truncation)) return "truncation must be finite and > 0";
  return {};
}

std::optional<std::size_t> tsgo_memory_estimate(std::size_t width, std::size_t height, int labels,
                                                int threads) {
  // Per pixel and label: the volume (4 bytes, float), which becomes the unaries. Per pixel: the
  // images, gradient planes, clusters, the filter's lists and slots, and labelings (512), and
  // the filter's two buffers of grid entries, 16 labels in float each, which its threads share
  // (640: up to 10 entries of 64 bytes; 3-9 on the datasets and on a pair of noise images).
  // Per filtering thread: one node's entries (at most the 4096 clusters, 64 bytes each).
  // Full-size Aloe: 2.9 GiB (2.0 measured on two threads).
  const std::optional<std::size_t> pixels = checked_product({width, height});
  if (!pixels || labels < 0) return std::nullopt;
  const auto per_pixel = checked_product({static_cast<std::size_t>(labels), sizeof(float)});
  const auto volume_and_images =
      per_pixel ? checked_product({*pixels, *per_pixel + 512 + 640}) : std::nullopt;
  const auto per_thread = checked_product({resolved_threads(threads), 4096 * 64});
  if (!volume_and_images || !per_thread) return std::nullopt;
  return checked_sum({*volume_and_images, *per_thread});
}

TsgoCost tsgo_cost(const cv::Mat& left, const cv::Mat& right, const TsgoOptions& options) {
  if (const std::string problem = options.validate(); !problem.empty()) {
    throw std::invalid_argument("TSGO options: " + problem);
  }
  require_memory(
      "the TSGO energy of " + std::to_string(left.cols) + "x" + std::to_string(left.rows) +
          " pixels and " + std::to_string(options.labels) + " labels",
      tsgo_memory_estimate(static_cast<std::size_t>(left.cols), static_cast<std::size_t>(left.rows),
                           options.labels, options.threads));
  EqualisedPair pair = equalise_photometry(left, right, options.equalise_tolerance);
  const std::array<cv::Mat, 6> left_gradients = signed_sqrt_gradients(pair.left, options.threads);
  const double mul = gradient_scale(pair.left, left_gradients);
  CostVolume volume =
      gradient_matching_cost(gradient_planes(left_gradients, mul, options.threads),
                             gradient_planes(pair.right, mul, options.threads), options.labels,
                             options.cost_truncation, options.threads);
  robust_transform(volume, options.transform_threshold, options.threads);
  fill_left_border(volume);
  BilateralOptions bilateral = options.bilateral;
  if (options.cluster_levels_from_labels) bilateral.cluster_levels = options.labels < 30 ? 11 : 12;
  bilateral.threads = options.threads;
  cross_bilateral_filter(volume, pair.left, bilateral);
  return TsgoCost{std::move(volume), pair.left, pair.applied};
}

PairwiseEnergy tsgo_energy(TsgoCost cost, const TsgoOptions& options) {
  const GridShape shape{cost.volume.width(), cost.volume.height()};
  const int labels = cost.volume.labels();
  const PairwiseTerm term = options.smoothness == StereoSmoothness::tsgo_step
                                ? PairwiseTerm::tsgo_step()
                                : PairwiseTerm::truncated_linear(options.truncation);
  const cv::Mat& image = cost.left;
  return PairwiseEnergy::with_float_unaries(
      shape.size(), labels, cost.volume.release(), {term},
      grid_edges(shape, Connectivity::four,
                 [&](VariableIndex u, VariableIndex v) { return tsgo_edge_weight(image, u, v); }));
}

TsgoProblem tsgo_problem(const cv::Mat& left, const cv::Mat& right, const TsgoOptions& options) {
  TsgoCost cost = tsgo_cost(left, right, options);
  cv::Mat guide = cost.left.clone();
  return {tsgo_energy(std::move(cost), options), std::move(guide)};
}

}  // namespace c2f::vision

#pragma once
// The TSGO stereo energy: step 1 (cost volume) and step 2 (the 4-connected MRF), for the left
// view. (The reference also solved the right view's MRF every iteration and never used the
// result; we do not compute it.)

#include <cstddef>
#include <opencv2/core.hpp>
#include <optional>
#include <string_view>

#include "c2f/core/pairwise_energy.hpp"
#include "c2f/vision/stereo/cost_volume.hpp"

namespace c2f::vision {

/// The pairwise term of step 2.
enum class StereoSmoothness {
  tsgo_step,  ///< w * (0, 1/6, 1) for |a - b| = 0, 1, >= 2: what TSGO and the reference optimise
  truncated_linear,  ///< w * min(|a - b|, truncation): the paper's wording
};

std::string_view to_string(StereoSmoothness smoothness);
StereoSmoothness stereo_smoothness_from_string(std::string_view text);

/// The cross-bilateral filter that ends step 1 (TSGO's one iteration of message passing on the
/// fully connected MRF).
struct BilateralOptions {
  int cell = 18;               ///< grid cell size in pixels (spatial sigma = one cell)
  double colour_sigma = 0.75;  ///< in 8-bit colour units
  double cutoff_sigmas = 3.0;  ///< clusters farther apart than cutoff * sigma do not mix
  int cluster_levels = 12;     ///< 2^12 = 4096 clusters (the reference's 4000 rounded up)
  int threads = 0;             ///< threads filtering labels (0: the machine's cores); the
                               ///< result is the same for every count
};

struct TsgoOptions {
  int labels = 85;  ///< disparities 0..labels-1
  double equalise_tolerance = 0.16;
  double cost_truncation = 360.0;
  double transform_threshold = 0.00095;
  BilateralOptions bilateral;              ///< cluster_levels is set from labels unless overridden
  bool cluster_levels_from_labels = true;  ///< 12 levels (4096 clusters), 11 when labels < 30
  StereoSmoothness smoothness = StereoSmoothness::tsgo_step;
  double truncation = 2.0;  ///< for truncated_linear
  /// Threads of the data preparation (0: the machine's cores; sets bilateral.threads). The
  /// energy is the same, bit for bit, for every count.
  int threads = 0;

  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
};

struct TsgoCost {
  CostVolume volume;  ///< filtered unaries of the left view, in (0, 1)
  cv::Mat left;       ///< the (equalised) left image the weights and the filter use
  bool equalised;     ///< whether photometric equalisation changed the images
};

/// An estimate of the bytes TSGO step 1 takes at its peak for width x height pixels and
/// `labels` labels on `threads` threads (0: the machine's cores): the cost volume, which
/// becomes the energy's unaries, the images and their features, the filter's workspace and
/// each filtering thread's buffer of one grid node. A run's solver needs more (run_memory_floor).
/// std::nullopt when the count overflows.
std::optional<std::size_t> tsgo_memory_estimate(std::size_t width, std::size_t height, int labels,
                                                int threads = 1);

/// TSGO step 1 for the left view: equalisation, gradient features, matching cost, robust
/// transform, border fill and the cross-bilateral filter. Throws std::invalid_argument for
/// images that are not 8-bit colour of one size, invalid options, or a problem larger than
/// the memory available (require_memory with tsgo_memory_estimate, checked first).
TsgoCost tsgo_cost(const cv::Mat& left, const cv::Mat& right, const TsgoOptions& options = {});

/// TSGO step 2: the 4-connected grid energy with the volume as unaries and weights from the
/// L1 colour difference classes of the left image (tsgo_edge_weight). Consumes the volume.
PairwiseEnergy tsgo_energy(TsgoCost cost, const TsgoOptions& options = {});

/// Both steps for a pair of views, keeping the image a schedule's slic:S levels segment.
struct TsgoProblem {
  PairwiseEnergy energy;
  cv::Mat guide;  ///< the (equalised) left image of TsgoCost: give it to slic_source
};

/// tsgo_energy(tsgo_cost(left, right, options), options) and that cost's left image. Throws as
/// tsgo_cost does.
TsgoProblem tsgo_problem(const cv::Mat& left, const cv::Mat& right,
                         const TsgoOptions& options = {});

}  // namespace c2f::vision

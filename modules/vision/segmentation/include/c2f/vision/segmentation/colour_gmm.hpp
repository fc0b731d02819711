#pragma once
// Colour models of the segmentation unaries: a full-covariance Gaussian mixture per label,
// fitted to that label's seed colours, and the cost the cooperative-cuts data preparation
// derives from it.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

#include "c2f/vision/segmentation/kmeans.hpp"

namespace c2f::vision {

struct GaussianComponent {
  double weight = 0.0;
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Identity();
};

struct ColourGmm {
  std::vector<GaussianComponent> components;
};

/// EM for a Gaussian mixture with `components` components (fewer when there are fewer
/// samples), initialised by k-means with `kmeans_options` (deterministic for its seed); 1e-5 I
/// is added to every covariance; stops when |loglik / loglik_old - 1| < 1e-10 or after 500
/// rounds. Throws std::invalid_argument without samples.
ColourGmm fit_colour_gmm(std::span<const Eigen::Vector3d> samples, int components = 5,
                         const KMeansOptions& kmeans_options = {});

/// The cost of colour x under `gmm` with regulariser s:
///   min_i [ -log w_i + 1/2 log det(S_i + s I) + 1/2 (x - m_i)^T (S_i + s I)^-1 (x - m_i) ]
///   + 1.5 log(2 pi)
/// (the minimum over components, not the negative log of the mixture).
class GmmCost {
 public:
  GmmCost(const ColourGmm& gmm, double regulariser);
  [[nodiscard]] double operator()(const Eigen::Vector3d& x) const;

 private:
  struct Term {
    double constant;
    Eigen::Vector3d mean;
    Eigen::Matrix3d precision;
  };
  std::vector<Term> terms_;
};

/// The costs of `colours` under `gmm` with the smallest regulariser s = 0.01 + 0.1 k (k = 0, 1,
/// ...) that makes every cost >= 0, as the cooperative-cuts preparation chooses it.
std::vector<double> nonnegative_gmm_costs(const ColourGmm& gmm,
                                          std::span<const Eigen::Vector3d> colours);

}  // namespace c2f::vision

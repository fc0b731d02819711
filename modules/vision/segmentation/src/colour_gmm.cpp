#include "c2f/vision/segmentation/colour_gmm.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "c2f/vision/segmentation/kmeans.hpp"

namespace c2f::vision {

namespace {

constexpr double kCovarianceFloor = 1e-5;

/// log N(x | mean, covariance) for a precomputed inverse and log-determinant.
double log_density(const Eigen::Vector3d& x, const Eigen::Vector3d& mean,
                   const Eigen::Matrix3d& precision, double log_det) {
  const Eigen::Vector3d d = x - mean;
  return -0.5 * d.dot(precision * d) - 0.5 * log_det - 1.5 * std::log(2.0 * std::numbers::pi);
}

}  // namespace

ColourGmm fit_colour_gmm(std::span<const Eigen::Vector3d> samples, int components,
                         const KMeansOptions& kmeans_options) {
  if (samples.empty()) throw std::invalid_argument("fit_colour_gmm: no samples");
  const std::size_t n = samples.size();
  const KMeansResult clusters = kmeans(samples, components, kmeans_options);
  const std::size_t k = clusters.centres.size();

  ColourGmm gmm;
  gmm.components.resize(k);
  for (std::size_t c = 0; c < k; ++c) {
    Eigen::Vector3d sum = Eigen::Vector3d::Zero();
    std::size_t count = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (clusters.assignment[i] != static_cast<int>(c)) continue;
      sum += samples[i];
      ++count;
    }
    GaussianComponent& component = gmm.components[c];
    component.weight = static_cast<double>(count) / static_cast<double>(n);
    component.mean =
        count > 0 ? Eigen::Vector3d(sum / static_cast<double>(count)) : clusters.centres[c];
    Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
    for (std::size_t i = 0; i < n; ++i) {
      if (clusters.assignment[i] != static_cast<int>(c)) continue;
      const Eigen::Vector3d d = samples[i] - component.mean;
      scatter += d * d.transpose();
    }
    component.covariance = (count > 1 ? Eigen::Matrix3d(scatter / static_cast<double>(count - 1))
                                      : Eigen::Matrix3d::Zero()) +
                           kCovarianceFloor * Eigen::Matrix3d::Identity();
  }

  // EM.
  std::vector<double> responsibility(n * k);
  double previous = -std::numeric_limits<double>::infinity();
  for (int round = 0; round < 500; ++round) {
    std::vector<Eigen::Matrix3d> precision(k);
    std::vector<double> log_det(k);
    for (std::size_t c = 0; c < k; ++c) {
      precision[c] = gmm.components[c].covariance.inverse();
      log_det[c] = std::log(gmm.components[c].covariance.determinant());
    }
    double loglik = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      double best = -std::numeric_limits<double>::infinity();
      for (std::size_t c = 0; c < k; ++c) {
        const double weight = gmm.components[c].weight;
        const double value =
            weight > 0.0 ? std::log(weight) + log_density(samples[i], gmm.components[c].mean,
                                                          precision[c], log_det[c])
                         : -std::numeric_limits<double>::infinity();
        responsibility[i * k + c] = value;
        best = std::max(best, value);
      }
      double total = 0.0;
      for (std::size_t c = 0; c < k; ++c) {
        responsibility[i * k + c] = std::exp(responsibility[i * k + c] - best);
        total += responsibility[i * k + c];
      }
      for (std::size_t c = 0; c < k; ++c) responsibility[i * k + c] /= total;
      loglik += best + std::log(total);
    }
    for (std::size_t c = 0; c < k; ++c) {
      double mass = 0.0;
      Eigen::Vector3d sum = Eigen::Vector3d::Zero();
      for (std::size_t i = 0; i < n; ++i) {
        mass += responsibility[i * k + c];
        sum += responsibility[i * k + c] * samples[i];
      }
      GaussianComponent& component = gmm.components[c];
      component.weight = mass / static_cast<double>(n);
      if (mass <= 0.0) continue;
      component.mean = sum / mass;
      Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
      for (std::size_t i = 0; i < n; ++i) {
        const Eigen::Vector3d d = samples[i] - component.mean;
        scatter += responsibility[i * k + c] * (d * d.transpose());
      }
      component.covariance = scatter / mass + kCovarianceFloor * Eigen::Matrix3d::Identity();
    }
    if (std::isfinite(previous) && std::abs(loglik / previous - 1.0) < 1e-10) break;
    previous = loglik;
  }
  return gmm;
}

GmmCost::GmmCost(const ColourGmm& gmm, double regulariser) {
  for (const GaussianComponent& component : gmm.components) {
    if (!(component.weight > 0.0)) continue;
    const Eigen::Matrix3d covariance =
        component.covariance + regulariser * Eigen::Matrix3d::Identity();
    terms_.push_back({-std::log(component.weight) + 0.5 * std::log(covariance.determinant()),
                      component.mean, covariance.inverse()});
  }
}

double GmmCost::operator()(const Eigen::Vector3d& x) const {
  double best = std::numeric_limits<double>::infinity();
  for (const Term& term : terms_) {
    const Eigen::Vector3d d = x - term.mean;
    best = std::min(best, term.constant + 0.5 * d.dot(term.precision * d));
  }
  return best + 1.5 * std::log(2.0 * std::numbers::pi);
}

std::vector<double> nonnegative_gmm_costs(const ColourGmm& gmm,
                                          std::span<const Eigen::Vector3d> colours) {
  std::vector<double> costs(colours.size());
  for (double regulariser = 0.01;; regulariser += 0.1) {
    const GmmCost cost(gmm, regulariser);
    bool nonnegative = true;
    for (std::size_t i = 0; i < colours.size(); ++i) {
      costs[i] = cost(colours[i]);
      nonnegative = nonnegative && costs[i] >= 0.0;
    }
    if (nonnegative) return costs;
  }
}

}  // namespace c2f::vision

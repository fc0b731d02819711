#include "c2f/vision/segmentation/kmeans.hpp"

#include <algorithm>
#include <limits>
#include <random>
#include <stdexcept>

namespace c2f::vision {

namespace {

/// The nearest centre of p and its squared distance.
std::pair<int, double> nearest(const Eigen::Vector3d& p,
                               const std::vector<Eigen::Vector3d>& centres) {
  int best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t c = 0; c < centres.size(); ++c) {
    const double distance = (p - centres[c]).squaredNorm();
    if (distance < best_distance) {
      best_distance = distance;
      best = static_cast<int>(c);
    }
  }
  return {best, best_distance};
}

}  // namespace

KMeansResult kmeans(std::span<const Eigen::Vector3d> points, int k, std::uint64_t seed,
                    int max_iterations) {
  if (k < 1) throw std::invalid_argument("kmeans: k must be >= 1");
  if (points.empty()) throw std::invalid_argument("kmeans: no points");
  const std::size_t n = points.size();
  const auto clusters = std::min<std::size_t>(static_cast<std::size_t>(k), n);
  std::mt19937_64 rng(seed);

  // k-means++ seeding: the first centre uniformly, each next one with probability ~ D^2.
  KMeansResult result;
  result.centres.push_back(points[std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)]);
  std::vector<double> distance(n);
  for (std::size_t i = 0; i < n; ++i) distance[i] = (points[i] - result.centres[0]).squaredNorm();
  while (result.centres.size() < clusters) {
    double total = 0.0;
    for (const double d : distance) total += d;
    std::size_t chosen = 0;
    if (total > 0.0) {
      double target = std::uniform_real_distribution<double>(0.0, total)(rng);
      while (chosen + 1 < n && target >= distance[chosen]) target -= distance[chosen++];
    } else {
      chosen = std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);  // all points equal
    }
    result.centres.push_back(points[chosen]);
    for (std::size_t i = 0; i < n; ++i)
      distance[i] = std::min(distance[i], (points[i] - result.centres.back()).squaredNorm());
  }

  result.assignment.assign(n, -1);
  std::vector<Eigen::Vector3d> sums(clusters);
  std::vector<std::size_t> counts(clusters);
  for (int round = 0; round < max_iterations; ++round) {
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      const auto [c, d] = nearest(points[i], result.centres);
      distance[i] = d;
      if (c != result.assignment[i]) {
        result.assignment[i] = c;
        changed = true;
      }
    }
    if (!changed) break;
    std::fill(sums.begin(), sums.end(), Eigen::Vector3d::Zero());
    std::fill(counts.begin(), counts.end(), 0);
    for (std::size_t i = 0; i < n; ++i) {
      const auto c = static_cast<std::size_t>(result.assignment[i]);
      sums[c] += points[i];
      ++counts[c];
    }
    for (std::size_t c = 0; c < clusters; ++c) {
      if (counts[c] > 0) {
        result.centres[c] = sums[c] / static_cast<double>(counts[c]);
        continue;
      }
      // Empty cluster: the point farthest from its centre becomes a singleton.
      const auto far = static_cast<std::size_t>(std::max_element(distance.begin(), distance.end()) -
                                                distance.begin());
      result.centres[c] = points[far];
      result.assignment[far] = static_cast<int>(c);
      distance[far] = 0.0;
    }
  }
  return result;
}

}  // namespace c2f::vision

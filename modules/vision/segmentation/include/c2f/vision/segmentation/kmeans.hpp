#pragma once
// k-means on 3-D points (colours, colour differences), deterministic for a given seed.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <vector>

namespace c2f::vision {

struct KMeansResult {
  std::vector<Eigen::Vector3d> centres;  ///< k centres (fewer when there are fewer points)
  std::vector<int> assignment;           ///< per point, the index of its nearest centre
};

/// Lloyd's k-means with k-means++ seeding drawn from `seed`, squared Euclidean distance, at
/// most max_iterations rounds (stops earlier when no point changes cluster). An empty cluster
/// takes the point farthest from its centre as a singleton (MATLAB's 'EmptyAction',
/// 'singleton'). k is reduced to the number of points when there are fewer. Throws
/// std::invalid_argument for k < 1 or no points.
KMeansResult kmeans(std::span<const Eigen::Vector3d> points, int k, std::uint64_t seed,
                    int max_iterations = 100);

}  // namespace c2f::vision

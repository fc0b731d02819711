#pragma once
// k-means on 3-D points (colours, colour differences), deterministic for a given seed.

#include <Eigen/Core>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

namespace c2f::vision {

/// How k-means picks its first centres.
enum class KMeansStart {
  sample,     ///< k distinct data points drawn uniformly (MATLAB's 'sample')
  plus_plus,  ///< k-means++: the first uniformly, each next one with probability ~ D^2
};

std::string_view to_string(KMeansStart start);
/// "sample" or "plusplus"; throws std::invalid_argument naming the choices otherwise.
KMeansStart kmeans_start_from_string(std::string_view text);

/// The defaults (k-means++ start, batch rounds only) measured lower pixel errors out of sample
/// than the reference's k-means in the segmentation data preparation, on both coopCuts sets
/// (docs/history/results-2026-11.md, "Parameters chosen on other images"); reference_kmeans()
/// is the released code's.
struct KMeansOptions {
  KMeansStart start = KMeansStart::plus_plus;
  /// After the batch rounds, move single points, in index order cyclically, to the cluster
  /// that lowers the total squared distance most (centres updated after every move), until a
  /// whole pass moves none (MATLAB's online phase).
  bool online_phase = false;
  std::uint64_t seed = 27;
  int max_iterations = 100;  ///< batch rounds plus online passes (MATLAB's MaxIter)
  /// Threads finding each point's nearest centre (0: the machine's cores). The centres are
  /// summed in one thread in index order, so the result is the same for every count.
  int threads = 0;

  bool operator==(const KMeansOptions&) const = default;
};

/// The k-means of the MATLAB the coopCuts code was released with (2012): 'sample' start,
/// batch then online phase. `--kmeans reference` in c2f-segment.
KMeansOptions reference_kmeans(std::uint64_t seed = 27);
/// k-means++ start and batch rounds only. `--kmeans plusplus` in c2f-segment.
KMeansOptions plus_plus_kmeans(std::uint64_t seed = 27);

struct KMeansResult {
  std::vector<Eigen::Vector3d> centres;  ///< k centres (fewer when there are fewer points)
  std::vector<int> assignment;           ///< per point, the index of its centre
};

/// k-means with squared Euclidean distance. Batch rounds: every point goes to its nearest
/// centre (on a tie a point stays in its cluster; in the first round the lowest index wins),
/// then every centre becomes its points' mean; an empty cluster takes the point farthest from
/// its centre as a singleton (MATLAB's 'EmptyAction','singleton'). They stop when no point
/// moves. Then the online phase when `options.online_phase`. k is reduced to the number of
/// points when there are fewer. Throws std::invalid_argument for k < 1, no points or
/// max_iterations < 1.
KMeansResult kmeans(std::span<const Eigen::Vector3d> points, int k, const KMeansOptions& options);

}  // namespace c2f::vision

#include "c2f/vision/segmentation/kmeans.hpp"

#include <algorithm>
#include <limits>
#include <random>
#include <stdexcept>

#include "c2f/support/enum_names.hpp"
#include "c2f/support/parallel_for.hpp"

namespace c2f::vision {

std::string_view to_string(KMeansStart start) {
  return start == KMeansStart::sample ? "sample" : "plusplus";
}

KMeansStart kmeans_start_from_string(std::string_view text) {
  constexpr KMeansStart kAll[] = {KMeansStart::sample, KMeansStart::plus_plus};
  return enum_from_string(text, kAll, "k-means start");
}

KMeansOptions reference_kmeans(std::uint64_t seed) {
  return {KMeansStart::sample, true, seed, 100};
}

KMeansOptions plus_plus_kmeans(std::uint64_t seed) {
  return {KMeansStart::plus_plus, false, seed, 100};
}

namespace {

using Points = std::span<const Eigen::Vector3d>;

/// Points per task of for_ranges.
constexpr std::size_t kRange = 16384;

/// Calls body(begin, end) over consecutive ranges of [0, n) of kRange points, on `threads`
/// threads; each range is one task, so what a task computes does not depend on the count.
template <class Body>
void for_ranges(std::size_t n, int threads, const Body& body) {
  parallel_for((n + kRange - 1) / kRange,
               [&](std::size_t r) { body(r * kRange, std::min(n, (r + 1) * kRange)); }, threads);
}

/// k distinct points drawn uniformly.
std::vector<Eigen::Vector3d> sample_start(Points points, std::size_t k, std::mt19937_64& rng) {
  std::vector<std::size_t> chosen;
  std::uniform_int_distribution<std::size_t> any(0, points.size() - 1);
  while (chosen.size() < k) {
    const std::size_t i = any(rng);
    if (std::find(chosen.begin(), chosen.end(), i) == chosen.end()) chosen.push_back(i);
  }
  std::vector<Eigen::Vector3d> centres;
  for (const std::size_t i : chosen) centres.push_back(points[i]);
  return centres;
}

/// k-means++: the first centre uniformly, each next one with probability ~ D^2.
std::vector<Eigen::Vector3d> plus_plus_start(Points points, std::size_t k, std::mt19937_64& rng,
                                             int threads) {
  const std::size_t n = points.size();
  std::vector<Eigen::Vector3d> centres{
      points[std::uniform_int_distribution<std::size_t>(0, n - 1)(rng)]};
  std::vector<double> distance(n);
  for (std::size_t i = 0; i < n; ++i) distance[i] = (points[i] - centres[0]).squaredNorm();
  while (centres.size() < k) {
    double total = 0.0;
    for (const double d : distance) total += d;
    std::size_t chosen = 0;
    if (total > 0.0) {
      double target = std::uniform_real_distribution<double>(0.0, total)(rng);
      while (chosen + 1 < n && target >= distance[chosen]) target -= distance[chosen++];
    } else {
      chosen = std::uniform_int_distribution<std::size_t>(0, n - 1)(rng);  // all points equal
    }
    centres.push_back(points[chosen]);
    for_ranges(n, threads, [&](std::size_t begin, std::size_t end) {
      for (std::size_t i = begin; i < end; ++i)
        distance[i] = std::min(distance[i], (points[i] - centres.back()).squaredNorm());
    });
  }
  return centres;
}

/// Batch rounds until no point moves or `rounds` are spent; returns the rounds made.
int batch_phase(Points points, KMeansResult& result, int rounds, int threads) {
  const std::size_t n = points.size(), k = result.centres.size();
  std::vector<double> distance(n);
  std::vector<Eigen::Vector3d> sums(k);
  std::vector<std::size_t> counts(k);
  int made = 0;
  while (made < rounds) {
    ++made;
    // Each point's nearest centre (a tie keeps the current cluster), by ranges.
    std::vector<char> range_changed((n + kRange - 1) / kRange, 0);
    for_ranges(n, threads, [&](std::size_t begin, std::size_t end) {
      bool moved = false;
      for (std::size_t i = begin; i < end; ++i) {
        int best = result.assignment[i];
        double best_distance = best >= 0 ? (points[i] - result.centres[best]).squaredNorm()
                                         : std::numeric_limits<double>::infinity();
        for (std::size_t c = 0; c < k; ++c) {
          const double d = (points[i] - result.centres[c]).squaredNorm();
          if (d < best_distance) {  // strictly nearer: a tie keeps the current cluster
            best_distance = d;
            best = static_cast<int>(c);
          }
        }
        distance[i] = best_distance;
        if (best != result.assignment[i]) {
          result.assignment[i] = best;
          moved = true;
        }
      }
      range_changed[begin / kRange] = moved ? 1 : 0;
    });
    const bool changed =
        std::find(range_changed.begin(), range_changed.end(), 1) != range_changed.end();
    if (!changed) break;
    std::fill(sums.begin(), sums.end(), Eigen::Vector3d::Zero());
    std::fill(counts.begin(), counts.end(), 0);
    for (std::size_t i = 0; i < n; ++i) {
      const auto c = static_cast<std::size_t>(result.assignment[i]);
      sums[c] += points[i];
      ++counts[c];
    }
    for (std::size_t c = 0; c < k; ++c) {
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
  return made;
}

/// Single-point moves in index order, cyclically: a point moves to the cluster whose total
/// squared distance it lowers most, counting the centre shifts (a point of a cluster of m
/// costs m/(m-1) |p - c|^2 there and m'/(m'+1) |p - c'|^2 in another of m'), only when that is
/// strictly lower. Ends after a whole pass without a move or after `passes` passes.
void online_phase(Points points, KMeansResult& result, int passes) {
  const std::size_t n = points.size(), k = result.centres.size();
  std::vector<double> counts(k, 0.0);
  for (const int c : result.assignment) counts[static_cast<std::size_t>(c)] += 1.0;
  std::size_t since_move = 0, i = 0;
  for (int pass = 0; pass < passes && since_move < n;) {
    const auto own = static_cast<std::size_t>(result.assignment[i]);
    ++since_move;
    if (counts[own] > 1.0) {
      double best =
          counts[own] / (counts[own] - 1.0) * (points[i] - result.centres[own]).squaredNorm();
      std::size_t target = own;
      for (std::size_t c = 0; c < k; ++c) {
        if (c == own) continue;
        const double cost =
            counts[c] / (counts[c] + 1.0) * (points[i] - result.centres[c]).squaredNorm();
        if (cost < best) {
          best = cost;
          target = c;
        }
      }
      if (target != own) {
        counts[target] += 1.0;
        counts[own] -= 1.0;
        result.centres[target] += (points[i] - result.centres[target]) / counts[target];
        result.centres[own] -= (points[i] - result.centres[own]) / counts[own];
        result.assignment[i] = static_cast<int>(target);
        since_move = 0;
      }
    }
    if (++i == n) {
      i = 0;
      ++pass;
    }
  }
}

}  // namespace

KMeansResult kmeans(Points points, int k, const KMeansOptions& options) {
  if (k < 1) throw std::invalid_argument("kmeans: k must be >= 1");
  if (points.empty()) throw std::invalid_argument("kmeans: no points");
  if (options.max_iterations < 1)
    throw std::invalid_argument("kmeans: max_iterations must be >= 1");
  if (options.threads < 0) throw std::invalid_argument("kmeans: threads must be >= 0");
  const auto clusters = std::min<std::size_t>(static_cast<std::size_t>(k), points.size());
  std::mt19937_64 rng(options.seed);
  KMeansResult result;
  result.centres = options.start == KMeansStart::sample
                       ? sample_start(points, clusters, rng)
                       : plus_plus_start(points, clusters, rng, options.threads);
  result.assignment.assign(points.size(), -1);
  const int rounds = batch_phase(points, result, options.max_iterations, options.threads);
  if (options.online_phase) online_phase(points, result, options.max_iterations - rounds);
  return result;
}

}  // namespace c2f::vision

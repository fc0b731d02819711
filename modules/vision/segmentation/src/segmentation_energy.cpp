#include "c2f/vision/segmentation/segmentation_energy.hpp"

#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "c2f/core/grid.hpp"
#include "c2f/support/memory_need.hpp"
#include "c2f/support/parallel_for.hpp"
#include "c2f/vision/segmentation/colour_gmm.hpp"
#include "c2f/vision/segmentation/kmeans.hpp"

namespace c2f::vision {

namespace {

constexpr double kZeroDifference = 2.2e-16;

Eigen::Vector3d rgb01(const cv::Mat& image, VariableIndex v) {
  const cv::Vec3b bgr = image.at<cv::Vec3b>(static_cast<int>(v));
  return {bgr[2] / 255.0, bgr[1] / 255.0, bgr[0] / 255.0};
}

}  // namespace

SegmentationEdges segmentation_edges(const cv::Mat& image, int num_classes,
                                     const KMeansOptions& kmeans_options) {
  if (image.type() != CV_8UC3) throw std::invalid_argument("segmentation_edges: needs 8-bit BGR");
  if (num_classes < 1) throw std::invalid_argument("segmentation_edges: num_classes must be >= 1");
  SegmentationEdges edges;
  edges.num_classes = num_classes;
  const GridShape shape{static_cast<std::size_t>(image.cols), static_cast<std::size_t>(image.rows)};
  edges.pairs = grid_neighbour_pairs(shape, Connectivity::eight);
  const std::size_t m = edges.pairs.size();
  std::vector<Eigen::Vector3d> differences(m);
  double mean = 0.0;
  for (std::size_t e = 0; e < m; ++e) {
    differences[e] = rgb01(image, edges.pairs[e].first) - rgb01(image, edges.pairs[e].second);
    mean += differences[e].squaredNorm();
  }
  mean /= static_cast<double>(std::max<std::size_t>(m, 1));
  edges.weights.resize(m);
  for (std::size_t e = 0; e < m; ++e) {
    edges.weights[e] =
        mean > 0.0 ? 0.05 + 0.95 * std::exp(-differences[e].squaredNorm() / (2.0 * mean)) : 1.0;
  }
  // Cluster c(u) - c(v) (u's side) and c(v) - c(u) (v's side) of every edge not near zero.
  std::vector<Eigen::Vector3d> points;
  points.reserve(2 * m);
  for (std::size_t e = 0; e < m; ++e) {
    if (differences[e].squaredNorm() < kZeroDifference) continue;
    points.push_back(differences[e]);
    points.push_back(-differences[e]);
  }
  const auto K = static_cast<std::uint32_t>(num_classes);
  edges.u_class.assign(m, K);
  edges.v_class.assign(m, K);
  if (points.empty()) return edges;
  const KMeansResult clusters = kmeans(points, num_classes, kmeans_options);
  edges.class_centres = clusters.centres;
  std::size_t next = 0;
  for (std::size_t e = 0; e < m; ++e) {
    if (differences[e].squaredNorm() < kZeroDifference) continue;
    edges.u_class[e] = static_cast<std::uint32_t>(clusters.assignment[next++]);
    edges.v_class[e] = static_cast<std::uint32_t>(clusters.assignment[next++]);
  }
  return edges;
}

std::vector<double> segmentation_unaries(const SegmentationScene& scene,
                                         const KMeansOptions& kmeans_options) {
  const std::size_t n = scene.image.total();
  const auto L = static_cast<std::size_t>(scene.num_labels());
  std::vector<Eigen::Vector3d> colours(n);
  for (std::size_t i = 0; i < n; ++i)
    colours[i] = rgb01(scene.image, static_cast<VariableIndex>(i));
  std::vector<double> unaries(n * L);
  // One label's colour model per task (each writes its own column; its k-means on one thread).
  KMeansOptions per_label = kmeans_options;
  per_label.threads = 1;
  parallel_for(
      L,
      [&](std::size_t l) {
        std::vector<Eigen::Vector3d> samples;
        for (std::size_t i = 0; i < n; ++i) {
          if (scene.seeds[i] == static_cast<int>(l)) samples.push_back(colours[i]);
        }
        if (samples.empty()) {
          throw std::invalid_argument("segmentation_unaries: label " + std::to_string(l) +
                                      " has no seed pixels");
        }
        const std::vector<double> costs =
            nonnegative_gmm_costs(fit_colour_gmm(samples, 5, per_label), colours);
        for (std::size_t i = 0; i < n; ++i) unaries[i * L + l] = costs[i];
      },
      kmeans_options.threads);
  for (std::size_t i = 0; i < n; ++i) {
    if (scene.seeds[i] == kNoLabel) continue;
    for (std::size_t l = 0; l < L; ++l) {
      if (static_cast<int>(l) != scene.seeds[i]) unaries[i * L + l] = 1000.0;
    }
  }
  for (double& u : unaries) u /= 50.0;
  return unaries;
}

CoopEnergy coop_energy(std::vector<double> unaries, int num_labels, const SegmentationEdges& edges,
                       const CoopParameters& parameters) {
  const std::size_t m = edges.pairs.size();
  const auto K = static_cast<std::uint32_t>(edges.num_classes);
  std::vector<double> totals(K, 0.0);
  std::vector<CoopEdge> coop_edges(m);
  std::vector<ClassWeight> entries(2 * m);
  for (std::size_t e = 0; e < m; ++e) {
    const auto first = static_cast<std::uint32_t>(2 * e);
    coop_edges[e] = {edges.pairs[e].first, edges.pairs[e].second, first, first + 1, first + 2};
    entries[2 * e] = {edges.u_class[e], edges.weights[e]};
    entries[2 * e + 1] = {edges.v_class[e], edges.weights[e]};
    if (edges.u_class[e] < K) totals[edges.u_class[e]] += edges.weights[e];
    if (edges.v_class[e] < K) totals[edges.v_class[e]] += edges.weights[e];
  }
  const std::size_t n = unaries.size() / static_cast<std::size_t>(num_labels);
  return CoopEnergy(n, num_labels, std::move(unaries), edges.num_classes, std::move(totals),
                    parameters, std::move(coop_edges), std::move(entries));
}

std::optional<std::size_t> segmentation_memory_estimate(std::size_t pixels, int labels) {
  if (labels < 0) return std::nullopt;
  const std::optional<std::size_t> per_pixel =
      checked_product({static_cast<std::size_t>(labels), 24});
  if (!per_pixel || *per_pixel > std::numeric_limits<std::size_t>::max() - 1024)
    return std::nullopt;
  return checked_product({pixels, *per_pixel + 1024});
}

SegmentationProblem segmentation_problem(const SegmentationScene& scene,
                                         const CoopParameters& parameters,
                                         const DataPreparation& preparation) {
  require_memory("segmenting " + std::to_string(scene.image.cols) + "x" +
                     std::to_string(scene.image.rows) + " pixels into " +
                     std::to_string(scene.num_labels()) + " labels",
                 segmentation_memory_estimate(scene.image.total(), scene.num_labels()));
  CoopEnergy coop =
      coop_energy(segmentation_unaries(scene, preparation.gmm_kmeans), scene.num_labels(),
                  segmentation_edges(scene.image, preparation.num_classes, preparation.edge_kmeans),
                  parameters);
  PairwiseEnergy potts = potts_energy(coop);
  return {std::move(coop), std::move(potts)};
}

}  // namespace c2f::vision

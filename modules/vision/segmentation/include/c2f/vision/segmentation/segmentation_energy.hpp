#pragma once
// The data terms of cooperative-cut segmentation, as the cooperative-cuts data preparation
// builds them, and the energies made of them.

#include <cstddef>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <utility>
#include <vector>

#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/vision/segmentation/kmeans.hpp"
#include "c2f/vision/segmentation/segmentation_scene.hpp"

namespace c2f::vision {

/// The 8-connected edges of an image with weights and directed colour-difference classes.
/// Each side of an edge is charged the class of its own colour minus the other side's, as the
/// released cooperative-cuts code does (makePairwisePotentials.m: class1 = class of
/// c(first) - c(second), charged to the first pixel's label).
struct SegmentationEdges {
  std::vector<std::pair<VariableIndex, VariableIndex>> pairs;  ///< grid_neighbour_pairs order
  std::vector<double> weights;                                 ///< w per edge
  std::vector<std::uint32_t> u_class;  ///< class of c(u) - c(v), charged to u's label
  std::vector<std::uint32_t> v_class;  ///< class of c(v) - c(u), charged to v's label
  int num_classes = 0;                 ///< K; class K marks near-zero differences
  /// The mean colour difference (own minus other, RGB in [0, 1]) of each class below K; fewer
  /// than K when there are fewer distinct differences than classes.
  std::vector<Eigen::Vector3d> class_centres;
};

/// Edges of an 8-bit BGR image, colours in [0, 1] RGB: w = 0.05 + 0.95 exp(-|dc|^2 /
/// (2 mean |dc|^2)) (mean over all edges; w = 1 on a uniform image); the 2E signed
/// differences, c(u) - c(v) then c(v) - c(u) per edge in edge order, are clustered by k-means
/// into num_classes classes (deterministic for the options' seed); differences with
/// |dc|^2 < 2.2e-16 go to class K.
SegmentationEdges segmentation_edges(const cv::Mat& image, int num_classes = 10,
                                     const KMeansOptions& kmeans_options = {});

/// Unaries (row-major pixels x labels): per label a 5-component colour GMM fitted to its seed
/// pixels (its k-means by `kmeans_options`), the cost of every pixel under it
/// (nonnegative_gmm_costs); a seeded pixel costs 1000 for every other label; everything
/// divided by 50.
std::vector<double> segmentation_unaries(const SegmentationScene& scene,
                                         const KMeansOptions& kmeans_options = {});

/// The cooperative-cut energy of unaries and edges (ground energy: one entry per side).
CoopEnergy coop_energy(std::vector<double> unaries, int num_labels, const SegmentationEdges& edges,
                       const CoopParameters& parameters);

/// Everything segmentation minimises, built once from a scene.
struct SegmentationProblem {
  CoopEnergy coop;
  PairwiseEnergy potts;  ///< the alpha-expansion baseline: potts_energy(coop)
};

/// A lower estimate of the bytes a segmentation of `pixels` pixels and `labels` labels needs:
/// unaries, their GMM fits and the Potts copy (3 x 8 bytes per pixel and label), the 8-connected
/// edges of both energies and one QPBO move graph (~1 KiB per pixel). std::nullopt on overflow.
std::optional<std::size_t> segmentation_memory_estimate(std::size_t pixels, int labels);

/// How the data preparation clusters: the number of edge classes and its two k-means runs.
/// The reference seeded its edge classes' k-means with 27 (of MATLAB's own random stream,
/// which ours does not reproduce) and left its GMMs' unseeded, so its unaries were one random
/// draw; ours are seeded, 27 by default.
struct DataPreparation {
  int num_classes = 10;       ///< K
  KMeansOptions gmm_kmeans;   ///< starts each label's colour GMM (segmentation_unaries)
  KMeansOptions edge_kmeans;  ///< clusters the colour differences (segmentation_edges)

  bool operator==(const DataPreparation&) const = default;
};

/// Builds both energies from the scene. Throws std::invalid_argument when the problem needs
/// more memory than is available (require_memory with segmentation_memory_estimate, checked
/// before anything is allocated).
SegmentationProblem segmentation_problem(const SegmentationScene& scene,
                                         const CoopParameters& parameters,
                                         const DataPreparation& preparation = {});

}  // namespace c2f::vision

#pragma once
// TSGO's "one iteration of message passing on the fully connected MRF": a normalised
// cross-bilateral filter of every cost slice, guided by the view's colour image, computed on a
// coarse spatial grid per colour cluster (the last stage of TSGO's step 1). Internal to the
// stereo library (not installed): the public entry point is tsgo_cost / tsgo_problem.

#include <opencv2/core.hpp>
#include <vector>

#include "c2f/vision/stereo/cost_volume.hpp"
#include "c2f/vision/stereo/tsgo_energy.hpp"

namespace c2f::vision {

struct ColourClusters {
  std::vector<int> cluster_of;   ///< per pixel (y * width + x)
  std::vector<cv::Vec3d> means;  ///< per cluster, BGR; clusters without members are empty
  std::vector<int> sizes;        ///< members per cluster
};

/// Median-cut colour quantisation into 2^levels clusters: level l splits every cluster at the
/// median of channel (l + 1) mod 3 (B = 0, G = 1, R = 2: G, R, B, G, ...). The members of a
/// cluster are ordered by that channel, stably (raster order among equal values), and split
/// into halves by count, so pixels equal to the median are divided in raster order. Cluster
/// colour = mean of its members. Each level is one counting sort of every pixel by (cluster,
/// value), linear in the pixels; the new cluster of each member is written on `threads` threads
/// (0: the machine's cores), and the clusters are the same for every count. Throws
/// std::invalid_argument for an empty or non-8-bit 3-channel image or levels outside [0, 20].
ColourClusters median_cut_clusters(const cv::Mat& image, int levels, int threads = 0);

/// Filters every cost slice in place: each pixel splats its cost (and a unit weight)
/// bilinearly into the 4 surrounding grid nodes of its colour cluster; the grids are blurred
/// along y then x with taps [e^-2, e^-1/2, 1, e^-1/2, e^-2]; within each node, cluster q
/// gathers the clusters q' with |mu_q - mu_q'| <= cutoff * sigma with weight
/// exp(-r^2 / (2 sigma^2)), r = round(|mu_q - mu_q'|); each pixel then reads its cluster's
/// bilinear interpolation back and divides by the interpolated weight. The grid's values and
/// arithmetic are float (weights, taps and range weights rounded to float; the quotient of two
/// floats rounded once), so a constant slice stays constant to a few float roundings, and the
/// volume is within about 1e-6 relative of the same filter in double. Only the grid entries the
/// result reads are stored and computed (per node, the clusters splatted there and those the
/// blurs and the range mixing carry them to), 16 labels at a time side by side, in two buffers
/// of entries (64 bytes each, 3-9 entries per pixel in all on Middlebury, KITTI, Aloe and a
/// pair of noise images). options.threads threads share each block of labels, each pass split
/// between them; each holds one grid node's entries of its own. Every value is the dense float
/// grid's, bit for bit, whatever the thread count. Throws std::invalid_argument when the guide
/// does not match the volume.
void cross_bilateral_filter(CostVolume& volume, const cv::Mat& guide,
                            const BilateralOptions& options = {});

}  // namespace c2f::vision

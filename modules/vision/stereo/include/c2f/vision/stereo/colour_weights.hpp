#pragma once
// Edge weights from colour differences, as TSGO's second step uses them.

#include <array>
#include <opencv2/core.hpp>

#include "c2f/core/labeling.hpp"

namespace c2f::vision {

/// TSGO's three pairwise weights, for similar, nearby and different colours.
inline constexpr std::array<double, 3> kTsgoWeights{0.3125, 0.15625, 0.125};
/// The L1 colour differences D = |dR| + |dG| + |dB| below which the first two weights apply.
inline constexpr std::array<int, 2> kTsgoWeightBounds{7, 15};

/// TSGO's pairwise weight for two pixels of an 8-bit colour image, by the L1 colour difference
/// D (0..765): kTsgoWeights[0] (0.3125) if D < 7, [1] (0.15625) if D < 15, else [2] (0.125).
/// Pixels are v = y * width + x.
double tsgo_edge_weight(const cv::Mat& image, VariableIndex u, VariableIndex v);

}  // namespace c2f::vision

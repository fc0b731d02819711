#pragma once
// Edge weights from colour differences, as TSGO's second step uses them.

#include <opencv2/core.hpp>

#include "c2f/core/labeling.hpp"

namespace c2f::vision {

/// TSGO's pairwise weight for two pixels of an 8-bit colour image, by the L1 colour difference
/// D = |dR| + |dG| + |dB| (0..765): 0.3125 if D < 7, 0.15625 if D < 15, else 0.125.
/// Pixels are v = y * width + x.
double tsgo_edge_weight(const cv::Mat& image, VariableIndex u, VariableIndex v);

}  // namespace c2f::vision

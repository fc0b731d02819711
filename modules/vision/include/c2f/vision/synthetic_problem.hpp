#pragma once
// A synthetic labeling problem with known answer: a piecewise-constant label image seen
// through Gaussian noise, restored with a truncated-quadratic unary and a truncated-linear
// smoothness term on the 4-connected grid: the problem of c2f-synthetic, the driver's smallest
// demo. Its error is pixel_error (c2f/vision/segmentation/segmentation_io.hpp).

#include <cstdint>
#include <span>
#include <string>

#include "c2f/core/grid.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::vision {

struct SyntheticSpec {
  GridShape shape{160, 120};
  int num_labels = 16;
  int num_shapes = 12;       ///< rectangles and discs painted over the background
  double noise_sigma = 3.0;  ///< in label units
  double smoothness = 4.0;   ///< weight of the truncated-linear term
  double truncation = 2.0;   ///< of the truncated-linear term
  std::uint64_t seed = 7;
};

struct SyntheticProblem {
  Labeling truth;
  PairwiseEnergy energy;
};

/// Throws std::invalid_argument naming the field when the spec is unusable.
SyntheticProblem make_synthetic_problem(const SyntheticSpec& spec);

/// Writes the labeling as an 8-bit binary PGM, labels scaled to 0..255. Throws
/// std::runtime_error naming the path on failure.
void write_label_pgm(const std::string& path, std::span<const Label> labeling, GridShape shape,
                     int num_labels);

}  // namespace c2f::vision

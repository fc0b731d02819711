#pragma once
// The tiny models the solver black-box tests run on: 3x3 and 2x4 grids and random graphs with
// 2 to 4 labels and every term kind.

#include <vector>

#include "c2f/core/grid.hpp"
#include "random_models.hpp"

namespace c2f::test {

/// A tiny grid or random-graph energy with the given term and non-negative weights in [0, 3).
PairwiseEnergy tiny_model(Rng& rng, int shape, int num_labels, const PairwiseTerm& term);

/// The terms the tests cycle through for num_labels labels: Potts, truncated linear, TSGO step,
/// and a random symmetric table with zero diagonal (a semi-metric).
std::vector<PairwiseTerm> test_terms(Rng& rng, int num_labels);

}  // namespace c2f::test

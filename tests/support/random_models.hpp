#pragma once
// Random small energies and partitions for property tests, and brute-force minimisation.

#include <cstdint>
#include <random>
#include <vector>

#include "c2f/cooperative/coop_energy.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/dense_partition.hpp"

namespace c2f::test {

using Rng = std::mt19937_64;

/// A random pairwise energy with num_variables variables and num_labels labels: random
/// unaries in [-5, 5), random edges (duplicates and both orientations allowed) with weights in
/// [0, 3), and terms of every kind (Potts, truncated linear, TSGO step, symmetric and
/// asymmetric tables with non-zero diagonals).
PairwiseEnergy random_energy(Rng& rng, std::size_t num_variables, int num_labels,
                             std::size_t num_edges);

/// A random energy on a width x height 4-connected grid with one random term kind.
PairwiseEnergy random_grid_energy(Rng& rng, std::size_t width, std::size_t height, int num_labels);

/// A random partition of num_variables variables into at most max_groups groups.
DensePartition random_partition(Rng& rng, std::size_t num_variables, std::size_t max_groups);

/// A random refinement of `coarse`: every group is split into up to `max_split` parts.
DensePartition random_refinement(Rng& rng, const DensePartition& coarse, std::size_t max_split);

/// A uniformly random labeling.
Labeling random_labeling(Rng& rng, std::size_t num_variables, int num_labels);

/// A random ground cooperative-cut energy on a w x h 8-connected grid: unaries in [0, 2),
/// edge weights in [0.05, 1), each side's class drawn from 0..num_classes (K, linear, included).
CoopEnergy random_coop_energy(Rng& rng, std::size_t w, std::size_t h, int num_labels,
                              int num_classes, CoopParameters parameters = {1.5, 0.05, 0.0});

struct BruteForceResult {
  double energy;
  Labeling labeling;
};

/// The exact minimum by enumerating all num_labels^num_variables labelings (keep it small).
BruteForceResult brute_force_minimum(const PairwiseEnergy& energy);

/// |a - b| <= relative * max(1, |a|, |b|).
bool close_relative(double a, double b, double relative);

}  // namespace c2f::test

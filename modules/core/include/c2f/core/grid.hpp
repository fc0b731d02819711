#pragma once
// Builders for pairwise energies on image grids (pixel v = y * width + x).

#include <cstddef>
#include <functional>
#include <span>
#include <string_view>
#include <utility>
#include <vector>

#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

enum class Connectivity { four = 4, eight = 8 };

struct GridShape {
  std::size_t width = 0;
  std::size_t height = 0;
  [[nodiscard]] std::size_t size() const noexcept { return width * height; }
};

/// Throws std::invalid_argument "<who>: the <what> has N variables, the WxH grid has M pixels"
/// unless num_variables == shape.size(): the one check of anything laid on a grid.
void require_grid_size(std::size_t num_variables, GridShape shape, std::string_view who,
                       std::string_view what = "energy");

/// The neighbour pairs (u, v) of a grid in raster order of u: for each pixel its right and
/// down neighbours, then for 8-connectivity its down-right and down-left neighbours.
/// Throws std::invalid_argument for an empty grid or one too large for VariableIndex.
std::vector<std::pair<VariableIndex, VariableIndex>> grid_neighbour_pairs(
    GridShape shape, Connectivity connectivity);

/// The edges of a grid energy with one shared term (term index 0), in grid_neighbour_pairs
/// order, edge (u, v) weighing weight(u, v). Throws as grid_neighbour_pairs.
std::vector<Edge> grid_edges(GridShape shape, Connectivity connectivity,
                             const std::function<double(VariableIndex, VariableIndex)>& weight);

/// A grid energy with one shared term; edge i (in grid_neighbour_pairs order) has weight
/// edge_weights[i]. Throws std::invalid_argument when the sizes do not match.
PairwiseEnergy make_grid_energy(GridShape shape, Connectivity connectivity, int num_labels,
                                std::vector<double> unaries, PairwiseTerm term,
                                std::span<const double> edge_weights);

/// As above with the weight of edge (u, v) given by weight(u, v).
PairwiseEnergy make_grid_energy(GridShape shape, Connectivity connectivity, int num_labels,
                                std::vector<double> unaries, PairwiseTerm term,
                                const std::function<double(VariableIndex, VariableIndex)>& weight);

}  // namespace c2f

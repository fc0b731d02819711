#include "c2f/core/grid.hpp"

#include <limits>
#include <stdexcept>
#include <string>

namespace c2f {

void require_grid_size(std::size_t num_variables, GridShape shape, std::string_view who,
                       std::string_view what) {
  if (num_variables == shape.size()) return;
  throw std::invalid_argument(std::string(who) + ": the " + std::string(what) + " has " +
                              std::to_string(num_variables) + " variables, the " +
                              std::to_string(shape.width) + "x" + std::to_string(shape.height) +
                              " grid has " + std::to_string(shape.size()) + " pixels");
}

std::vector<std::pair<VariableIndex, VariableIndex>> grid_neighbour_pairs(
    GridShape shape, Connectivity connectivity) {
  if (shape.width == 0 || shape.height == 0) {
    throw std::invalid_argument("grid: width and height must be >= 1, got " +
                                std::to_string(shape.width) + "x" + std::to_string(shape.height));
  }
  if (shape.size() / shape.width != shape.height ||
      shape.size() > std::numeric_limits<VariableIndex>::max()) {
    throw std::invalid_argument("grid: " + std::to_string(shape.width) + "x" +
                                std::to_string(shape.height) +
                                " pixels do not fit a 32-bit variable index");
  }
  const std::size_t w = shape.width;
  const std::size_t h = shape.height;
  const bool eight = connectivity == Connectivity::eight;
  std::vector<std::pair<VariableIndex, VariableIndex>> pairs;
  pairs.reserve(shape.size() * (eight ? 4 : 2));
  auto add = [&pairs](std::size_t a, std::size_t b) {
    pairs.emplace_back(static_cast<VariableIndex>(a), static_cast<VariableIndex>(b));
  };
  for (std::size_t y = 0; y < h; ++y) {
    for (std::size_t x = 0; x < w; ++x) {
      const std::size_t v = y * w + x;
      if (x + 1 < w) add(v, v + 1);
      if (y + 1 < h) add(v, v + w);
      if (eight && y + 1 < h) {
        if (x + 1 < w) add(v, v + w + 1);
        if (x > 0) add(v, v + w - 1);
      }
    }
  }
  return pairs;
}

PairwiseEnergy make_grid_energy(GridShape shape, Connectivity connectivity, int num_labels,
                                std::vector<double> unaries, PairwiseTerm term,
                                std::span<const double> edge_weights) {
  const auto pairs = grid_neighbour_pairs(shape, connectivity);
  if (edge_weights.size() != pairs.size()) {
    throw std::invalid_argument("make_grid_energy: edge_weights has " +
                                std::to_string(edge_weights.size()) + " entries, the " +
                                std::to_string(shape.width) + "x" + std::to_string(shape.height) +
                                " grid has " + std::to_string(pairs.size()) + " edges");
  }
  std::vector<Edge> edges(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    edges[i] = Edge{pairs[i].first, pairs[i].second, edge_weights[i], 0};
  }
  return PairwiseEnergy(shape.size(), num_labels, std::move(unaries), {std::move(term)},
                        std::move(edges));
}

std::vector<Edge> grid_edges(GridShape shape, Connectivity connectivity,
                             const std::function<double(VariableIndex, VariableIndex)>& weight) {
  const auto pairs = grid_neighbour_pairs(shape, connectivity);
  std::vector<Edge> edges(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    edges[i] = Edge{pairs[i].first, pairs[i].second, weight(pairs[i].first, pairs[i].second), 0};
  }
  return edges;
}

PairwiseEnergy make_grid_energy(GridShape shape, Connectivity connectivity, int num_labels,
                                std::vector<double> unaries, PairwiseTerm term,
                                const std::function<double(VariableIndex, VariableIndex)>& weight) {
  return PairwiseEnergy(shape.size(), num_labels, std::move(unaries), {std::move(term)},
                        grid_edges(shape, connectivity, weight));
}

}  // namespace c2f

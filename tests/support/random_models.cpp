#include "random_models.hpp"

#include "c2f/core/grid.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "c2f/core/grid.hpp"

namespace c2f::test {

namespace {

PairwiseTerm random_term(Rng& rng, int num_labels) {
  std::uniform_int_distribution<int> kind(0, 4);
  std::uniform_real_distribution<double> cost(-1.0, 2.0);
  switch (kind(rng)) {
    case 0:
      return PairwiseTerm::potts();
    case 1:
      return PairwiseTerm::truncated_linear(std::uniform_real_distribution<double>(0.5, 3.0)(rng));
    case 2:
      return PairwiseTerm::tsgo_step();
    case 3: {  // symmetric table with a non-zero diagonal
      std::vector<double> table(static_cast<std::size_t>(num_labels * num_labels));
      for (int a = 0; a < num_labels; ++a) {
        for (int b = a; b < num_labels; ++b) {
          table[a * num_labels + b] = table[b * num_labels + a] = cost(rng);
        }
      }
      return PairwiseTerm::table(num_labels, std::move(table));
    }
    default: {  // asymmetric table
      std::vector<double> table(static_cast<std::size_t>(num_labels * num_labels));
      for (double& c : table) c = cost(rng);
      return PairwiseTerm::table(num_labels, std::move(table));
    }
  }
}

std::vector<double> random_unaries(Rng& rng, std::size_t n, int num_labels) {
  std::uniform_real_distribution<double> unary(-5.0, 5.0);
  std::vector<double> unaries(n * static_cast<std::size_t>(num_labels));
  for (double& u : unaries) u = unary(rng);
  return unaries;
}

}  // namespace

PairwiseEnergy random_energy(Rng& rng, std::size_t num_variables, int num_labels,
                             std::size_t num_edges) {
  if (num_variables < 2) throw std::invalid_argument("random_energy: need >= 2 variables");
  std::vector<PairwiseTerm> terms;
  const int num_terms = std::uniform_int_distribution<int>(1, 3)(rng);
  for (int t = 0; t < num_terms; ++t) terms.push_back(random_term(rng, num_labels));
  std::uniform_int_distribution<VariableIndex> variable(
      0, static_cast<VariableIndex>(num_variables - 1));
  std::uniform_real_distribution<double> weight(0.0, 3.0);
  std::uniform_int_distribution<std::uint32_t> term(0, static_cast<std::uint32_t>(num_terms - 1));
  std::vector<Edge> edges;
  while (edges.size() < num_edges) {
    const VariableIndex u = variable(rng);
    const VariableIndex v = variable(rng);
    if (u != v) edges.push_back(Edge{u, v, weight(rng), term(rng)});
  }
  return PairwiseEnergy(num_variables, num_labels, random_unaries(rng, num_variables, num_labels),
                        std::move(terms), std::move(edges));
}

PairwiseEnergy random_grid_energy(Rng& rng, std::size_t width, std::size_t height, int num_labels) {
  std::uniform_real_distribution<double> weight(0.0, 3.0);
  const GridShape shape{width, height};
  return make_grid_energy(
      shape, Connectivity::four, num_labels, random_unaries(rng, shape.size(), num_labels),
      random_term(rng, num_labels), [&](VariableIndex, VariableIndex) { return weight(rng); });
}

DensePartition random_partition(Rng& rng, std::size_t num_variables, std::size_t max_groups) {
  const std::size_t groups = std::uniform_int_distribution<std::size_t>(1, max_groups)(rng);
  std::uniform_int_distribution<int> id(0, static_cast<int>(groups) - 1);
  std::vector<int> ids(num_variables);
  for (int& i : ids) i = id(rng);
  return DensePartition::from_ids(ids);
}

DensePartition random_refinement(Rng& rng, const DensePartition& coarse, std::size_t max_split) {
  std::uniform_int_distribution<std::int64_t> part(0, static_cast<std::int64_t>(max_split) - 1);
  std::vector<std::int64_t> ids(coarse.num_variables());
  for (std::size_t v = 0; v < ids.size(); ++v) {
    ids[v] = static_cast<std::int64_t>(coarse.group_of(v)) * static_cast<std::int64_t>(max_split) +
             part(rng);
  }
  return DensePartition::from_ids(ids);
}

Labeling random_labeling(Rng& rng, std::size_t num_variables, int num_labels) {
  std::uniform_int_distribution<Label> label(0, num_labels - 1);
  Labeling labeling(num_variables);
  for (Label& l : labeling) l = label(rng);
  return labeling;
}

BruteForceResult brute_force_minimum(const PairwiseEnergy& energy) {
  const std::size_t n = energy.num_variables();
  const int num_labels = energy.num_labels();
  Labeling current(n, 0);
  BruteForceResult best{energy.evaluate(current), current};
  while (true) {
    std::size_t v = 0;
    while (v < n && ++current[v] == num_labels) current[v++] = 0;
    if (v == n) break;
    const double e = energy.evaluate_unchecked(current);
    if (e < best.energy) best = {e, current};
  }
  return best;
}

bool close_relative(double a, double b, double relative) {
  return std::abs(a - b) <= relative * std::max({1.0, std::abs(a), std::abs(b)});
}

CoopEnergy random_coop_energy(Rng& rng, std::size_t w, std::size_t h, int num_labels,
                              int num_classes, CoopParameters parameters) {
  std::uniform_real_distribution<double> unary(0.0, 2.0), weight(0.05, 1.0);
  std::uniform_int_distribution<int> edge_class(0, num_classes);
  const std::size_t n = w * h;
  std::vector<double> unaries(n * static_cast<std::size_t>(num_labels));
  for (double& u : unaries) u = unary(rng);
  std::vector<CoopEdge> edges;
  std::vector<ClassWeight> entries;
  std::vector<double> totals(static_cast<std::size_t>(num_classes), 0.0);
  for (const auto& [u, v] : grid_neighbour_pairs({w, h}, Connectivity::eight)) {
    const auto first = static_cast<std::uint32_t>(entries.size());
    const double w_e = weight(rng);
    for (int side = 0; side < 2; ++side) {
      const auto c = static_cast<std::uint32_t>(edge_class(rng));
      entries.push_back({c, w_e});
      if (c < static_cast<std::uint32_t>(num_classes)) totals[c] += w_e;
    }
    edges.push_back({u, v, first, first + 1, first + 2});
  }
  return CoopEnergy(n, num_labels, std::move(unaries), num_classes, std::move(totals), parameters,
                    std::move(edges), std::move(entries));
}

}  // namespace c2f::test

#include "tiny_models.hpp"

namespace c2f::test {

PairwiseEnergy tiny_model(Rng& rng, int shape, int num_labels, const PairwiseTerm& term) {
  std::uniform_real_distribution<double> unary(-2.0, 4.0);
  std::uniform_real_distribution<double> weight(0.0, 3.0);
  std::vector<std::pair<VariableIndex, VariableIndex>> pairs;
  std::size_t n = 0;
  if (shape == 0) {
    n = 9;
    pairs = grid_neighbour_pairs({3, 3}, Connectivity::four);
  } else if (shape == 1) {
    n = 8;
    pairs = grid_neighbour_pairs({2, 4}, Connectivity::four);
  } else {
    n = 7;
    std::uniform_int_distribution<VariableIndex> node(0, 6);
    while (pairs.size() < 12) {
      const VariableIndex a = node(rng), b = node(rng);
      if (a != b) pairs.emplace_back(a, b);
    }
  }
  std::vector<double> unaries(n * static_cast<std::size_t>(num_labels));
  for (double& u : unaries) u = unary(rng);
  std::vector<Edge> edges;
  for (const auto& [a, b] : pairs) edges.push_back(Edge{a, b, weight(rng), 0});
  return PairwiseEnergy(n, num_labels, std::move(unaries), {term}, std::move(edges));
}

std::vector<PairwiseTerm> test_terms(Rng& rng, int num_labels) {
  std::uniform_real_distribution<double> cost(0.1, 2.0);
  std::vector<double> table(static_cast<std::size_t>(num_labels * num_labels), 0.0);
  for (int a = 0; a < num_labels; ++a) {
    for (int b = a + 1; b < num_labels; ++b)
      table[a * num_labels + b] = table[b * num_labels + a] = cost(rng);
  }
  return {PairwiseTerm::potts(), PairwiseTerm::truncated_linear(1.5), PairwiseTerm::tsgo_step(),
          PairwiseTerm::table(num_labels, std::move(table))};
}

}  // namespace c2f::test

#include "c2f/lift/reduce.hpp"

#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace c2f {

namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

bool has_nonzero_diagonal(const PairwiseTerm& term, int num_labels) {
  for (Label l = 0; l < num_labels; ++l) {
    if (term.cost(l, l) != 0.0) return true;
  }
  return false;
}

}  // namespace

PairwiseEnergy reduce(const PairwiseEnergy& energy, const GroupIds& partition) {
  if (partition.num_variables() != energy.num_variables()) {
    throw std::invalid_argument(
        "reduce: the partition has " + std::to_string(partition.num_variables()) +
        " variables, the energy has " + std::to_string(energy.num_variables()));
  }
  const std::size_t num_groups = partition.num_groups();
  const int num_labels = energy.num_labels();
  const auto L = static_cast<std::size_t>(num_labels);
  const auto terms = energy.terms();
  const auto edges = energy.edges();

  // Unaries: sum of member rows.
  std::vector<double> unaries(num_groups * L, 0.0);
  energy.unaries().visit([&](auto costs) {
    for (std::size_t v = 0; v < energy.num_variables(); ++v) {
      const auto row = costs.subspan(v * L, L);
      double* target = unaries.data() + static_cast<std::size_t>(partition[v]) * L;
      for (std::size_t l = 0; l < L; ++l) target[l] += static_cast<double>(row[l]);
    }
  });

  std::vector<char> term_symmetric(terms.size());
  std::vector<char> term_diagonal(terms.size());
  for (std::size_t t = 0; t < terms.size(); ++t) {
    term_symmetric[t] = terms[t].is_symmetric();
    term_diagonal[t] = has_nonzero_diagonal(terms[t], num_labels);
  }

  // Orient each inter-group edge as (first, second) and bucket it by `first` (counting sort).
  std::vector<std::uint32_t> bucket_start(num_groups + 1, 0);
  std::vector<std::pair<VariableIndex, VariableIndex>> oriented(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    const Edge& e = edges[i];
    VariableIndex a = partition[e.u];
    VariableIndex b = partition[e.v];
    if (a == b) {
      if (term_diagonal[e.term]) {
        double* target = unaries.data() + static_cast<std::size_t>(a) * L;
        for (Label l = 0; l < num_labels; ++l) target[l] += energy.pairwise_cost(e, l, l);
      }
      oriented[i] = {kNone, kNone};
      continue;
    }
    if (term_symmetric[e.term] && a > b) std::swap(a, b);
    oriented[i] = {a, b};
    ++bucket_start[a + 1];
  }
  for (std::size_t g = 0; g < num_groups; ++g) bucket_start[g + 1] += bucket_start[g];
  std::vector<std::uint32_t> order(bucket_start[num_groups]);
  {
    std::vector<std::uint32_t> cursor(bucket_start.begin(), bucket_start.end() - 1);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      if (oriented[i].first != kNone)
        order[cursor[oriented[i].first]++] = static_cast<std::uint32_t>(i);
    }
  }

  // Merge per (first, second, term): for the current `first`, stamp[second] marks the head of
  // a chain of output edges with that second endpoint (one per term seen).
  std::vector<Edge> merged;
  merged.reserve(order.size());
  std::vector<std::uint32_t> chain_next;
  chain_next.reserve(order.size());
  std::vector<std::uint32_t> stamp(num_groups, kNone);
  std::vector<std::uint32_t> head(num_groups, kNone);
  for (std::size_t a = 0; a < num_groups; ++a) {
    for (std::uint32_t k = bucket_start[a]; k < bucket_start[a + 1]; ++k) {
      const Edge& e = edges[order[k]];
      const VariableIndex b = oriented[order[k]].second;
      if (stamp[b] != a) {
        stamp[b] = static_cast<std::uint32_t>(a);
        head[b] = kNone;
      }
      std::uint32_t found = head[b];
      while (found != kNone && merged[found].term != e.term) found = chain_next[found];
      if (found != kNone) {
        merged[found].weight += e.weight;
      } else {
        chain_next.push_back(head[b]);
        head[b] = static_cast<std::uint32_t>(merged.size());
        merged.push_back(Edge{static_cast<VariableIndex>(a), b, e.weight, e.term});
      }
    }
  }

  return PairwiseEnergy(num_groups, num_labels, std::move(unaries),
                        std::vector<PairwiseTerm>(terms.begin(), terms.end()), std::move(merged));
}

}  // namespace c2f

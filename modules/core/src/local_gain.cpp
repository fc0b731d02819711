#include "c2f/core/local_gain.hpp"

#include <algorithm>
#include <bit>
#include <cstdlib>
#include <stdexcept>
#include <string>
#include <vector>

namespace c2f {

namespace {

/// Adds weight * cost(l, other) (or cost(other, l) when the variable is the edge's v) for every
/// label l to costs: the term's kind is decided once per edge, not per label.
void add_edge_costs(const PairwiseTerm& term, double weight, Label other, bool variable_first,
                    std::span<double> costs) {
  const auto L = static_cast<Label>(costs.size());
  switch (term.kind()) {
    case TermKind::potts:
      for (Label l = 0; l < L; ++l) costs[static_cast<std::size_t>(l)] += weight;
      costs[static_cast<std::size_t>(other)] -= weight;
      return;
    case TermKind::table: {
      const std::vector<double>& table = term.table_costs();
      const auto n = static_cast<std::size_t>(L);
      const auto b = static_cast<std::size_t>(other);
      for (std::size_t l = 0; l < n; ++l)
        costs[l] += weight * (variable_first ? table[l * n + b] : table[b * n + l]);
      return;
    }
    case TermKind::truncated_linear: {
      const double truncation = term.truncation();
      for (Label l = 0; l < L; ++l) {
        const double distance = std::abs(l - other);
        costs[static_cast<std::size_t>(l)] +=
            weight * (distance < truncation ? distance : truncation);
      }
      return;
    }
    case TermKind::tsgo_step:
      for (Label l = 0; l < L; ++l) costs[static_cast<std::size_t>(l)] += weight;
      for (Label l = std::max(0, other - 1); l <= std::min(L - 1, other + 1); ++l)
        costs[static_cast<std::size_t>(l)] -= weight * (l == other ? 1.0 : 5.0 / 6.0);
      return;
  }
}

}  // namespace

double local_gain(const PairwiseEnergy& energy, std::span<const Label> labeling,
                  std::size_t max_costs) {
  const std::size_t n = energy.num_variables();
  const auto L = static_cast<std::size_t>(energy.num_labels());
  if (labeling.size() != n) {
    throw std::invalid_argument("local_gain: the labeling has " + std::to_string(labeling.size()) +
                                " labels, the energy " + std::to_string(n) + " variables");
  }
  for (std::size_t v = 0; v < n; ++v) {
    if (labeling[v] < 0 || static_cast<std::size_t>(labeling[v]) >= L) {
      throw std::invalid_argument("local_gain: variable " + std::to_string(v) + " has label " +
                                  std::to_string(labeling[v]) + ", outside [0, " +
                                  std::to_string(L - 1) + "]");
    }
  }
  if (n == 0) return 0.0;
  std::size_t stride = 1;
  if (max_costs > 0 && n * L > max_costs)
    stride = std::bit_ceil((n * L + max_costs - 1) / max_costs);
  const std::size_t skip = stride - 1;                    // v is visited when v & skip is 0
  const std::size_t visited = (n + stride - 1) / stride;  // variables 0, stride, 2 stride, ...
  std::vector<double> costs(visited * L);
  for (std::size_t i = 0; i < visited; ++i)
    for (std::size_t l = 0; l < L; ++l)
      costs[i * L + l] = energy.unary(i * stride, static_cast<Label>(l));
  const auto terms = energy.terms();
  for (const Edge& e : energy.edges()) {
    if ((e.u & skip) == 0) {
      add_edge_costs(terms[e.term], e.weight, labeling[e.v], true,
                     std::span<double>(costs).subspan(e.u / stride * L, L));
    }
    if ((e.v & skip) == 0) {
      add_edge_costs(terms[e.term], e.weight, labeling[e.u], false,
                     std::span<double>(costs).subspan(e.v / stride * L, L));
    }
  }
  double gain = 0.0;
  for (std::size_t i = 0; i < visited; ++i) {
    const double* row = costs.data() + i * L;
    const double current = row[static_cast<std::size_t>(labeling[i * stride])];
    gain += std::max(0.0, current - *std::min_element(row, row + L));
  }
  return gain * static_cast<double>(n) / static_cast<double>(visited);
}

}  // namespace c2f

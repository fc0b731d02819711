#include "c2f/lift/local_grouping.hpp"

#include <bit>
#include <map>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <utility>

#include "c2f/lift/colour_passing.hpp"

namespace c2f {

DensePartition local_grouping(const PairwiseEnergy& energy, GridShape shape, int labels,
                              int iterations) {
  require_grid_size(energy.num_variables(), shape, "local_grouping");
  if (labels < 1 || labels > energy.num_labels()) {
    throw std::invalid_argument("local_grouping: N_L must be in [1, " +
                                std::to_string(energy.num_labels()) + "]");
  }
  if (iterations < 1) throw std::invalid_argument("local_grouping: N_iter must be >= 1");
  const std::size_t n = shape.size();
  const std::size_t w = shape.width;
  // Edge classes by (term, weight); -1 marks a missing right or down edge.
  std::map<std::pair<std::uint32_t, std::uint64_t>, std::int64_t> class_of;
  std::vector<std::int64_t> right(n, -1), down(n, -1);
  for (const Edge& e : energy.edges()) {
    const VariableIndex a = std::min(e.u, e.v), b = std::max(e.u, e.v);
    const double weight = e.weight == 0.0 ? 0.0 : e.weight;
    const auto cls = class_of
                         .try_emplace({e.term, std::bit_cast<std::uint64_t>(weight)},
                                      static_cast<std::int64_t>(class_of.size()))
                         .first->second;
    if (b == a + 1 && a % w + 1 < w) right[a] = cls;
    if (b == a + w) down[a] = cls;
  }
  std::vector<Label> top(static_cast<std::size_t>(labels));
  std::unordered_map<std::u32string, std::int64_t> ids;
  std::vector<std::int64_t> group(n);
  std::u32string key;
  for (std::size_t v = 0; v < n; ++v) {
    lowest_cost_labels(energy.unaries().row(v), top.size(), top);
    const std::size_t x = v % w, y = v / w;
    const auto owned = static_cast<char32_t>((x + 1 < w) + (y + 1 < shape.height));
    key.assign(top.begin(), top.end());
    key.push_back(owned);
    if (iterations >= 2) {
      auto a = static_cast<char32_t>(right[v] + 1), b = static_cast<char32_t>(down[v] + 1);
      if (a > b) std::swap(a, b);
      key.push_back(a);
      key.push_back(b);
    }
    group[v] = ids.try_emplace(key, static_cast<std::int64_t>(ids.size())).first->second;
  }
  return DensePartition::from_ids(group);
}

}  // namespace c2f

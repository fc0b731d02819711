#pragma once
// For every variable of a pairwise energy, the edges it belongs to (compressed rows): what
// local solvers (ICM, belief propagation) and colour passing walk over.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "c2f/core/huge_page_allocator.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

/// One edge seen from one of its endpoints.
struct Incidence {
  std::uint32_t edge = 0;   ///< index into energy.edges()
  VariableIndex other = 0;  ///< the other endpoint
  bool is_first = false;    ///< this variable is the edge's u (matters for asymmetric terms)
};

class EdgeIncidence {
 public:
  EdgeIncidence() = default;
  /// O(N + E). Incidences of a variable follow the edge order.
  explicit EdgeIncidence(const PairwiseEnergy& energy)
      : EdgeIncidence(energy.num_variables(), energy.edges()) {}

  /// The same for any edge list whose elements have endpoints `u` and `v` (< num_variables).
  template <class EdgeType>
  EdgeIncidence(std::size_t num_variables, std::span<const EdgeType> edges)
      : offsets_(num_variables + 1, 0) {
    for (const EdgeType& e : edges) {
      ++offsets_[e.u + 1];
      ++offsets_[e.v + 1];
    }
    for (std::size_t v = 0; v + 1 < offsets_.size(); ++v) offsets_[v + 1] += offsets_[v];
    incidences_.resize(offsets_.back());
    LargeVector<std::size_t> cursor(offsets_.begin(), offsets_.end() - 1);
    for (std::size_t i = 0; i < edges.size(); ++i) {
      const auto index = static_cast<std::uint32_t>(i);
      incidences_[cursor[edges[i].u]++] = {index, edges[i].v, true};
      incidences_[cursor[edges[i].v]++] = {index, edges[i].u, false};
    }
  }

  [[nodiscard]] std::span<const Incidence> of(std::size_t v) const noexcept {
    return {incidences_.data() + offsets_[v], offsets_[v + 1] - offsets_[v]};
  }

 private:
  LargeVector<std::size_t> offsets_;
  LargeVector<Incidence> incidences_;
};

}  // namespace c2f

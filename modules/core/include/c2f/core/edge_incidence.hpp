#pragma once
// For every variable of a pairwise energy, the edges it belongs to (compressed rows): what
// local solvers (ICM, belief propagation) and colour passing walk over.

#include <cstdint>
#include <span>
#include <vector>

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
  explicit EdgeIncidence(const PairwiseEnergy& energy);

  [[nodiscard]] std::span<const Incidence> of(std::size_t v) const noexcept {
    return {incidences_.data() + offsets_[v], offsets_[v + 1] - offsets_[v]};
  }

 private:
  std::vector<std::size_t> offsets_;
  std::vector<Incidence> incidences_;
};

}  // namespace c2f

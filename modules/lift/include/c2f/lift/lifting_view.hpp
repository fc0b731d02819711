#pragma once
// What the partitions of a schedule read of an energy, whatever its kind: the unary costs, and
// the pairwise factors with their initial colours for colour passing. A pairwise energy gives
// its view here; other energy kinds (the cooperative-cut energy) give theirs beside their type.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "c2f/core/huge_page_allocator.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/core/unary_costs.hpp"

namespace c2f {

/// A pairwise factor of the colour-passing graph.
struct ColourFactor {
  VariableIndex u = 0;
  VariableIndex v = 0;
  std::uint32_t colour = 0;  ///< factors with equal colours start alike
  bool symmetric = true;     ///< endpoints compared as a set (false: in order, u first)
};

struct LiftingView {
  std::size_t num_variables = 0;
  int num_labels = 0;
  UnaryCosts unaries;  ///< row-major num_variables x num_labels, the energy's own
  LargeVector<ColourFactor> factors;
  /// The energy itself when it is a PairwiseEnergy (the reference's local grouping reads its
  /// grid edges); null for other kinds.
  const PairwiseEnergy* pairwise = nullptr;
};

/// A pairwise energy's view: one factor per edge, coloured by its (term, weight) and symmetric
/// as its term. The energy must outlive the view.
LiftingView lifting_view(const PairwiseEnergy& energy);

}  // namespace c2f

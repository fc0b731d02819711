#pragma once
// Internal to ExpansionSolver: the regions its parallel moves solve at once
// (ExpansionOptions::regions). Installed only because the solver templates include it.
//
// A layout cuts the variable indices 0..N-1 into consecutive ranges such that every edge joins
// variables of one range or of two adjacent ranges. Ranges of equal parity (colour) then share
// no edge: with the other colour's variables held at their labels, the binary problem of a move
// over one colour's variables falls apart into one independent problem per range, and solving
// them at once is the exact move over that colour. On a row-major grid the ranges are bands of
// rows. The layout depends on the energy's edges and the requested count only, never on how
// many threads solve it.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// Ranges r = [bounds[r], bounds[r + 1]) of variable indices; region_of[i] is i's range.
struct RegionLayout {
  std::vector<std::size_t> bounds{0};
  std::vector<std::uint16_t> region_of;

  [[nodiscard]] std::size_t count() const noexcept { return bounds.size() - 1; }
};

/// Fewest variables a region of a parallel move holds: smaller problems gain less from a thread
/// than starting it costs.
inline constexpr std::size_t kMinRegionVariables = 4096;

/// The layout of at most `wanted` ranges of about equal size, at least min_variables each (the
/// last one at least half the others), in which every edge joins the same or adjacent ranges.
/// A range extends at least as far as the edges of the range before it reach, so an energy
/// whose edges join far-apart indices gets fewer ranges than wanted, down to one.
[[nodiscard]] inline RegionLayout region_layout(const PairwiseEnergy& energy, std::size_t wanted,
                                                std::size_t min_variables = kMinRegionVariables) {
  const std::size_t n = energy.num_variables();
  RegionLayout layout;
  wanted = std::min<std::size_t>({wanted, n / std::max<std::size_t>(min_variables, 1), 0xffff});
  if (wanted >= 2) {
    // reach[i]: the largest index that a variable at or before i is joined to.
    std::vector<std::size_t> reach(n);
    for (std::size_t i = 0; i < n; ++i) reach[i] = i;
    for (const Edge& edge : energy.edges()) {
      const std::size_t low = std::min(edge.u, edge.v);
      reach[low] = std::max<std::size_t>(reach[low], std::max(edge.u, edge.v));
    }
    for (std::size_t i = 1; i < n; ++i) reach[i] = std::max(reach[i], reach[i - 1]);
    const std::size_t size = (n + wanted - 1) / wanted;
    for (std::size_t end = size; end < n;) {
      layout.bounds.push_back(end);
      end = std::max(end + size, reach[end - 1] + 1);
    }
    // A last range smaller than half the others joins the one before (its edges reach only
    // that one, so the merged range keeps the property).
    if (layout.bounds.size() >= 2 && n - layout.bounds.back() < size / 2) layout.bounds.pop_back();
  }
  layout.bounds.push_back(n);
  layout.region_of.resize(n);
  for (std::size_t r = 0; r < layout.count(); ++r)
    std::fill(layout.region_of.begin() + static_cast<std::ptrdiff_t>(layout.bounds[r]),
              layout.region_of.begin() + static_cast<std::ptrdiff_t>(layout.bounds[r + 1]),
              static_cast<std::uint16_t>(r));
  return layout;
}

}  // namespace c2f::detail

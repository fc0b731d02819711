#pragma once
// Max-flow backend on Boost Graph's boykov_kolmogorov_max_flow (Boost licence): the default.

#include <cstddef>
#include <memory>
#include <span>

#include "c2f/adapters/maxflow/maxflow.hpp"

namespace c2f {

/// Boykov-Kolmogorov max-flow from Boost Graph on a compressed-sparse-row graph built once per
/// topology (terminals are two extra vertices; every arc has its reverse). solve() writes the
/// capacities into preallocated arrays; Boost's algorithm itself allocates its own work arrays
/// (a few O(nodes) vectors) on each call, which its API does not let us reuse.
class BoostMaxFlow {
 public:
  BoostMaxFlow();
  ~BoostMaxFlow();
  BoostMaxFlow(BoostMaxFlow&&) noexcept;
  BoostMaxFlow& operator=(BoostMaxFlow&&) noexcept;

  void build(std::size_t num_nodes, std::span<const FlowEdge> edges);
  /// Throws std::invalid_argument when the capacity arrays do not fit the graph, and
  /// std::logic_error before build().
  double solve(const FlowCapacities& caps);
  [[nodiscard]] bool in_source_set(FlowNode node) const;
  [[nodiscard]] std::size_t num_nodes() const noexcept;
  [[nodiscard]] std::size_t num_edges() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

static_assert(MaxFlow<BoostMaxFlow>);

}  // namespace c2f

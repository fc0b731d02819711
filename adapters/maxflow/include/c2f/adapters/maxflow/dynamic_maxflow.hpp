#pragma once
// Our own max-flow: Boykov-Kolmogorov augmenting paths (PAMI 2004) with dynamic updates
// (Kohli and Torr, "Dynamic graph cuts", PAMI 2007). MIT, like the rest of c2f; the default
// backend of the graph-cut solvers.

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include "c2f/adapters/maxflow/maxflow.hpp"

namespace c2f {

/// What the last solve() did.
struct DynamicSolveStats {
  bool reused = false;            ///< resumed from the previous flow (else from zero flow)
  std::size_t changed_nodes = 0;  ///< nodes whose terminal capacities changed (when reused)
  std::size_t changed_edges = 0;  ///< edges whose capacities changed (when reused)
  std::size_t augmentations = 0;  ///< augmenting paths found
};

/// Boykov-Kolmogorov max-flow on flat arrays (nodes; arcs sorted by tail, each with its
/// reverse), built once per topology; solve() allocates nothing once the work lists have
/// grown to their largest size.
///
/// The first solve() after build() (or forget_flow()) starts from zero flow. Every later
/// solve() keeps the flow and the two search trees of the previous one and applies only the
/// capacities that differ: a changed terminal pair moves the node's residual terminal
/// capacity by the difference of (source - sink), which is a reparametrisation (adding the
/// same amount to both terminal arcs changes every cut by that constant); a changed edge moves
/// its residuals by the capacity change, and flow above a lowered capacity is cancelled and
/// handed to the endpoints' terminal arcs. Tree arcs that lost their residual make orphans,
/// nodes whose terminal residual changed sign change tree, and every touched node is searched
/// again; the search then resumes. The result is a maximum flow of the new capacities: the
/// same minimum cut value as a solve from zero (to floating-point rounding), and the same
/// source set (the nodes reachable from the source in the residual graph) whenever the
/// residuals agree exactly. A re-solve costs in proportion to what changed and to the paths it
/// must find.
class DynamicMaxFlow {
 public:
  DynamicMaxFlow();
  ~DynamicMaxFlow();
  DynamicMaxFlow(DynamicMaxFlow&&) noexcept;
  DynamicMaxFlow& operator=(DynamicMaxFlow&&) noexcept;

  /// Throws std::invalid_argument for an edge with an endpoint >= num_nodes or a loop, or
  /// more than 2^31 arcs.
  void build(std::size_t num_nodes, std::span<const FlowEdge> edges);
  /// Maximum flow value (= minimum cut capacity) for these capacities; see the class comment.
  /// Throws std::invalid_argument when caps do not fit the graph, std::logic_error before
  /// build().
  double solve(const FlowCapacities& caps);
  /// Makes the next solve() start from zero flow.
  void forget_flow() noexcept;
  /// After solve(): whether node is reachable from the source in the residual graph.
  [[nodiscard]] bool in_source_set(FlowNode node) const;
  [[nodiscard]] std::size_t num_nodes() const noexcept;
  [[nodiscard]] std::size_t num_edges() const noexcept;
  [[nodiscard]] const DynamicSolveStats& last_solve() const noexcept;
  /// Bytes held by the graph (excluding the small work lists).
  [[nodiscard]] std::size_t memory_bytes() const noexcept;
  /// memory_bytes() of a graph with this many nodes and edges, before building it.
  [[nodiscard]] static std::size_t memory_bytes_for(std::size_t num_nodes,
                                                    std::size_t num_edges) noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

static_assert(MaxFlow<DynamicMaxFlow>);

/// A MaxFlow backend whose solve() resumes from its previous flow; forget_flow() makes the
/// next solve start afresh. Solvers keep one such graph per recurring problem (recycling).
template <class G>
concept ReusingMaxFlow = MaxFlow<G> && requires(G& g, std::size_t n, std::size_t m) {
  g.forget_flow();
  { G::memory_bytes_for(n, m) } -> std::convertible_to<std::size_t>;
};

}  // namespace c2f

#pragma once
// Our own max-flow: Boykov-Kolmogorov augmenting paths (PAMI 2004) with dynamic updates
// (Kohli and Torr, "Dynamic graph cuts", PAMI 2007). MIT, like the rest of c2f; the default
// backend of the graph-cut solvers.

#include <concepts>
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
  std::size_t arcs_scanned = 0;   ///< arcs the trees' growth examined
};

/// Boykov-Kolmogorov max-flow on flat arrays (nodes; arcs sorted by tail, each with its
/// reverse), built once per topology; a solve allocates nothing once the work lists have grown
/// to their largest size. Copies share the topology (heads, reverse arcs, arc ranges) and own
/// only their flow state, so a copy costs half of what the first graph does.
///
/// solve(caps) starts from zero flow (the MaxFlow contract). A solved graph can then be changed
/// and solved again from its flow and search trees (Kohli and Torr's dynamic graph cuts):
/// change_terminal() moves a node's source - sink capacity difference (adding the same amount
/// to both terminal arcs changes every cut by that constant, so only the difference matters: a
/// reparametrisation), change_edge() moves an edge's capacities, cancelling flow above a
/// lowered capacity and handing it to the endpoints' terminal arcs; resolve() then orphans the
/// tree arcs that lost their residual, moves nodes whose terminal residual changed sign to the
/// other tree, searches every touched node again and resumes. The result is a maximum flow of
/// the changed capacities: the same minimum cut value as a solve from zero (to floating-point
/// rounding), and the same source set (the nodes reachable from the source in the residual
/// graph) whenever the arithmetic is exact. A re-solve costs in proportion to what changed and
/// to the paths it must find. A copy keeps the flow and trees: it resolves from them too.
class DynamicMaxFlow {
 public:
  DynamicMaxFlow();
  ~DynamicMaxFlow();
  DynamicMaxFlow(const DynamicMaxFlow& other);
  /// The same copy, its new memory faulted in on up to `threads` threads (0: every core): a
  /// large graph's copy costs mostly the kernel's zeroing of fresh pages.
  DynamicMaxFlow(const DynamicMaxFlow& other, int threads);
  DynamicMaxFlow& operator=(const DynamicMaxFlow& other);
  DynamicMaxFlow(DynamicMaxFlow&&) noexcept;
  DynamicMaxFlow& operator=(DynamicMaxFlow&&) noexcept;

  /// Throws std::invalid_argument for an edge with an endpoint >= num_nodes or a loop, or
  /// more than 2^31 edges. Builds on up to `threads` threads (0: every core), to the same
  /// graph for every count.
  void build(std::size_t num_nodes, std::span<const FlowEdge> edges, int threads = 1);
  /// Maximum flow value (= minimum cut capacity) from zero flow. Throws std::invalid_argument
  /// when caps do not fit the graph, std::logic_error before build().
  double solve(const FlowCapacities& caps);
  /// solve() without computing the flow value (an O(nodes + edges) pass): for callers that
  /// need only the cut.
  void solve_cut(const FlowCapacities& caps);
  /// Cuts the nodes into parts for the solves in parts: node i in part[i] (parts 0, 1, ... up
  /// to 255). Kept, with each edge's part and the list of edges between parts, until the next
  /// build(); copies share it. Throws std::invalid_argument when part does not have one entry
  /// per node, std::logic_error before build(). Finds the edges' parts on up to `threads`
  /// threads.
  void cut_into_parts(std::span<const std::uint8_t> part, int threads = 1);
  /// The parts cut_into_parts made (1 before it).
  [[nodiscard]] std::size_t num_parts() const noexcept;
  /// solve_cut in two stages, the first on up to `threads` threads (0: every core): each part
  /// solved as a graph of its own with the edges between parts closed, all at once; then those
  /// edges opened and the whole graph solved on from the parts' flows and search trees, which
  /// stay valid (an edge between parts carried no flow). The cut is solve_cut's: the minimum cut
  /// whose source side is what the source reaches in the residual graph, to floating-point
  /// rounding. The result depends on the parts, never on `threads`. With one part: solve_cut.
  /// Throws as solve().
  void solve_cut_in_parts(const FlowCapacities& caps, int threads);
  /// After a solve: adds delta to the node's source capacity minus its sink capacity.
  void change_terminal(FlowNode node, double delta);
  /// After a solve: adds the deltas to the edge's forward and backward capacities (which must
  /// stay >= 0).
  void change_edge(std::size_t edge, double delta_forward, double delta_backward);
  /// After a solve: every change of `terminals` (change_terminal), then of `edges`
  /// (change_edge). With one part, one at a time in that order. Cut into parts, on up to
  /// `threads` threads: the changes sorted by part (by chunks), then each part's terminal
  /// changes and the edge changes inside it on one thread, in their order, then the edge
  /// changes between parts in theirs. The changed graph
  /// and the next resolve_in_parts depend on the parts, never on `threads`. Throws
  /// std::out_of_range for a node or edge the graph does not have (nothing changed then).
  void change_in_parts(std::span<const TerminalChange> terminals, std::span<const EdgeChange> edges,
                       int threads);
  /// After a solve: change_in_parts with the changes already listed by part (ChangesByPart:
  /// a list per part, then the edges between parts), which saves sorting them. Each part's
  /// changes are made on one thread, in their order, each after checking it names a node or
  /// edge of its list's part; then the edges between parts, all checked first. The same graph
  /// as change_in_parts with the lists joined in part order. Throws std::invalid_argument when
  /// the lists do not match num_parts(), or when an edge of the last list is not between parts
  /// (nothing changed then); when a part's list names a node or edge outside the part, throws
  /// std::invalid_argument after the other parts' changes, and the flow is dropped (solve()
  /// again before changing or resolving). With one part: change_in_parts(terminals[0],
  /// edges[0]), and edges[1] must be empty.
  void change_by_parts(const ChangesByPart& changes, int threads);
  /// The minimum cut after the changes since the last solve or resolve, from the current flow.
  void resolve();
  /// resolve() in the two stages of solve_cut_in_parts: the touched nodes of every part searched
  /// on at once (the edges between parts closed, the flow on them kept), then the whole graph
  /// from the nodes those edges join. The cut is resolve()'s, to floating-point rounding; the
  /// result depends on the parts, never on `threads`. With one part: resolve().
  void resolve_in_parts(int threads);

  /// After a solve: whether node is reachable from the source in the residual graph.
  [[nodiscard]] bool in_source_set(FlowNode node) const;
  /// in_source_set of every node at once, on up to `threads` threads (0: every core);
  /// in_source.size() must be num_nodes().
  void source_set(std::span<char> in_source, int threads = 1) const;
  [[nodiscard]] std::size_t num_nodes() const noexcept;
  [[nodiscard]] std::size_t num_edges() const noexcept;
  /// What the last solve() or resolve() did.
  [[nodiscard]] const DynamicSolveStats& last_solve() const noexcept;
  /// Bytes of the graph's own flow state (node states, arc residuals, and the orphan and
  /// touched lists at their full size, as a copy reserves them): what a copy adds.
  [[nodiscard]] std::size_t memory_bytes() const noexcept;
  /// memory_bytes() of a graph with this many nodes and edges, before building it.
  [[nodiscard]] static std::size_t memory_bytes_for(std::size_t num_nodes,
                                                    std::size_t num_edges) noexcept;
  /// Bytes of the topology, held once by build() and shared by every copy.
  [[nodiscard]] std::size_t topology_bytes() const noexcept;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

static_assert(MaxFlow<DynamicMaxFlow>);

/// A MaxFlow backend that can change a solved graph's capacities and re-solve from its flow,
/// and be copied with that flow. Solvers keep one such graph per recurring problem (recycling).
template <class G>
concept ReusingMaxFlow = MaxFlow<G> && std::copy_constructible<G> &&
    requires(G& g, FlowNode i, std::size_t e, double delta, std::size_t n, std::size_t m) {
  g.change_terminal(i, delta);
  g.change_edge(e, delta, delta);
  g.resolve();
  { G::memory_bytes_for(n, m) } -> std::convertible_to<std::size_t>;
};

static_assert(ReusingMaxFlow<DynamicMaxFlow>);

/// A ReusingMaxFlow backend that builds a graph, cuts it into parts, and solves, changes and
/// re-solves it in parts, each on up to `threads` threads, to results that depend on the parts
/// and never on the threads. The graph-cut solvers solve in parts on such a backend only.
template <class G>
concept PartedMaxFlow = ReusingMaxFlow<G> &&
    requires(G& g, const G& cg, std::size_t n, std::span<const FlowEdge> edges,
             std::span<const std::uint8_t> part, const FlowCapacities& caps,
             std::span<const TerminalChange> terminals, std::span<const EdgeChange> changes,
             const ChangesByPart& by_part, std::span<char> in_source, int threads) {
  g.build(n, edges, threads);
  g.cut_into_parts(part, threads);
  g.solve_cut_in_parts(caps, threads);
  g.change_in_parts(terminals, changes, threads);
  g.change_by_parts(by_part, threads);
  g.resolve_in_parts(threads);
  cg.source_set(in_source, threads);
};

static_assert(PartedMaxFlow<DynamicMaxFlow>);

/// Applies to a solved graph the differences between two capacity sets (terminal pairs whose
/// source - sink differs, edges whose capacities differ), without re-solving: resolve() or
/// resolve_in_parts() next. Returns the number of changed nodes and edges. Throws
/// std::invalid_argument when the sets do not fit the graph.
std::size_t apply_capacity_changes(DynamicMaxFlow& graph, const FlowCapacities& before,
                                   const FlowCapacities& after);

/// apply_capacity_changes, then resolve().
std::size_t resolve_with(DynamicMaxFlow& graph, const FlowCapacities& before,
                         const FlowCapacities& after);

}  // namespace c2f

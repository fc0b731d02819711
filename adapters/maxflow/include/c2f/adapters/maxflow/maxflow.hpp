#pragma once
// The MaxFlow concept: s-t minimum cut on a graph whose topology is built once and whose
// capacities are reset before every solve (one solve per move of a graph-cut solver).

#include <concepts>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "c2f/core/huge_page_allocator.hpp"

namespace c2f {

using FlowNode = std::uint32_t;

/// A pair of opposite arcs from -> to and to -> from.
struct FlowEdge {
  FlowNode from = 0;
  FlowNode to = 0;
};

/// A change of a solved graph's terminal capacities, one of a batch (DynamicMaxFlow::
/// change_in_parts).
struct TerminalChange {
  FlowNode node;
  double delta;  ///< added to the node's source capacity minus its sink capacity
};

/// A change of a solved graph's edge capacities, one of a batch.
struct EdgeChange {
  std::size_t edge;
  double delta_forward;
  double delta_backward;
};

/// A batch of changes of a graph cut into parts, listed by part (DynamicMaxFlow::
/// change_by_parts): for each part k, terminals[k] changes nodes of part k and edges[k] edges
/// whose nodes are both in part k; edges[parts] changes the edges between parts. Each list in
/// the order its changes are to be made.
struct ChangesByPart {
  std::vector<LargeVector<TerminalChange>> terminals;  ///< one list per part
  std::vector<LargeVector<EdgeChange>> edges;          ///< one per part, then the edges between

  /// `parts` lists of terminal changes and parts + 1 of edge changes, all empty (keeps their
  /// memory).
  void clear(std::size_t parts) {
    terminals.resize(parts);
    edges.resize(parts + 1);
    for (LargeVector<TerminalChange>& list : terminals) list.clear();
    for (LargeVector<EdgeChange>& list : edges) list.clear();
  }
};

/// Every capacity of one solve: per node the arc from the source and the arc to the sink, per
/// edge the capacity of from -> to (forward) and of to -> from (backward). All finite, >= 0.
/// Cutting a node to the sink side costs `source[i]`, to the source side `sink[i]`.
struct FlowCapacities {
  LargeVector<double> source;
  LargeVector<double> sink;
  LargeVector<double> forward;
  LargeVector<double> backward;

  /// Sizes the arrays for a graph (keeps their memory when it shrinks or stays).
  void resize(std::size_t num_nodes, std::size_t num_edges);
};

/// Empty when caps fit a graph of num_nodes and num_edges and every value is finite and >= 0;
/// else a message naming the first offending entry.
std::string check_capacities(const FlowCapacities& caps, std::size_t num_nodes,
                             std::size_t num_edges);

/// A max-flow backend. Contract:
///  - `build(n, edges)` fixes the topology (n nodes, edges with endpoints < n and from != to;
///    std::invalid_argument otherwise);
///  - `solve(caps)` sets every capacity (topology kept) and returns the maximum flow, which
///    equals the capacity of the minimum cut it leaves; no per-call allocation of graph storage;
///  - `in_source_set(i)` tells, after solve, on which side of that minimum cut node i lies.
template <class G>
concept MaxFlow = requires(G& g, const G& cg, std::size_t n, std::span<const FlowEdge> edges,
                           const FlowCapacities& caps, FlowNode i) {
  g.build(n, edges);
  { g.solve(caps) } -> std::convertible_to<double>;
  { cg.in_source_set(i) } -> std::convertible_to<bool>;
  { cg.num_nodes() } -> std::convertible_to<std::size_t>;
  { cg.num_edges() } -> std::convertible_to<std::size_t>;
};

/// The capacity of the cut that puts the nodes with in_source[i] on the source side.
double cut_capacity(const FlowCapacities& caps, std::span<const FlowEdge> edges,
                    std::span<const char> in_source);

/// Throws std::invalid_argument unless every edge has endpoints < num_nodes and from != to,
/// naming the first edge that does not. Checks by chunks on up to `threads` threads (0: every
/// core).
void check_topology(std::size_t num_nodes, std::span<const FlowEdge> edges, const char* who,
                    int threads = 1);

}  // namespace c2f

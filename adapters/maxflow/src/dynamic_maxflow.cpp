#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"

#include <algorithm>
#include <cstdint>
#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace c2f {

namespace {

using Index = std::uint32_t;
constexpr Index kNone = std::numeric_limits<Index>::max();  // no parent: free node or orphan
constexpr Index kTerminal = kNone - 1;                      // parent is the tree's terminal

enum Tree : std::uint8_t { kFree = 0, kSourceTree = 1, kSinkTree = 2 };

/// One node. `excess` is the residual terminal capacity: > 0 from the source, < 0 to the
/// sink. `parent` is the arc from the node to its parent in its search tree.
struct Node {
  double excess = 0.0;
  Index first_arc = 0;  ///< arcs of node i are [nodes[i].first_arc, nodes[i + 1].first_arc)
  Index parent = kNone;
  Index next_active = kNone;  ///< kNone: not in the active queue; the last one points to itself
  Index stamp = 0;            ///< when `distance` was last known to be exact
  Index distance = 0;         ///< arcs to the terminal at time `stamp`
  Tree tree = kFree;
  bool touched = false;  ///< in the list of nodes a dynamic update changed
};

struct Arc {
  double residual = 0.0;
  Index head = 0;
  Index sister = 0;  ///< the reverse arc
};

/// Fills `to` with `from`, asking the kernel for transparent huge pages first when the block is
/// large: a graph of many megabytes otherwise costs one page fault per 4 KiB as it is first
/// written, which dominates copying or building it.
template <class T>
void assign_huge(std::vector<T>& to, const std::vector<T>& from) {
  to.clear();
  to.shrink_to_fit();
  to.reserve(from.size());
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  const std::size_t bytes = from.size() * sizeof(T);
  if (bytes >= 2 * kHuge) {
    const auto begin = reinterpret_cast<std::uintptr_t>(to.data());
    const std::uintptr_t first = (begin + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t last = (begin + bytes) & ~(kHuge - 1);
    if (last > first) madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
  }
#endif
  to.assign(from.begin(), from.end());
}

}  // namespace

struct DynamicMaxFlow::Impl {
  std::size_t num_nodes = 0;
  std::size_t num_edges = 0;
  std::vector<Node> nodes;  // num_nodes + 1 (the last one only closes the arc ranges)
  std::vector<Arc> arcs;
  std::vector<Index> forward_arc;  // edge e: its from -> to arc; the sister is to -> from
  bool has_flow = false;           // solve() ran since build(): the dynamic changes apply
  Index time = 0;
  Index first_active = kNone, last_active = kNone;
  std::vector<Index> orphans, touched;
  DynamicSolveStats stats;

  Impl() = default;
  /// A copy with the same flow and trees (the graph arrays on huge pages where possible).
  Impl(const Impl& other)
      : num_nodes(other.num_nodes),
        num_edges(other.num_edges),
        forward_arc(other.forward_arc),
        has_flow(other.has_flow),
        time(other.time),
        first_active(other.first_active),
        last_active(other.last_active),
        orphans(other.orphans),
        touched(other.touched),
        stats(other.stats) {
    assign_huge(nodes, other.nodes);
    assign_huge(arcs, other.arcs);
    orphans.reserve(num_nodes);
    touched.reserve(num_nodes);
  }
  Impl& operator=(const Impl&) = delete;

  void activate(Index i) {
    Node& node = nodes[i];
    if (node.next_active != kNone) return;
    node.next_active = i;
    if (last_active == kNone) {
      first_active = i;
    } else {
      nodes[last_active].next_active = i;
    }
    last_active = i;
  }

  /// The next active node still in a tree, taken off the queue; kNone when there is none.
  Index pop_active() {
    while (first_active != kNone) {
      const Index i = first_active;
      const Index next = nodes[i].next_active;
      nodes[i].next_active = kNone;
      if (next == i) {
        first_active = last_active = kNone;
      } else {
        first_active = next;
      }
      if (nodes[i].tree != kFree) return i;
    }
    return kNone;
  }

  void make_orphan(Index i) {
    nodes[i].parent = kNone;
    orphans.push_back(i);
  }

  /// Whether the arc from node i to its parent still carries the tree: the parent -> i arc has
  /// residual in the source tree, the i -> parent arc in the sink tree.
  [[nodiscard]] bool parent_arc_open(Index i) const {
    const Node& node = nodes[i];
    const Arc& up = arcs[node.parent];
    return node.tree == kSourceTree ? arcs[up.sister].residual > 0.0 : up.residual > 0.0;
  }

  /// Whether every capacity is finite and >= 0: one branch-free pass; check_capacities, which
  /// names the offending entry, runs only when this fails.
  [[nodiscard]] static bool all_valid(std::span<const double> values) {
    bool valid = true;
    for (const double c : values) valid &= c >= 0.0 && c <= std::numeric_limits<double>::max();
    return valid;
  }

  void start_from_zero_flow(const FlowCapacities& caps) {
    for (std::size_t i = 0; i < num_nodes; ++i) {
      Node& node = nodes[i];
      node.excess = caps.source[i] - caps.sink[i];
      node.next_active = kNone;
      node.stamp = 0;
      node.distance = 1;
      node.touched = false;
      if (node.excess != 0.0) {
        node.tree = node.excess > 0.0 ? kSourceTree : kSinkTree;
        node.parent = kTerminal;
      } else {
        node.tree = kFree;
        node.parent = kNone;
      }
    }
    first_active = last_active = kNone;
    for (std::size_t i = 0; i < num_nodes; ++i)
      if (nodes[i].tree != kFree) activate(static_cast<Index>(i));
    for (std::size_t e = 0; e < num_edges; ++e) {
      Arc& forward = arcs[forward_arc[e]];
      forward.residual = caps.forward[e];
      arcs[forward.sister].residual = caps.backward[e];
    }
    time = 0;
  }

  void touch(Index i) {
    if (nodes[i].touched) return;
    nodes[i].touched = true;
    touched.push_back(i);
  }

  /// Moves node i's residual terminal capacity by delta (a change of source - sink).
  void change_terminal(Index i, double delta) {
    nodes[i].excess += delta;
    touch(i);
    ++stats.changed_nodes;
  }

  /// Moves edge e's residuals by its capacity changes; flow above a lowered capacity is
  /// cancelled and handed to the endpoints' terminal arcs.
  void change_edge(std::size_t e, double delta_forward, double delta_backward) {
    Arc& forward = arcs[forward_arc[e]];
    Arc& backward = arcs[forward.sister];
    const Index from = backward.head;
    const Index to = forward.head;
    double forward_residual = forward.residual + delta_forward;
    double backward_residual = backward.residual + delta_backward;
    if (forward_residual < 0.0) {
      // More flow from -> to than the new capacity: cancel the surplus; `from` keeps it
      // (towards its sink arc), `to` misses it (from its source arc).
      const double surplus = -forward_residual;
      nodes[from].excess += surplus;
      nodes[to].excess -= surplus;
      backward_residual += forward_residual;
      forward_residual = 0.0;
    } else if (backward_residual < 0.0) {
      const double surplus = -backward_residual;
      nodes[to].excess += surplus;
      nodes[from].excess -= surplus;
      forward_residual += backward_residual;
      backward_residual = 0.0;
    }
    forward.residual = std::max(forward_residual, 0.0);  // max: rounding below zero
    backward.residual = std::max(backward_residual, 0.0);
    touch(from);
    touch(to);
    ++stats.changed_edges;
  }

  /// Node o leaves its tree: its children there become orphans, and the neighbours there with
  /// residual towards o are searched again (a searched source-tree node must have every
  /// residual out-arc inside its tree, a searched sink-tree node every residual in-arc).
  void leave_tree(Index o) {
    const Tree tree = nodes[o].tree;
    for (Index a = nodes[o].first_arc; a < nodes[o + 1].first_arc; ++a) {
      const Arc& arc = arcs[a];
      const Index j = arc.head;
      Node& neighbour = nodes[j];
      if (neighbour.tree != tree) continue;
      const double towards_o = tree == kSourceTree ? arcs[arc.sister].residual : arc.residual;
      if (towards_o > 0.0) activate(j);
      if (neighbour.parent != kNone && neighbour.parent != kTerminal &&
          arcs[neighbour.parent].head == o)
        make_orphan(j);
    }
  }

  /// Restores the search-tree invariants at the touched nodes: a node with terminal residual
  /// hangs from that terminal (leaving its old tree if the sign changed), a tree arc without
  /// residual makes an orphan, and every touched tree node is searched again.
  void repair_touched_nodes() {
    for (const Index i : touched) {
      Node& node = nodes[i];
      node.touched = false;
      if (node.excess != 0.0) {
        const Tree tree = node.excess > 0.0 ? kSourceTree : kSinkTree;
        if (node.tree != kFree && node.tree != tree) leave_tree(i);
        node.tree = tree;
        node.parent = kTerminal;
        node.stamp = time;
        node.distance = 1;
        activate(i);
      } else if (node.tree != kFree) {
        if (node.parent == kTerminal || (node.parent != kNone && !parent_arc_open(i)))
          make_orphan(i);
        activate(i);
      }
    }
    touched.clear();
  }

  /// Walks from node j to its terminal; the distance, or kNone when the walk meets an orphan.
  /// Marks the nodes on a successful walk with the current time and their distance.
  Index distance_to_terminal(Index j) {
    Index steps = 0;
    Index k = j;
    Index total = kNone;
    while (true) {
      Node& node = nodes[k];
      if (node.stamp == time) {
        total = steps + node.distance;
        break;
      }
      ++steps;
      if (node.parent == kTerminal) {
        node.stamp = time;
        node.distance = 1;
        total = steps;
        break;
      }
      if (node.parent == kNone) return kNone;
      k = arcs[node.parent].head;
    }
    Index d = total;
    for (k = j; nodes[k].stamp != time; k = arcs[nodes[k].parent].head) {
      nodes[k].stamp = time;
      nodes[k].distance = d--;
    }
    return total;
  }

  void adopt(Index o) {
    Node& orphan = nodes[o];
    if (orphan.parent != kNone || orphan.tree == kFree) return;  // re-hung since it was listed
    const Tree tree = orphan.tree;
    Index best_arc = kNone;
    Index best_distance = kNone;
    for (Index a = orphan.first_arc; a < nodes[o + 1].first_arc; ++a) {
      const Arc& arc = arcs[a];
      if (nodes[arc.head].tree != tree) continue;
      const double residual = tree == kSourceTree ? arcs[arc.sister].residual : arc.residual;
      if (!(residual > 0.0)) continue;
      const Index d = distance_to_terminal(arc.head);
      if (d < best_distance) {
        best_distance = d;
        best_arc = a;
      }
    }
    if (best_arc != kNone) {
      orphan.parent = best_arc;
      orphan.stamp = time;
      orphan.distance = best_distance + 1;
      return;
    }
    leave_tree(o);
    orphan.tree = kFree;
  }

  void adopt_orphans() {
    for (std::size_t k = 0; k < orphans.size(); ++k) adopt(orphans[k]);
    orphans.clear();
  }

  /// Pushes the bottleneck along source terminal -> ... -> u -> v -> ... -> sink terminal,
  /// where `middle` is the arc u -> v; saturated tree arcs and terminals make orphans.
  void augment(Index middle) {
    const Index u = arcs[arcs[middle].sister].head;
    const Index v = arcs[middle].head;
    double bottleneck = arcs[middle].residual;
    for (Index x = u;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        bottleneck = std::min(bottleneck, nodes[x].excess);
        break;
      }
      bottleneck = std::min(bottleneck, arcs[arcs[up].sister].residual);
      x = arcs[up].head;
    }
    for (Index x = v;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        bottleneck = std::min(bottleneck, -nodes[x].excess);
        break;
      }
      bottleneck = std::min(bottleneck, arcs[up].residual);
      x = arcs[up].head;
    }
    arcs[middle].residual -= bottleneck;
    arcs[arcs[middle].sister].residual += bottleneck;
    for (Index x = u;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        nodes[x].excess -= bottleneck;
        if (nodes[x].excess == 0.0) make_orphan(x);
        break;
      }
      Arc& down = arcs[arcs[up].sister];  // parent -> x
      down.residual -= bottleneck;
      arcs[up].residual += bottleneck;
      const Index parent = arcs[up].head;
      if (down.residual == 0.0) make_orphan(x);
      x = parent;
    }
    for (Index x = v;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        nodes[x].excess += bottleneck;
        if (nodes[x].excess == 0.0) make_orphan(x);
        break;
      }
      arcs[up].residual -= bottleneck;
      arcs[arcs[up].sister].residual += bottleneck;
      const Index parent = arcs[up].head;
      if (arcs[up].residual == 0.0) make_orphan(x);
      x = parent;
    }
    ++stats.augmentations;
  }

  /// Grows the tree of node i by one scan of its arcs; the arc from the source side to the sink
  /// side when the trees meet there, else kNone.
  Index grow(Index i) {
    Node& node = nodes[i];
    const bool source_side = node.tree == kSourceTree;
    for (Index a = node.first_arc; a < nodes[i + 1].first_arc; ++a) {
      const Arc& arc = arcs[a];
      // Source tree: grow along i -> j; sink tree: along j -> i.
      const double residual = source_side ? arc.residual : arcs[arc.sister].residual;
      if (!(residual > 0.0)) continue;
      Node& neighbour = nodes[arc.head];
      if (neighbour.tree == kFree) {
        neighbour.tree = node.tree;
        neighbour.parent = arc.sister;
        neighbour.stamp = node.stamp;
        neighbour.distance = node.distance + 1;
        activate(arc.head);
      } else if (neighbour.tree != node.tree) {
        return source_side ? a : arc.sister;
      }
    }
    return kNone;
  }

  void run() {
    Index current = kNone;
    while (true) {
      if (current == kNone || nodes[current].tree == kFree) {
        current = pop_active();
        if (current == kNone) break;
      }
      const Index middle = grow(current);
      if (middle == kNone) {
        current = kNone;
        continue;
      }
      ++time;
      augment(middle);
      adopt_orphans();
    }
  }

  [[nodiscard]] double cut_value(const FlowCapacities& caps) const {
    double total = 0.0;
    for (std::size_t i = 0; i < num_nodes; ++i)
      total += nodes[i].tree == kSourceTree ? caps.sink[i] : caps.source[i];
    for (std::size_t e = 0; e < num_edges; ++e) {
      const Arc& forward = arcs[forward_arc[e]];
      const bool to_source = nodes[forward.head].tree == kSourceTree;
      const bool from_source = nodes[arcs[forward.sister].head].tree == kSourceTree;
      if (from_source && !to_source) total += caps.forward[e];
      if (!from_source && to_source) total += caps.backward[e];
    }
    return total;
  }
};

DynamicMaxFlow::DynamicMaxFlow() : impl_(std::make_unique<Impl>()) {}
DynamicMaxFlow::~DynamicMaxFlow() = default;
DynamicMaxFlow::DynamicMaxFlow(const DynamicMaxFlow& other)
    : impl_(std::make_unique<Impl>(*other.impl_)) {}
DynamicMaxFlow& DynamicMaxFlow::operator=(const DynamicMaxFlow& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}
DynamicMaxFlow::DynamicMaxFlow(DynamicMaxFlow&&) noexcept = default;
DynamicMaxFlow& DynamicMaxFlow::operator=(DynamicMaxFlow&&) noexcept = default;

void DynamicMaxFlow::build(std::size_t num_nodes, std::span<const FlowEdge> edges) {
  check_topology(num_nodes, edges, "DynamicMaxFlow::build");
  if (num_nodes >= kTerminal || edges.size() >= (std::size_t{1} << 31)) {
    throw std::invalid_argument("DynamicMaxFlow::build: " + std::to_string(num_nodes) +
                                " nodes and " + std::to_string(edges.size()) +
                                " edges exceed the 32-bit arc indices");
  }
  Impl& m = *impl_;
  m.num_nodes = num_nodes;
  m.num_edges = edges.size();
  m.nodes.assign(num_nodes + 1, Node{});
  // Arcs sorted by tail: count, prefix sums, place.
  for (const FlowEdge& e : edges) {
    ++m.nodes[e.from].first_arc;
    ++m.nodes[e.to].first_arc;
  }
  Index offset = 0;
  for (Node& node : m.nodes) {
    const Index count = node.first_arc;
    node.first_arc = offset;
    offset += count;
  }
  std::vector<Index> fill(num_nodes);
  for (std::size_t i = 0; i < num_nodes; ++i) fill[i] = m.nodes[i].first_arc;
  m.arcs.assign(2 * edges.size(), Arc{});
  m.forward_arc.resize(edges.size());
  for (std::size_t e = 0; e < edges.size(); ++e) {
    const Index forward = fill[edges[e].from]++;
    const Index backward = fill[edges[e].to]++;
    m.arcs[forward] = {0.0, edges[e].to, backward};
    m.arcs[backward] = {0.0, edges[e].from, forward};
    m.forward_arc[e] = forward;
  }
  m.orphans.clear();
  m.touched.clear();
  m.orphans.reserve(num_nodes);
  m.touched.reserve(num_nodes);
  m.has_flow = false;
  m.stats = {};
}

double DynamicMaxFlow::solve(const FlowCapacities& caps) {
  solve_cut(caps);
  return impl_->cut_value(caps);
}

void DynamicMaxFlow::solve_cut(const FlowCapacities& caps) {
  Impl& m = *impl_;
  if (m.nodes.empty()) throw std::logic_error("DynamicMaxFlow::solve: call build() first");
  const bool sizes_fit = caps.source.size() == m.num_nodes && caps.sink.size() == m.num_nodes &&
                         caps.forward.size() == m.num_edges && caps.backward.size() == m.num_edges;
  if (!sizes_fit || !Impl::all_valid(caps.source) || !Impl::all_valid(caps.sink) ||
      !Impl::all_valid(caps.forward) || !Impl::all_valid(caps.backward)) {
    throw std::invalid_argument("DynamicMaxFlow::solve: " +
                                check_capacities(caps, m.num_nodes, m.num_edges));
  }
  m.stats = {};
  m.start_from_zero_flow(caps);
  m.has_flow = true;
  m.run();
}

void DynamicMaxFlow::change_terminal(FlowNode node, double delta) {
  Impl& m = *impl_;
  if (!m.has_flow) throw std::logic_error("DynamicMaxFlow::change_terminal: solve() first");
  if (m.touched.empty()) m.stats = {};
  m.change_terminal(node, delta);
}

void DynamicMaxFlow::change_edge(std::size_t edge, double delta_forward, double delta_backward) {
  Impl& m = *impl_;
  if (!m.has_flow) throw std::logic_error("DynamicMaxFlow::change_edge: solve() first");
  if (m.touched.empty()) m.stats = {};
  m.change_edge(edge, delta_forward, delta_backward);
}

void DynamicMaxFlow::resolve() {
  Impl& m = *impl_;
  if (!m.has_flow) throw std::logic_error("DynamicMaxFlow::resolve: solve() first");
  if (m.touched.empty()) m.stats = {};
  m.stats.reused = true;
  ++m.time;
  m.repair_touched_nodes();
  m.adopt_orphans();
  m.run();
}

bool DynamicMaxFlow::in_source_set(FlowNode node) const {
  return impl_->nodes[node].tree == kSourceTree;
}

void DynamicMaxFlow::source_set(std::span<char> in_source) const {
  const Impl& m = *impl_;
  if (in_source.size() != m.num_nodes)
    throw std::invalid_argument("DynamicMaxFlow::source_set: wrong size");
  for (std::size_t i = 0; i < m.num_nodes; ++i) in_source[i] = m.nodes[i].tree == kSourceTree;
}

std::size_t DynamicMaxFlow::num_nodes() const noexcept {
  return impl_->num_nodes;
}
std::size_t DynamicMaxFlow::num_edges() const noexcept {
  return impl_->num_edges;
}
const DynamicSolveStats& DynamicMaxFlow::last_solve() const noexcept {
  return impl_->stats;
}

std::size_t DynamicMaxFlow::memory_bytes() const noexcept {
  return memory_bytes_for(impl_->num_nodes, impl_->num_edges);
}

std::size_t DynamicMaxFlow::memory_bytes_for(std::size_t num_nodes,
                                             std::size_t num_edges) noexcept {
  const std::size_t per_node = sizeof(Node);
  const std::size_t per_edge = 2 * sizeof(Arc) + sizeof(Index);  // + forward_arc
  return (num_nodes + 1) * per_node + num_edges * per_edge;
}

std::size_t resolve_with(DynamicMaxFlow& graph, const FlowCapacities& before,
                         const FlowCapacities& after) {
  const std::size_t n = graph.num_nodes();
  const std::size_t m = graph.num_edges();
  for (const FlowCapacities* caps : {&before, &after}) {
    if (const std::string problem = check_capacities(*caps, n, m); !problem.empty())
      throw std::invalid_argument("resolve_with: " + problem);
  }
  std::size_t changes = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double delta = (after.source[i] - after.sink[i]) - (before.source[i] - before.sink[i]);
    if (delta == 0.0) continue;
    graph.change_terminal(static_cast<FlowNode>(i), delta);
    ++changes;
  }
  for (std::size_t e = 0; e < m; ++e) {
    if (after.forward[e] == before.forward[e] && after.backward[e] == before.backward[e]) continue;
    graph.change_edge(e, after.forward[e] - before.forward[e],
                      after.backward[e] - before.backward[e]);
    ++changes;
  }
  graph.resolve();
  return changes;
}

}  // namespace c2f

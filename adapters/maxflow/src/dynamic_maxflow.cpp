#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"

#include <algorithm>
#include <chrono>
#include <cstdint>
#if defined(__linux__)
#include <sys/mman.h>
#endif
#include <limits>
#include <memory>
#include <numeric>
#include <ranges>
#include <span>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "c2f/core/default_init_allocator.hpp"
#include "c2f/core/huge_page_allocator.hpp"
#include "c2f/support/parallel_for.hpp"

namespace c2f {

namespace {

using Index = std::uint32_t;
constexpr Index kNone = std::numeric_limits<Index>::max();  // no parent: free node or orphan
constexpr Index kTerminal = kNone - 1;                      // parent is the tree's terminal

enum Tree : std::uint8_t { kFree = 0, kSourceTree = 1, kSinkTree = 2 };

/// One node's flow state. `excess` is the residual terminal capacity: > 0 from the source,
/// < 0 to the sink. `parent` is the arc from the node to its parent in its search tree.
/// Trivial, so that a DefaultInitVector of nodes is sized without writing them: the graph's
/// arrays are written once, by chunks on the threads, after they are sized. kFreshNode is a
/// node of a graph just built.
struct Node {
  double excess;
  Index parent;
  Index next_active;  ///< kNone: not in the active queue; the last one points to itself
  Index stamp;        ///< when `distance` was last known to be exact
  Index distance;     ///< arcs to the terminal at time `stamp`
  Tree tree;
  bool touched;  ///< in the list of nodes a dynamic update changed
};
static_assert(std::is_trivially_default_constructible_v<Node>);
constexpr Node kFreshNode{0.0, kNone, kNone, 0, 0, kFree, false};

/// What never changes after build(): the arcs sorted by tail, each with its head and its
/// reverse. Copies of a graph (recycled per-label graphs) share one Topology and own only their
/// flow state (nodes and residuals): a TSGO QPBO move graph at 171k pixels (342k nodes, 1.37M
/// edges) costs 33 MB per copy instead of 60 MB.
struct Topology {
  DefaultInitVector<Index> first_arc;    ///< arcs of node i: [first_arc[i], first_arc[i + 1])
  DefaultInitVector<Index> head;         ///< per arc
  DefaultInitVector<Index> sister;       ///< per arc: the reverse arc
  DefaultInitVector<Index> forward_arc;  ///< per edge: its from -> to arc; the sister is to -> from
};

/// A cut of a graph's nodes into parts (DynamicMaxFlow::cut_into_parts): each node's part and
/// the edges joining two parts. Fixed with the topology, shared by copies.
struct Parts {
  std::vector<std::uint8_t> of_node;
  /// Per edge: the part of both its nodes, or `count` when it joins two parts.
  std::vector<std::uint16_t> of_edge;
  std::vector<std::size_t> between;
  std::size_t count = 1;
  /// The nodes of part k, ascending: members[first_member[k] .. first_member[k + 1]).
  DefaultInitVector<std::uint32_t> members;
  std::vector<std::size_t> first_member;
};

/// Nodes or edges per task when a pass over them is split among threads (parallel_for_chunks).
constexpr std::size_t kPassChunk = 16384;

/// The parts' numbers ordered by `seconds` (each part's last search), longest first, ties by
/// number.
std::vector<std::size_t> longest_first(const std::vector<double>& seconds) {
  std::vector<std::size_t> order(seconds.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return seconds[a] > seconds[b]; });
  return order;
}

/// A bucket sort_by_part's bucket_of returns for an entry that names no node or edge.
constexpr std::size_t kOutOfRange = std::numeric_limits<std::size_t>::max();

/// The positions of a list's entries sorted by bucket, each bucket's in list order.
struct ByPart {
  DefaultInitVector<std::uint32_t> positions;  ///< bucket b's: [first[b], first[b + 1])
  std::vector<std::size_t> first;
  bool out_of_range = false;  ///< some entry's bucket was kOutOfRange (then nothing is sorted)

  [[nodiscard]] std::span<const std::uint32_t> of(std::size_t bucket) const {
    return std::span(positions).subspan(first[bucket], first[bucket + 1] - first[bucket]);
  }
};

/// Sorts positions 0 .. size - 1 of a list into `buckets` buckets, entry c into bucket_of(c):
/// each chunk of kPassChunk entries counts its buckets and later places its entries, both on up
/// to `threads` threads, so every bucket keeps list order and the result does not depend on
/// the threads.
template <class BucketOf>
ByPart sort_by_part(std::size_t size, std::size_t buckets, const BucketOf& bucket_of, int threads) {
  ByPart sorted;
  const std::size_t chunks = (size + kPassChunk - 1) / kPassChunk;
  DefaultInitVector<std::uint16_t> bucket(size);     // up to 256 parts and the bucket between them
  std::vector<std::size_t> at(chunks * buckets, 0);  // chunk c's count, then its next place, of b
  std::vector<std::uint8_t> bad(chunks, 0);
  parallel_for_chunks(
      size, kPassChunk,
      [&](std::size_t chunk, std::size_t first, std::size_t last) {
        std::size_t* count = at.data() + chunk * buckets;
        for (std::size_t c = first; c < last; ++c) {
          const std::size_t b = bucket_of(c);
          if (b >= buckets) {
            bad[chunk] = 1;
            continue;
          }
          bucket[c] = static_cast<std::uint16_t>(b);
          ++count[b];
        }
      },
      threads);
  sorted.out_of_range = std::find(bad.begin(), bad.end(), 1) != bad.end();
  sorted.first.assign(buckets + 1, 0);
  if (sorted.out_of_range) return sorted;
  std::size_t place = 0;  // bucket by bucket, chunk by chunk
  for (std::size_t b = 0; b < buckets; ++b) {
    sorted.first[b] = place;
    for (std::size_t chunk = 0; chunk < chunks; ++chunk) {
      const std::size_t count = at[chunk * buckets + b];
      at[chunk * buckets + b] = place;
      place += count;
    }
  }
  sorted.first[buckets] = place;
  sorted.positions.resize(size);
  parallel_for_chunks(
      size, kPassChunk,
      [&](std::size_t chunk, std::size_t first, std::size_t last) {
        std::size_t* next = at.data() + chunk * buckets;
        for (std::size_t c = first; c < last; ++c)
          sorted.positions[next[bucket[c]]++] = static_cast<std::uint32_t>(c);
      },
      threads);
  return sorted;
}

/// Fills `to` with `from`, by chunks on up to `threads` threads. A large block is on huge pages
/// already (DefaultInitVector's HugePageAllocator: 2 MiB-aligned, advised MADV_HUGEPAGE); this
/// also asks, on up to `threads` threads at once, for the pages themselves
/// (MADV_POPULATE_WRITE, by ranges of 2 MiB): a graph of many megabytes otherwise costs a page
/// fault per page as one thread first writes it, and the kernel's zeroing of those pages
/// dominates copying it (22% of a flat whole-move run on a 480x640 grid of 32 labels). A
/// request: pages the kernel does not give ahead are faulted in by the copy, as without it.
template <class T>
void assign_huge(DefaultInitVector<T>& to, const DefaultInitVector<T>& from, int threads) {
  to.clear();
  to.shrink_to_fit();
  to.reserve(from.size());
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
  const std::size_t bytes = from.size() * sizeof(T);
  if (threads != 1 && bytes >= kHugePageMinBytes) {
    const auto begin = reinterpret_cast<std::uintptr_t>(to.data());
    const std::uintptr_t first = (begin + kHugePageBytes - 1) & ~(kHugePageBytes - 1);
    const std::uintptr_t last = (begin + bytes) & ~(kHugePageBytes - 1);
    if (last > first) {
      parallel_for_chunks((last - first) / kHugePageBytes, 1,
                          [&](std::size_t, std::size_t from_page, std::size_t to_page) {
                            madvise(reinterpret_cast<void*>(first + from_page * kHugePageBytes),
                                    (to_page - from_page) * kHugePageBytes, MADV_POPULATE_WRITE);
                          },
                          threads);
    }
  }
#endif
  to.resize(from.size());  // unwritten: copied by chunks below
  parallel_for_chunks(
      from.size(), kPassChunk,
      [&](std::size_t, std::size_t first, std::size_t last) {
        std::copy(from.begin() + first, from.begin() + last, to.begin() + first);
      },
      threads);
}

/// Edges per task when build() places arcs on several threads.
constexpr std::size_t kPlaceChunk = 65536;

/// The arcs of `edges` sorted by tail, each node's in edge order: the same arrays for every
/// thread count. On several threads each range of edges counts its arcs at every node, and
/// from those counts knows where its arcs go.
void place_arcs(Topology& t, std::size_t num_nodes, std::span<const FlowEdge> edges, int threads) {
  const std::size_t ranges = std::min<std::size_t>(
      resolved_threads(threads), std::max<std::size_t>(1, edges.size() / kPlaceChunk));
  const std::size_t per_range = (edges.size() + ranges - 1) / std::max<std::size_t>(ranges, 1);
  // next[r][i]: where range r puts its next arc at node i (first its count of them).
  std::vector<std::vector<Index>> next(ranges);
  parallel_for(
      ranges,
      [&](std::size_t r) {
        next[r].assign(num_nodes, 0);
        const std::size_t last = std::min(edges.size(), (r + 1) * per_range);
        for (std::size_t e = r * per_range; e < last; ++e) {
          ++next[r][edges[e].from];
          ++next[r][edges[e].to];
        }
      },
      threads);
  // Node i's arcs begin after those of the nodes before it; range r's after those of ranges
  // before r at i. By chunks of nodes: each chunk's arc count, then the counts summed in chunk
  // order, then each chunk's offsets from its own start.
  t.first_arc.resize(num_nodes + 1);
  const std::size_t chunks = (num_nodes + kPassChunk - 1) / kPassChunk;
  std::vector<Index> chunk_start(chunks + 1, 0);
  parallel_for_chunks(
      num_nodes, kPassChunk,
      [&](std::size_t c, std::size_t first, std::size_t last) {
        Index count = 0;
        for (std::size_t i = first; i < last; ++i) {
          for (std::size_t r = 0; r < ranges; ++r) count += next[r][i];
        }
        chunk_start[c + 1] = count;
      },
      threads);
  for (std::size_t c = 0; c < chunks; ++c) chunk_start[c + 1] += chunk_start[c];
  parallel_for_chunks(
      num_nodes, kPassChunk,
      [&](std::size_t c, std::size_t first, std::size_t last) {
        Index offset = chunk_start[c];
        for (std::size_t i = first; i < last; ++i) {
          t.first_arc[i] = offset;
          for (std::size_t r = 0; r < ranges; ++r) {
            const Index count = next[r][i];
            next[r][i] = offset;
            offset += count;
          }
        }
      },
      threads);
  t.first_arc[num_nodes] = chunk_start[chunks];
  t.head.resize(2 * edges.size());
  t.sister.resize(2 * edges.size());
  t.forward_arc.resize(edges.size());
  parallel_for(
      ranges,
      [&](std::size_t r) {
        std::vector<Index>& fill = next[r];
        const std::size_t last = std::min(edges.size(), (r + 1) * per_range);
        for (std::size_t e = r * per_range; e < last; ++e) {
          const Index forward = fill[edges[e].from]++;
          const Index backward = fill[edges[e].to]++;
          t.head[forward] = edges[e].to;
          t.sister[forward] = backward;
          t.head[backward] = edges[e].from;
          t.sister[backward] = forward;
          t.forward_arc[e] = forward;
        }
      },
      threads);
}

}  // namespace

/// One search over the graph's nodes, or over one part of them: the active queue, the orphan
/// list and the clock of the distance stamps, held by reference. The serial solve searches with
/// the graph's own. A parallel solve (solve_cut with parts) gives each part its own over
/// disjoint nodes, with the arcs between parts closed (no residual either way, so no tree grows
/// or augments across them) and `part` set, so that no step reads a node of another part.
struct Search {
  Node* nodes;
  double* residual;
  const Topology& t;
  Index& time;
  Index& first_active;
  Index& last_active;
  std::vector<Index>& orphans;
  std::size_t& augmentations;
  std::size_t& arcs_scanned;
  const std::uint8_t* part = nullptr;  ///< parallel: each node's part (null: one search)
  std::uint8_t mine = 0;               ///< parallel: this search's part

  [[nodiscard]] bool other_part(Index j) const { return part != nullptr && part[j] != mine; }

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
    const Index up = node.parent;
    return node.tree == kSourceTree ? residual[t.sister[up]] > 0.0 : residual[up] > 0.0;
  }

  /// Node o leaves its tree: its children there become orphans, and the neighbours there with
  /// residual towards o are searched again (a searched source-tree node must have every
  /// residual out-arc inside its tree, a searched sink-tree node every residual in-arc).
  void leave_tree(Index o) {
    const Tree tree = nodes[o].tree;
    for (Index a = t.first_arc[o]; a < t.first_arc[o + 1]; ++a) {
      const Index j = t.head[a];
      if (other_part(j)) continue;
      Node& neighbour = nodes[j];
      if (neighbour.tree != tree) continue;
      const double towards_o = tree == kSourceTree ? residual[t.sister[a]] : residual[a];
      if (towards_o > 0.0) activate(j);
      if (neighbour.parent != kNone && neighbour.parent != kTerminal &&
          t.head[neighbour.parent] == o)
        make_orphan(j);
    }
  }

  /// Restores the search-tree invariants at node i after its terminal or edge capacities
  /// changed: a node with terminal residual hangs from that terminal (leaving its old tree if
  /// the sign changed), a tree arc without residual makes an orphan, and a tree node is searched
  /// again.
  void repair(Index i) {
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
      if (node.parent == kTerminal || (node.parent != kNone && !parent_arc_open(i))) make_orphan(i);
      activate(i);
    }
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
      k = t.head[node.parent];
    }
    Index d = total;
    for (k = j; nodes[k].stamp != time; k = t.head[nodes[k].parent]) {
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
    for (Index a = t.first_arc[o]; a < t.first_arc[o + 1]; ++a) {
      const Index j = t.head[a];
      if (other_part(j) || nodes[j].tree != tree) continue;
      const double towards_o = tree == kSourceTree ? residual[t.sister[a]] : residual[a];
      if (!(towards_o > 0.0)) continue;
      const Index d = distance_to_terminal(j);
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
    const Index u = t.head[t.sister[middle]];
    const Index v = t.head[middle];
    double bottleneck = residual[middle];
    for (Index x = u;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        bottleneck = std::min(bottleneck, nodes[x].excess);
        break;
      }
      bottleneck = std::min(bottleneck, residual[t.sister[up]]);
      x = t.head[up];
    }
    for (Index x = v;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        bottleneck = std::min(bottleneck, -nodes[x].excess);
        break;
      }
      bottleneck = std::min(bottleneck, residual[up]);
      x = t.head[up];
    }
    residual[middle] -= bottleneck;
    residual[t.sister[middle]] += bottleneck;
    for (Index x = u;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        nodes[x].excess -= bottleneck;
        if (nodes[x].excess == 0.0) make_orphan(x);
        break;
      }
      double& down = residual[t.sister[up]];  // parent -> x
      down -= bottleneck;
      residual[up] += bottleneck;
      const Index parent = t.head[up];
      if (down == 0.0) make_orphan(x);
      x = parent;
    }
    for (Index x = v;;) {
      const Index up = nodes[x].parent;
      if (up == kTerminal) {
        nodes[x].excess += bottleneck;
        if (nodes[x].excess == 0.0) make_orphan(x);
        break;
      }
      residual[up] -= bottleneck;
      residual[t.sister[up]] += bottleneck;
      const Index parent = t.head[up];
      if (residual[up] == 0.0) make_orphan(x);
      x = parent;
    }
    ++augmentations;
  }

  /// Grows the tree of node i by a scan of its arcs from arc `from` on; the arc from the source
  /// side to the sink side when the trees meet there, else kNone.
  Index grow(Index i, Index from) {
    Node& node = nodes[i];
    const bool source_side = node.tree == kSourceTree;
    const Index end = t.first_arc[i + 1];
    for (Index a = from; a < end; ++a) {
      // Source tree: grow along i -> j; sink tree: along j -> i.
      const Index sister = t.sister[a];
      const double open = source_side ? residual[a] : residual[sister];
      if (!(open > 0.0)) continue;
      const Index j = t.head[a];
      Node& neighbour = nodes[j];
      if (neighbour.tree == kFree) {
        neighbour.tree = node.tree;
        neighbour.parent = sister;
        neighbour.stamp = node.stamp;
        neighbour.distance = node.distance + 1;
        activate(j);
      } else if (neighbour.tree != node.tree) {
        arcs_scanned += a - from + 1;
        return source_side ? a : sister;
      }
    }
    arcs_scanned += end - from;
    return kNone;
  }

  /// Grows the trees from the active nodes and augments where they meet, until no active node
  /// is left. A node whose scan met the other tree goes on, after the augmentation, from the arc
  /// where they met: scanning it again from its first arc would cost a node of degree d up to
  /// d scans of its d arcs (a coarse level's large group has thousands of neighbours).
  void run() {
    Index current = kNone;
    Index from = 0;  // the arc of `current` its scan goes on from
    while (true) {
      if (current == kNone || nodes[current].tree == kFree) {
        current = pop_active();
        if (current == kNone) break;
        from = t.first_arc[current];
      }
      const Index middle = grow(current, from);
      if (middle == kNone) {
        current = kNone;
        continue;
      }
      // The arcs before the meeting arc led into the node's own tree and still do, or lead to
      // nodes that left it since, and leave_tree() queued this node again for those.
      from = nodes[current].tree == kSourceTree ? middle : t.sister[middle];
      ++time;
      augment(middle);
      adopt_orphans();
    }
  }
};

struct DynamicMaxFlow::Impl {
  std::size_t num_nodes = 0;
  std::size_t num_edges = 0;
  std::shared_ptr<const Topology> topology;  // shared with copies; null before build()
  std::shared_ptr<const Parts> parts;        // cut_into_parts; null: one part
  DefaultInitVector<Node> nodes;             // num_nodes
  DefaultInitVector<double> residual;        // per arc
  bool has_flow = false;                     // solve() ran since build(): the dynamic changes apply
  Index time = 0;
  Index first_active = kNone, last_active = kNone;
  std::vector<Index> orphans, touched;
  /// Where change_in_parts listed each part's nodes in `touched`: part k's are
  /// touched[touched_by_part[k], touched_by_part[k + 1]); those before the first and after the
  /// last are of any part. Empty when `touched` is in no such order.
  std::vector<std::size_t> touched_by_part;
  DynamicSolveStats stats;
  /// The seconds each part's search took in the last search_in_parts (empty before one): the
  /// next one hands the parts to its threads longest first. Only the threads' schedule depends
  /// on it, never the flow (each part's search reads and writes its own nodes only).
  std::vector<double> part_seconds;

  Impl() = default;
  /// A copy with the same flow and trees (the graph arrays on huge pages where possible, their
  /// pages faulted in on up to `threads` threads).
  Impl(const Impl& other, int threads)
      : num_nodes(other.num_nodes),
        num_edges(other.num_edges),
        topology(other.topology),
        parts(other.parts),
        has_flow(other.has_flow),
        time(other.time),
        first_active(other.first_active),
        last_active(other.last_active),
        orphans(other.orphans),
        touched(other.touched),
        touched_by_part(other.touched_by_part),
        stats(other.stats),
        part_seconds(other.part_seconds) {
    assign_huge(nodes, other.nodes, threads);
    assign_huge(residual, other.residual, threads);
    orphans.reserve(num_nodes);
    touched.reserve(num_nodes);
  }
  Impl& operator=(const Impl&) = delete;

  /// Whether every capacity is finite and >= 0: one branch-free pass; check_capacities, which
  /// names the offending entry, runs only when this fails.
  [[nodiscard]] static bool all_valid(std::span<const double> values) {
    bool valid = true;
    for (const double c : values) valid &= c >= 0.0 && c <= std::numeric_limits<double>::max();
    return valid;
  }

  /// all_valid on up to `threads` threads, by chunks.
  [[nodiscard]] static bool all_valid(std::span<const double> values, int threads) {
    if (threads == 1) return all_valid(values);
    std::vector<std::uint8_t> valid((values.size() + kPassChunk - 1) / kPassChunk, 1);
    parallel_for_chunks(
        values.size(), kPassChunk,
        [&](std::size_t c, std::size_t first, std::size_t last) {
          valid[c] = all_valid(values.subspan(first, last - first)) ? 1 : 0;
        },
        threads);
    return std::all_of(valid.begin(), valid.end(), [](std::uint8_t v) { return v != 0; });
  }

  /// Throws std::invalid_argument naming the first capacity that does not fit the graph.
  /// Checks on up to `threads` threads.
  void check_solvable(const FlowCapacities& caps, int threads = 1) const {
    const bool sizes_fit = caps.source.size() == num_nodes && caps.sink.size() == num_nodes &&
                           caps.forward.size() == num_edges && caps.backward.size() == num_edges;
    if (!sizes_fit || !all_valid(caps.source, threads) || !all_valid(caps.sink, threads) ||
        !all_valid(caps.forward, threads) || !all_valid(caps.backward, threads)) {
      throw std::invalid_argument("DynamicMaxFlow::solve: " +
                                  check_capacities(caps, num_nodes, num_edges));
    }
  }

  /// Zero flow on `caps`, every node with terminal residual hanging from its terminal, and
  /// nothing queued yet; written on up to `threads` threads (each node and edge by one).
  void load_zero_flow(const FlowCapacities& caps, int threads = 1) {
    parallel_for_chunks(
        num_nodes, kPassChunk,
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t i = first; i < last; ++i) {
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
        },
        threads);
    first_active = last_active = kNone;
    const Topology& t = *topology;
    parallel_for_chunks(
        num_edges, kPassChunk,
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t e = first; e < last; ++e) {
            const Index forward = t.forward_arc[e];
            residual[forward] = caps.forward[e];
            residual[t.sister[forward]] = caps.backward[e];
          }
        },
        threads);
    time = 0;
  }

  void start_from_zero_flow(const FlowCapacities& caps) {
    load_zero_flow(caps);
    Search s = search();
    for (std::size_t i = 0; i < num_nodes; ++i)
      if (nodes[i].tree != kFree) s.activate(static_cast<Index>(i));
  }

  /// The flow of `caps` from zero in parts (search_in_parts), every terminal node queued in
  /// its part.
  void solve_in_parts(const FlowCapacities& caps, int threads) {
    load_zero_flow(caps, threads);
    search_in_parts(threads, [&](Search& s, std::size_t k) {
      for (std::size_t m = parts->first_member[k]; m < parts->first_member[k + 1]; ++m) {
        const Index i = parts->members[m];
        if (nodes[i].tree != kFree) s.activate(i);
      }
    });
  }

  /// resolve() in parts (search_in_parts): each part repairs its touched nodes, in the order of
  /// `touched` (the run change_in_parts listed for it, and the rest picked out by part).
  void resolve_in_parts(int threads) {
    const std::vector<std::uint8_t>& part = parts->of_node;
    const auto repair_of_part = [&](Search& s, std::size_t k, std::size_t first, std::size_t last) {
      for (std::size_t m = first; m < last; ++m)
        if (part[touched[m]] == k) s.repair(touched[m]);
    };
    search_in_parts(threads, [&](Search& s, std::size_t k) {
      if (touched_by_part.empty()) {
        repair_of_part(s, k, 0, touched.size());
        return;
      }
      repair_of_part(s, k, 0, touched_by_part.front());
      for (std::size_t m = touched_by_part[k]; m < touched_by_part[k + 1]; ++m)
        s.repair(touched[m]);
      repair_of_part(s, k, touched_by_part.back(), touched.size());
    });
  }

  /// Searches on from the current flow in two stages. First every part on its own nodes, all
  /// at once on up to `threads` threads: the edges between parts are closed (their flow stays,
  /// their residuals are set aside, and a node hanging from a neighbour across one becomes an
  /// orphan of its part), and prepare(search, k) queues part k's nodes. Then those edges open
  /// and the whole graph is searched on from the nodes they join. Both stages start from valid
  /// flows and trees, so the result is a maximum flow of the graph.
  template <class Prepare>
  void search_in_parts(int threads, const Prepare& prepare) {
    const Topology& t = *topology;
    const std::vector<std::uint8_t>& part = parts->of_node;
    const std::vector<std::size_t>& between = parts->between;
    std::vector<double> set_aside;  // their residuals, forward then backward
    set_aside.reserve(2 * between.size());
    for (const std::size_t e : between) {
      const Index forward = t.forward_arc[e];
      const Index backward = t.sister[forward];
      set_aside.push_back(residual[forward]);
      set_aside.push_back(residual[backward]);
      residual[forward] = residual[backward] = 0.0;
    }
    struct alignas(kCacheLineBytes) PartSearch {  // written by its part's thread only
      Index time = 0, first_active = kNone, last_active = kNone;
      std::vector<Index> orphans;
      std::size_t augmentations = 0, arcs_scanned = 0;
    };
    std::vector<PartSearch> searches(parts->count);
    const Index start = time + 1;  // later than every stamp
    // With the parts' times of a search before (a re-solve, or a copy's first), the threads
    // take the parts longest first; else (a fresh graph) each starts on its own half of them,
    // whose nodes the passes before (load_zero_flow, by chunks) left in its core's caches.
    const bool timed_before = part_seconds.size() == parts->count;
    const std::vector<std::size_t> order =
        timed_before ? longest_first(part_seconds) : std::vector<std::size_t>{};
    part_seconds.assign(parts->count, 0.0);
    const auto search_part = [&](std::size_t k) {
      const auto began = std::chrono::steady_clock::now();
      PartSearch& own = searches[k];
      own.time = start;
      Search s{nodes.data(),
               residual.data(),
               t,
               own.time,
               own.first_active,
               own.last_active,
               own.orphans,
               own.augmentations,
               own.arcs_scanned,
               part.data(),
               static_cast<std::uint8_t>(k)};
      for (const std::size_t e : between) {
        // A node's parent arc leads from it to its parent.
        const Index forward = t.forward_arc[e];
        const Index backward = t.sister[forward];
        const Index from = t.head[backward];
        const Index to = t.head[forward];
        if (part[from] == k && nodes[from].parent == forward) s.make_orphan(from);
        if (part[to] == k && nodes[to].parent == backward) s.make_orphan(to);
      }
      prepare(s, k);
      s.adopt_orphans();
      s.run();
      part_seconds[k] =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - began).count();
    };
    if (timed_before) {
      parallel_for_in_order(order, search_part, threads);
    } else {
      parallel_for(parts->count, search_part, threads);
    }
    time = start;
    for (const PartSearch& own : searches) {
      time = std::max(time, own.time);
      stats.augmentations += own.augmentations;
      stats.arcs_scanned += own.arcs_scanned;
    }
    touched.clear();  // the parts repaired them
    touched_by_part.clear();
    for (std::size_t k = 0; k < between.size(); ++k) {
      const Index forward = t.forward_arc[between[k]];
      residual[forward] = set_aside[2 * k];
      residual[t.sister[forward]] = set_aside[2 * k + 1];
      touch(t.head[forward]);
      touch(t.head[t.sister[forward]]);
    }
    ++time;
    repair_touched_nodes();
    adopt_orphans();
    run();
  }

  /// Lists node i in `list` (the touched list, or a part's) unless it is touched already.
  void touch(Index i, std::vector<Index>& list) {
    if (nodes[i].touched) return;
    nodes[i].touched = true;
    list.push_back(i);
  }
  void touch(Index i) { touch(i, touched); }

  /// Moves node i's residual terminal capacity by delta (a change of source - sink).
  void change_terminal(Index i, double delta, std::vector<Index>& list) {
    nodes[i].excess += delta;
    touch(i, list);
  }
  void change_terminal(Index i, double delta) {
    change_terminal(i, delta, touched);
    ++stats.changed_nodes;
  }

  /// change_edge, listing the endpoints it touches in `list`.
  void change_edge(std::size_t e, double delta_forward, double delta_backward,
                   std::vector<Index>& list) {
    const Topology& t = *topology;
    const Index forward = t.forward_arc[e];
    const Index backward = t.sister[forward];
    const Index from = t.head[backward];
    const Index to = t.head[forward];
    double forward_residual = residual[forward] + delta_forward;
    double backward_residual = residual[backward] + delta_backward;
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
    residual[forward] = std::max(forward_residual, 0.0);  // max: rounding below zero
    residual[backward] = std::max(backward_residual, 0.0);
    touch(from, list);
    touch(to, list);
  }

  /// Moves edge e's residuals by its capacity changes; flow above a lowered capacity is
  /// cancelled and handed to the endpoints' terminal arcs.
  void change_edge(std::size_t e, double delta_forward, double delta_backward) {
    change_edge(e, delta_forward, delta_backward, touched);
    ++stats.changed_edges;
  }

  /// Throws std::out_of_range naming the first terminal change, then the first edge change, that
  /// names a node or edge the graph does not have.
  void check_changes(std::span<const TerminalChange> terminals,
                     std::span<const EdgeChange> edges) const {
    for (const TerminalChange& change : terminals) {
      if (change.node >= num_nodes) {
        throw std::out_of_range("DynamicMaxFlow::change_in_parts: node " +
                                std::to_string(change.node) + " of " + std::to_string(num_nodes));
      }
    }
    for (const EdgeChange& change : edges) {
      if (change.edge >= num_edges) {
        throw std::out_of_range("DynamicMaxFlow::change_in_parts: edge " +
                                std::to_string(change.edge) + " of " + std::to_string(num_edges));
      }
    }
  }

  /// DynamicMaxFlow::change_in_parts with more than one part. The changes are sorted by part
  /// first (by chunks on the threads, each part's in their order); then made as
  /// change_each_part makes them, and then the changes of edges between parts in their order.
  /// Throws std::out_of_range, changing nothing, when a change names a node or edge the graph
  /// does not have.
  void change_in_parts(std::span<const TerminalChange> terminals, std::span<const EdgeChange> edges,
                       int threads) {
    const std::vector<std::uint8_t>& part = parts->of_node;
    const std::size_t between_parts = parts->count;  // Parts::of_edge of edges between parts
    const ByPart terminals_by_part = sort_by_part(
        terminals.size(), parts->count + 1,
        [&](std::size_t c) -> std::size_t {
          const FlowNode node = terminals[c].node;
          return node < num_nodes ? part[node] : kOutOfRange;
        },
        threads);
    if (terminals_by_part.out_of_range) check_changes(terminals, {});
    const ByPart edges_by_part = sort_by_part(
        edges.size(), parts->count + 1,
        [&](std::size_t c) -> std::size_t {
          const std::size_t e = edges[c].edge;
          return e < num_edges ? parts->of_edge[e] : kOutOfRange;
        },
        threads);
    if (edges_by_part.out_of_range) check_changes({}, edges);
    change_each_part(
        [&](std::size_t k) {
          return std::views::transform(terminals_by_part.of(k),
                                       [&](std::uint32_t c) { return terminals[c]; });
        },
        [&](std::size_t k) {
          return std::views::transform(edges_by_part.of(k),
                                       [&](std::uint32_t c) { return edges[c]; });
        },
        /*check=*/false, threads);
    for (const std::uint32_t c : edges_by_part.of(between_parts))
      change_edge(edges[c].edge, edges[c].delta_forward, edges[c].delta_backward, touched);
    stats.changed_nodes += terminals.size();
    stats.changed_edges += edges.size();
  }

  /// DynamicMaxFlow::change_by_parts with more than one part: the edges between parts checked,
  /// each part's changes made (change_each_part, checked as they go), then the edges between
  /// parts in their order.
  void change_by_parts(const ChangesByPart& changes, int threads) {
    const std::span<const EdgeChange> between = changes.edges[parts->count];
    for (std::size_t c = 0; c < between.size(); ++c) {
      const std::size_t e = between[c].edge;
      if (e >= num_edges || parts->of_edge[e] != parts->count) {
        throw std::invalid_argument("DynamicMaxFlow::change_by_parts: change " + std::to_string(c) +
                                    " of the edges between parts names edge " + std::to_string(e) +
                                    ", which is not between parts");
      }
    }
    const std::string misplaced = change_each_part(
        [&](std::size_t k) { return std::span(changes.terminals[k]); },
        [&](std::size_t k) { return std::span(changes.edges[k]); }, /*check=*/true, threads);
    if (!misplaced.empty()) {
      has_flow = false;
      touched.clear();
      touched_by_part.clear();
      orphans.clear();
      throw std::invalid_argument("DynamicMaxFlow::change_by_parts: " + misplaced +
                                  "; the flow is dropped (solve again)");
    }
    for (const EdgeChange& change : between)
      change_edge(change.edge, change.delta_forward, change.delta_backward, touched);
    for (const LargeVector<TerminalChange>& list : changes.terminals)
      stats.changed_nodes += list.size();
    for (const LargeVector<EdgeChange>& list : changes.edges) stats.changed_edges += list.size();
  }

  /// Makes each part's changes on one thread (up to `threads` at once): part k's terminal
  /// changes (the range terminals_of(k)), then its edge changes (edges_of(k)), in their order,
  /// its touched nodes listed apart and joined in part order after. With `check`, a part stops
  /// at its first change that names a node or edge outside it; returns the lowest such part's
  /// description ("" when every change was made).
  template <class TerminalsOf, class EdgesOf>
  std::string change_each_part(const TerminalsOf& terminals_of, const EdgesOf& edges_of, bool check,
                               int threads) {
    const std::vector<std::uint8_t>& part = parts->of_node;
    if (touched.empty()) stats = {};  // the first change since the last solve
    touched_by_part.clear();          // ordered below only when nothing was touched before
    const bool ordered = touched.empty();
    std::vector<OnOwnLine<std::vector<Index>>> listed(parts->count);
    std::vector<std::string> misplaced(parts->count);
    parallel_for(
        parts->count,
        [&](std::size_t k) {
          std::vector<Index>& list = listed[k].value;
          std::size_t c = 0;
          for (const TerminalChange& change : terminals_of(k)) {
            if (check && (change.node >= num_nodes || part[change.node] != k)) {
              misplaced[k] = "terminal change " + std::to_string(c) + " of part " +
                             std::to_string(k) + " names node " + std::to_string(change.node) +
                             ", which is not in that part";
              return;
            }
            change_terminal(change.node, change.delta, list);
            ++c;
          }
          c = 0;
          for (const EdgeChange& change : edges_of(k)) {
            if (check && (change.edge >= num_edges || parts->of_edge[change.edge] != k)) {
              misplaced[k] = "edge change " + std::to_string(c) + " of part " + std::to_string(k) +
                             " names edge " + std::to_string(change.edge) +
                             ", which is not inside that part";
              return;
            }
            change_edge(change.edge, change.delta_forward, change.delta_backward, list);
            ++c;
          }
        },
        threads);
    if (ordered) touched_by_part.push_back(touched.size());
    for (const OnOwnLine<std::vector<Index>>& own : listed) {
      const std::vector<Index>& list = own.value;
      touched.insert(touched.end(), list.begin(), list.end());
      if (ordered) touched_by_part.push_back(touched.size());
    }
    for (const std::string& problem : misplaced)
      if (!problem.empty()) return problem;
    return {};
  }

  /// Restores the search-tree invariants at the touched nodes (Search::repair).
  void repair_touched_nodes() {
    Search s = search();
    for (const Index i : touched) s.repair(i);
    touched.clear();
    touched_by_part.clear();
  }

  /// The search with the graph's own queue, orphans and clock.
  Search search() {
    return {nodes.data(), residual.data(),     *topology,         time, first_active, last_active,
            orphans,      stats.augmentations, stats.arcs_scanned};
  }
  void adopt_orphans() { search().adopt_orphans(); }
  void run() { search().run(); }

  [[nodiscard]] double cut_value(const FlowCapacities& caps) const {
    double total = 0.0;
    for (std::size_t i = 0; i < num_nodes; ++i)
      total += nodes[i].tree == kSourceTree ? caps.sink[i] : caps.source[i];
    const Topology& t = *topology;
    for (std::size_t e = 0; e < num_edges; ++e) {
      const Index forward = t.forward_arc[e];
      const bool to_source = nodes[t.head[forward]].tree == kSourceTree;
      const bool from_source = nodes[t.head[t.sister[forward]]].tree == kSourceTree;
      if (from_source && !to_source) total += caps.forward[e];
      if (!from_source && to_source) total += caps.backward[e];
    }
    return total;
  }
};

DynamicMaxFlow::DynamicMaxFlow() : impl_(std::make_unique<Impl>()) {}
DynamicMaxFlow::~DynamicMaxFlow() = default;
DynamicMaxFlow::DynamicMaxFlow(const DynamicMaxFlow& other)
    : impl_(std::make_unique<Impl>(*other.impl_, 1)) {}
DynamicMaxFlow::DynamicMaxFlow(const DynamicMaxFlow& other, int threads)
    : impl_(std::make_unique<Impl>(*other.impl_, threads)) {}
DynamicMaxFlow& DynamicMaxFlow::operator=(const DynamicMaxFlow& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_, 1);
  return *this;
}
DynamicMaxFlow::DynamicMaxFlow(DynamicMaxFlow&&) noexcept = default;
DynamicMaxFlow& DynamicMaxFlow::operator=(DynamicMaxFlow&&) noexcept = default;

void DynamicMaxFlow::build(std::size_t num_nodes, std::span<const FlowEdge> edges, int threads) {
  check_topology(num_nodes, edges, "DynamicMaxFlow::build", threads);
  if (num_nodes >= kTerminal || edges.size() >= (std::size_t{1} << 31)) {
    throw std::invalid_argument("DynamicMaxFlow::build: " + std::to_string(num_nodes) +
                                " nodes and " + std::to_string(edges.size()) +
                                " edges exceed the 32-bit arc indices");
  }
  auto topology = std::make_shared<Topology>();
  place_arcs(*topology, num_nodes, edges, threads);
  Impl& m = *impl_;
  m.num_nodes = num_nodes;
  m.num_edges = edges.size();
  m.topology = std::move(topology);
  m.parts.reset();
  // Fresh states by chunks on the threads (a near move builds a graph per move).
  m.nodes.resize(num_nodes);
  m.residual.resize(2 * edges.size());
  parallel_for_chunks(
      num_nodes, kPassChunk,
      [&](std::size_t, std::size_t first, std::size_t last) {
        std::fill(m.nodes.begin() + first, m.nodes.begin() + last, kFreshNode);
      },
      threads);
  parallel_for_chunks(
      m.residual.size(), kPassChunk,
      [&](std::size_t, std::size_t first, std::size_t last) {
        std::fill(m.residual.begin() + first, m.residual.begin() + last, 0.0);
      },
      threads);
  m.orphans.clear();
  m.touched.clear();
  m.touched_by_part.clear();
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
  if (!m.topology) throw std::logic_error("DynamicMaxFlow::solve: call build() first");
  m.check_solvable(caps);
  m.stats = {};
  m.start_from_zero_flow(caps);
  m.has_flow = true;
  m.run();
}

void DynamicMaxFlow::cut_into_parts(std::span<const std::uint8_t> part, int threads) {
  Impl& m = *impl_;
  if (!m.topology) throw std::logic_error("DynamicMaxFlow::cut_into_parts: call build() first");
  if (part.size() != m.num_nodes) {
    throw std::invalid_argument("DynamicMaxFlow::cut_into_parts: " + std::to_string(part.size()) +
                                " part ids for " + std::to_string(m.num_nodes) + " nodes");
  }
  auto parts = std::make_shared<Parts>();
  parts->of_node.assign(part.begin(), part.end());
  parts->count = part.empty() ? 1 : std::size_t{*std::max_element(part.begin(), part.end())} + 1;
  // Each part's nodes, ascending: the nodes sorted by part, by chunks on the threads.
  ByPart members = sort_by_part(
      part.size(), parts->count, [&](std::size_t i) -> std::size_t { return part[i]; }, threads);
  parts->members = std::move(members.positions);
  parts->first_member = std::move(members.first);
  // The edges between parts, found by chunks and joined in order.
  const Topology& t = *m.topology;
  std::vector<std::vector<std::size_t>> found((m.num_edges + kPassChunk - 1) / kPassChunk);
  parts->of_edge.resize(m.num_edges);
  parallel_for_chunks(
      m.num_edges, kPassChunk,
      [&](std::size_t c, std::size_t first, std::size_t last) {
        for (std::size_t e = first; e < last; ++e) {
          const Index forward = t.forward_arc[e];
          const std::uint8_t from = part[t.head[t.sister[forward]]];
          if (part[t.head[forward]] == from) {
            parts->of_edge[e] = from;
          } else {
            parts->of_edge[e] = static_cast<std::uint16_t>(parts->count);
            found[c].push_back(e);
          }
        }
      },
      threads);
  for (const std::vector<std::size_t>& edges : found)
    parts->between.insert(parts->between.end(), edges.begin(), edges.end());
  m.parts = std::move(parts);
}

std::size_t DynamicMaxFlow::num_parts() const noexcept {
  return impl_->parts ? impl_->parts->count : 1;
}

void DynamicMaxFlow::solve_cut_in_parts(const FlowCapacities& caps, int threads) {
  Impl& m = *impl_;
  if (num_parts() == 1) {
    solve_cut(caps);
    return;
  }
  m.check_solvable(caps, threads);
  m.stats = {};
  m.solve_in_parts(caps, threads);
  m.has_flow = true;
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

void DynamicMaxFlow::change_in_parts(std::span<const TerminalChange> terminals,
                                     std::span<const EdgeChange> edges, int threads) {
  Impl& m = *impl_;
  if (!m.has_flow) throw std::logic_error("DynamicMaxFlow::change_in_parts: solve() first");
  if (num_parts() > 1) {
    m.change_in_parts(terminals, edges, threads);  // checks the changes as it sorts them
    return;
  }
  m.check_changes(terminals, edges);
  if (m.touched.empty()) m.stats = {};
  for (const TerminalChange& change : terminals) m.change_terminal(change.node, change.delta);
  for (const EdgeChange& change : edges)
    m.change_edge(change.edge, change.delta_forward, change.delta_backward);
}

void DynamicMaxFlow::change_by_parts(const ChangesByPart& changes, int threads) {
  Impl& m = *impl_;
  if (!m.has_flow) throw std::logic_error("DynamicMaxFlow::change_by_parts: solve() first");
  const std::size_t parts = num_parts();
  if (changes.terminals.size() != parts || changes.edges.size() != parts + 1) {
    throw std::invalid_argument(
        "DynamicMaxFlow::change_by_parts: " + std::to_string(changes.terminals.size()) + " and " +
        std::to_string(changes.edges.size()) + " lists of changes for a graph in " +
        std::to_string(parts) + " parts (one per part, and the edges' one more)");
  }
  if (parts > 1) {
    m.change_by_parts(changes, threads);
    return;
  }
  if (!changes.edges[1].empty()) {
    throw std::invalid_argument(
        "DynamicMaxFlow::change_by_parts: edges between parts changed in a graph of one part");
  }
  change_in_parts(changes.terminals[0], changes.edges[0], threads);
}

void DynamicMaxFlow::resolve_in_parts(int threads) {
  Impl& m = *impl_;
  if (!m.has_flow) throw std::logic_error("DynamicMaxFlow::resolve: solve() first");
  if (num_parts() == 1) {
    resolve();
    return;
  }
  if (m.touched.empty()) m.stats = {};
  m.stats.reused = true;
  m.resolve_in_parts(threads);
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

void DynamicMaxFlow::source_set(std::span<char> in_source, int threads) const {
  const Impl& m = *impl_;
  if (in_source.size() != m.num_nodes)
    throw std::invalid_argument("DynamicMaxFlow::source_set: wrong size");
  parallel_for_chunks(
      m.num_nodes, kPassChunk,
      [&](std::size_t, std::size_t first, std::size_t last) {
        for (std::size_t i = first; i < last; ++i) in_source[i] = m.nodes[i].tree == kSourceTree;
      },
      threads);
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
  // Node states, arc residuals, and the orphan and touched lists a copy reserves in full.
  return num_nodes * (sizeof(Node) + 2 * sizeof(Index)) + 2 * num_edges * sizeof(double);
}

std::size_t DynamicMaxFlow::topology_bytes() const noexcept {
  const Topology* t = impl_->topology.get();
  if (t == nullptr) return 0;
  return (t->first_arc.size() + t->head.size() + t->sister.size() + t->forward_arc.size()) *
         sizeof(Index);
}

std::size_t apply_capacity_changes(DynamicMaxFlow& graph, const FlowCapacities& before,
                                   const FlowCapacities& after) {
  const std::size_t n = graph.num_nodes();
  const std::size_t m = graph.num_edges();
  for (const FlowCapacities* caps : {&before, &after}) {
    if (const std::string problem = check_capacities(*caps, n, m); !problem.empty())
      throw std::invalid_argument("apply_capacity_changes: " + problem);
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
  return changes;
}

std::size_t resolve_with(DynamicMaxFlow& graph, const FlowCapacities& before,
                         const FlowCapacities& after) {
  const std::size_t changes = apply_capacity_changes(graph, before, after);
  graph.resolve();
  return changes;
}

}  // namespace c2f

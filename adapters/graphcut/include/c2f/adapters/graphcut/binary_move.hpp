#pragma once
// Exact solution of the binary problems behind graph-cut moves, with QPBO for the
// non-submodular ones.
//
//   minimise  sum_i d[i] * b_i  +  sum_e p[e] * (1 - b_u) * b_v     over b in {0, 1}^n
//
// Any pairwise binary term with values A = E(0,0), B = E(0,1), C = E(1,0), D = E(1,1) is
// A + (C - A) b_u + (D - C) b_v + (B + C - A - D)(1 - b_u) b_v: see add_binary_term(). The
// term is submodular when p = B + C - A - D >= 0.
//
// Numerics: capacities are doubles computed from the double costs of the energy; callers
// accept a move only after checking its exact double energy.
//
// Recycling (Alahari, Kohli and Torr): with a backend that changes a solved graph and resumes
// from its flow (ReusingMaxFlow), every graph remembers the problem it was last solved for and
// a new problem only changes the nodes and pairs whose coefficients differ. A solver may give
// each recurring move (a key, e.g. the label of an expansion move) a graph of its own, so that
// the move costs in proportion to what changed since that key's last move. A key's first move
// uses a shared graph, re-solved from whatever move it solved before (a better start than zero
// flow even for another label); from its second move on it has a graph of its own (a copy of
// the graph solved last) while such graphs fit in a memory limit; when one does not, graphs
// idle since before that key's previous move are evicted, least recently used first
// (detail::MoveGraphs). With MoveOptions::first_move_own_graph a key's graph is its own from
// its first move, solved from zero flow. Other backends solve every move from zero flow.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "c2f/adapters/graphcut/detail/bands.hpp"
#include "c2f/adapters/graphcut/detail/move_graphs.hpp"
#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#include "c2f/adapters/maxflow/maxflow.hpp"
#include "c2f/core/default_init_allocator.hpp"
#include "c2f/core/huge_page_allocator.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

/// The value of one binary variable after a move: 0, 1, or left open by QPBO.
enum class MoveLabel : std::int8_t { zero = 0, one = 1, unlabeled = -1 };

struct BinaryMoveStats {
  bool used_qpbo = false;     ///< some p[e] < 0: solved on the doubled graph
  bool recycled = false;      ///< solved on the key's own graph, from its previous flow
  std::size_t unlabeled = 0;  ///< variables QPBO left open
  double flow_seconds = 0.0;  ///< time inside the max-flow backend
};

/// Adds the pairwise binary term (A, B, C, D) of pair e = (u, v) to d and p.
inline void add_binary_term(std::span<double> d, std::span<double> p, std::size_t e, FlowNode u,
                            FlowNode v, double A, double B, double C, double D) noexcept {
  d[u] += C - A;
  d[v] += D - C;
  p[e] += B + C - A - D;
}

template <MaxFlow Backend>
class BinaryMoveSolver {
 public:
  /// Fixes the topology: n binary variables and the pairs (u, v) that carry pairwise terms.
  /// The n-node graph and the 2n-node QPBO graph are built on first need. Keeps the threads
  /// solve_in_parts gave (checks the pairs on them) and goes back to one part.
  void bind(std::size_t num_nodes, std::span<const FlowEdge> pairs) {
    check_topology(num_nodes, pairs, "BinaryMoveSolver::bind", parts_threads_);
    num_nodes_ = num_nodes;
    parts_ = 1;
    pairs_of_part_.clear();
    pairs_.assign(pairs.begin(), pairs.end());
    doubled_pairs_.clear();
    doubled_ready_ = false;
    graphs_.clear();
  }

  /// The topology of the moves of a pairwise energy: one binary variable per variable, one
  /// pair per edge (same order).
  void bind(const PairwiseEnergy& energy) {
    std::vector<FlowEdge> pairs(energy.edges().size());
    for (std::size_t e = 0; e < pairs.size(); ++e)
      pairs[e] = {energy.edges()[e].u, energy.edges()[e].v};
    bind(energy.num_variables(), pairs);
  }

  /// Lets moves with keys 0..num_keys-1 keep graphs of their own (recycling) while all such
  /// graphs stay within memory_limit bytes. Only backends that resume from their flow
  /// (ReusingMaxFlow) recycle; with first_move_own a key's graph is its own from its first
  /// move (MoveOptions::first_move_own_graph). Call after bind(); a later bind() ends recycling.
  void recycle(std::size_t num_keys, std::size_t memory_limit, bool first_move_own = false) {
    graphs_.recycle(num_keys, memory_limit, first_move_own);
  }

  /// Solves every move's max-flow in `parts` parts at once on up to `threads` threads, when the
  /// backend can (PartedMaxFlow; and builds, changes and reads its graphs on those threads): node
  /// i, and its QPBO complement, in part i * parts / n (bands of indices). 1: one part. Call after
  /// bind(), before the first solve.
  void solve_in_parts(std::size_t parts, int threads) {
    parts_ = std::max<std::size_t>(1, std::min<std::size_t>(parts, 255));
    parts_threads_ = threads;
    pairs_of_part_.clear();
  }

  /// Frees every graph (they are built again on the next solve); recycling goes on as
  /// recycle() set it.
  void drop_graphs() { graphs_.drop(); }

  /// Bytes of the graphs the keys own so far.
  [[nodiscard]] std::size_t recycled_bytes() const noexcept { return graphs_.owned_bytes(); }
  /// Graphs evicted to make room for others since recycle() (detail::MoveGraphs).
  [[nodiscard]] std::size_t evicted_graphs() const noexcept { return graphs_.evictions(); }

  /// Minimises the problem above. With every p[e] >= 0 one max-flow gives an exact minimiser
  /// and every variable is labelled. Otherwise QPBO (Kolmogorov and Rother 2007) on the doubled
  /// graph gives a partial labelling with weak persistency: the labelled part can be imposed on
  /// any b without increasing the objective, so keeping unlabelled variables at 0 (the current
  /// labels) never does worse than b = 0. `key` (see recycle()) names the recurring move this
  /// is. Throws std::invalid_argument for sizes that do not fit or a coefficient that is not
  /// finite.
  BinaryMoveStats solve(std::span<const double> d, std::span<const double> p,
                        std::span<MoveLabel> out, std::size_t key = kNoKey) {
    if (d.size() != num_nodes_ || out.size() != num_nodes_ || p.size() != pairs_.size()) {
      throw std::invalid_argument("BinaryMoveSolver::solve: sizes do not match the bound topology");
    }
    BinaryMoveStats stats;
    const auto [submodular, finite] = scan_coefficients(d, p);
    if (!finite)
      throw std::invalid_argument("BinaryMoveSolver::solve: a coefficient is not finite");
    const auto start = std::chrono::steady_clock::now();
    if (submodular) {
      copy_node_values(d);
      MoveGraph& graph = graph_for(key, GraphKind::plain, stats);
      solve_graph(graph, GraphKind::plain, p);
      detail::for_each_band(
          num_nodes_,
          [&](std::size_t, std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i)
              out[i] = in_source_[i] ? MoveLabel::zero : MoveLabel::one;
          },
          parts_threads_);
    } else {
      stats.used_qpbo = true;
      // p (1 - b_u) b_v with p < 0 equals p (1 - b_u) + |p| (1 - b_u) (1 - b_v): the first part
      // moves |p| onto b_u's coefficient (plus a constant), the second is submodular in
      // (b_u, b'_v).
      copy_node_values(d);
      for (std::size_t e = 0; e < pairs_.size(); ++e) {
        if (p[e] < 0.0) node_values_[pairs_[e].from] -= p[e];
      }
      MoveGraph& graph = graph_for(key, GraphKind::qpbo, stats);
      solve_graph(graph, GraphKind::qpbo, p);
      const std::size_t n = num_nodes_;
      band_counts_.assign(detail::band_count(n), 0);
      detail::for_each_band(
          n,
          [&](std::size_t b, std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i) {
              const bool node_source = in_source_[i] != 0;
              const bool complement_source = in_source_[n + i] != 0;
              if (node_source == complement_source) {
                out[i] = MoveLabel::unlabeled;
                ++band_counts_[b];
              } else {
                out[i] = node_source ? MoveLabel::zero : MoveLabel::one;
              }
            }
          },
          parts_threads_);
      for (const std::size_t count : band_counts_) stats.unlabeled += count;
    }
    stats.flow_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
  }

 private:
  static constexpr std::size_t kNoKey = detail::MoveGraphs<Backend>::kNoKey;
  using GraphKind = detail::GraphKind;
  using MoveGraph = detail::MoveGraph<Backend>;

  /// node_values_ = d, by bands on the threads the parts are solved on.
  void copy_node_values(std::span<const double> d) {
    node_values_.resize(d.size());
    detail::for_each_band(
        d.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          std::copy(d.begin() + first, d.begin() + last, node_values_.begin() + first);
        },
        parts_threads_);
  }

  /// Whether every p[e] >= 0, and whether every d[i] and p[e] is finite; by bands on the
  /// threads the parts are solved on.
  std::pair<bool, bool> scan_coefficients(std::span<const double> d, std::span<const double> p) {
    const std::size_t p_bands = detail::band_count(p.size());
    band_flags_.assign(p_bands + detail::band_count(d.size()), 0);
    constexpr std::uint8_t kNegative = 1, kNotFinite = 2;
    detail::for_each_band(
        p.size(),
        [&](std::size_t b, std::size_t first, std::size_t last) {
          bool submodular = true, finite = true;
          for (std::size_t e = first; e < last; ++e) {
            submodular &= p[e] >= 0.0;
            finite &= std::isfinite(p[e]);
          }
          band_flags_[b] = (submodular ? 0 : kNegative) | (finite ? 0 : kNotFinite);
        },
        parts_threads_);
    detail::for_each_band(
        d.size(),
        [&](std::size_t b, std::size_t first, std::size_t last) {
          bool finite = true;
          for (std::size_t i = first; i < last; ++i) finite &= std::isfinite(d[i]);
          band_flags_[p_bands + b] = finite ? 0 : kNotFinite;
        },
        parts_threads_);
    std::uint8_t any = 0;
    for (const std::uint8_t flags : band_flags_) any |= flags;
    return {(any & kNegative) == 0, (any & kNotFinite) == 0};
  }

  [[nodiscard]] std::size_t graph_nodes(GraphKind kind) const noexcept {
    return kind == GraphKind::plain ? num_nodes_ : 2 * num_nodes_;
  }
  [[nodiscard]] std::span<const FlowEdge> graph_edges(GraphKind kind) {
    if (kind == GraphKind::plain) return pairs_;
    if (!doubled_ready_) prepare_qpbo();
    return doubled_pairs_;
  }

  /// The graph that solves a move of this key and kind (detail::MoveGraphs), built.
  MoveGraph& graph_for(std::size_t key, GraphKind kind, BinaryMoveStats& stats) {
    MoveGraph& graph =
        graphs_.acquire(key, kind, graph_bytes(kind), stats.recycled, parts_threads_);
    if (!graph.built) {
      if constexpr (PartedMaxFlow<Backend>) {
        graph.graph.build(graph_nodes(kind), graph_edges(kind), parts_threads_);
        if (parts_ > 1) graph.graph.cut_into_parts(node_parts(kind), parts_threads_);
      } else {
        graph.graph.build(graph_nodes(kind), graph_edges(kind));
      }
      graph.built = true;
    }
    return graph;
  }

  /// The part of variable i (and of its QPBO complement n + i) when moves are solved in parts:
  /// bands of indices, i * parts / n.
  [[nodiscard]] std::size_t part_of(std::size_t i) const noexcept {
    return i * parts_ / num_nodes_;
  }

  /// Each node's part for solve_in_parts (part_of; node n + i (QPBO) with i).
  [[nodiscard]] std::vector<std::uint8_t> node_parts(GraphKind kind) const {
    std::vector<std::uint8_t> part(graph_nodes(kind));
    detail::for_each_band(
        num_nodes_,
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t i = first; i < last; ++i)
            part[i] = static_cast<std::uint8_t>(part_of(i));
        },
        parts_threads_);
    if (kind == GraphKind::qpbo)
      std::copy(part.begin(), part.begin() + num_nodes_, part.begin() + num_nodes_);
    return part;
  }

  /// One graph of this kind with its problem (what a key's graphs cost), in bytes.
  [[nodiscard]] std::size_t graph_bytes(GraphKind kind) {
    std::size_t bytes = (graph_nodes(kind) + pairs_.size()) * sizeof(double);
    if constexpr (ReusingMaxFlow<Backend>)
      bytes += Backend::memory_bytes_for(graph_nodes(kind), graph_edges(kind).size());
    return bytes;
  }

  /// Solves `graph` for node_values_ and p (a reusing backend: by changing what differs from
  /// the problem it holds; else from zero flow) and leaves its source set in in_source_.
  void solve_graph(MoveGraph& graph, GraphKind kind, std::span<const double> p) {
    const std::size_t nodes = graph_nodes(kind);
    in_source_.resize(nodes);
    if constexpr (ReusingMaxFlow<Backend>) {
      if (graph.solved) {
        change_graph(graph, kind, p);
        if constexpr (PartedMaxFlow<Backend>) {
          graph.graph.resolve_in_parts(parts_threads_);
        } else {
          graph.graph.resolve();
        }
        read_source_set(graph.graph);
        return;
      }
    }
    fill_capacities(kind, p);
    const FlowCapacities& caps = kind == GraphKind::plain ? plain_caps_ : qpbo_caps_;
    if constexpr (requires(const Backend& g, std::span<char> side) {
                    graph.graph.solve_cut(caps);
                    g.source_set(side);
                  }) {
      if constexpr (PartedMaxFlow<Backend>) {
        graph.graph.solve_cut_in_parts(caps, parts_threads_);
      } else {
        graph.graph.solve_cut(caps);
      }
      read_source_set(graph.graph);
    } else {
      graph.graph.solve(caps);
      for (std::size_t i = 0; i < nodes; ++i)
        in_source_[i] = graph.graph.in_source_set(static_cast<FlowNode>(i));
    }
    if constexpr (ReusingMaxFlow<Backend>) {
      graph.node_values = node_values_;
      graph.pair_values.assign(p.begin(), p.end());
      graph.solved = true;
    }
  }

  /// The solved graph's source set into in_source_ (on the parts' threads when the backend can).
  void read_source_set(const Backend& graph) {
    if constexpr (PartedMaxFlow<Backend>) {
      graph.source_set(in_source_, parts_threads_);
    } else {
      graph.source_set(in_source_);
    }
  }

  // The plain graph: node i has source capacity max(d_i, 0) and sink capacity max(-d_i, 0);
  // pair e's edge (u, v) carries p[e] forward.
  //
  // The QPBO graph: node i stands for b_i and node n + i for its complement (b_i = 0 when n + i
  // is on the sink side); with h = adjusted d_i / 2, node i has source - sink = h and node n + i
  // has -h. Pair e owns edges 4e..4e+3: (u, v), (v', u'), (u, v'), (v, u'); the first two carry
  // p/2 when p >= 0 (submodular), the last two -p/2 when p < 0; backward capacities stay 0.
  void fill_capacities(GraphKind kind, std::span<const double> p) {
    const std::size_t n = num_nodes_;
    // By bands on the threads the parts are solved on (each entry written by one band).
    if (kind == GraphKind::plain) {
      plain_caps_.resize(n, pairs_.size());
      detail::for_each_band(
          n,
          [&](std::size_t, std::size_t first, std::size_t last) {
            for (std::size_t i = first; i < last; ++i) {
              plain_caps_.source[i] = std::max(node_values_[i], 0.0);
              plain_caps_.sink[i] = std::max(-node_values_[i], 0.0);
            }
          },
          parts_threads_);
      detail::for_each_band(
          pairs_.size(),
          [&](std::size_t, std::size_t first, std::size_t last) {
            for (std::size_t e = first; e < last; ++e) {
              plain_caps_.forward[e] = p[e];
              plain_caps_.backward[e] = 0.0;
            }
          },
          parts_threads_);
      return;
    }
    detail::for_each_band(
        n,
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t i = first; i < last; ++i) {
            const double half = 0.5 * node_values_[i];
            qpbo_caps_.source[i] = std::max(half, 0.0);
            qpbo_caps_.sink[i] = std::max(-half, 0.0);
            qpbo_caps_.source[n + i] = std::max(-half, 0.0);
            qpbo_caps_.sink[n + i] = std::max(half, 0.0);
          }
        },
        parts_threads_);
    detail::for_each_band(
        pairs_.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t e = first; e < last; ++e) {
            const double half = 0.5 * p[e];
            qpbo_caps_.forward[4 * e + 0] = qpbo_caps_.forward[4 * e + 1] = std::max(half, 0.0);
            qpbo_caps_.forward[4 * e + 2] = qpbo_caps_.forward[4 * e + 3] = std::max(-half, 0.0);
            for (std::size_t a = 4 * e; a < 4 * e + 4; ++a) qpbo_caps_.backward[a] = 0.0;
          }
        },
        parts_threads_);
  }

  /// Changes a solved graph from the problem it holds to (node_values_, p): only the nodes and
  /// pairs whose coefficients differ, by the differences of the capacities above. The changes
  /// are found by bands on the parts' threads and listed in index order (nodes, then pairs);
  /// a backend that can (PartedMaxFlow) makes them by parts on those threads. In parts they
  /// are found and made by parts (change_graph_by_parts).
  void change_graph(MoveGraph& graph, GraphKind kind, std::span<const double> p) {
    if constexpr (PartedMaxFlow<Backend>) {
      if (parts_ > 1) {
        change_graph_by_parts(graph, kind, p);
        return;
      }
    }
    terminal_changes_.clear();
    detail::append_by_bands(
        num_nodes_, band_terminals_, terminal_changes_,
        [&](std::size_t first, std::size_t last, LargeVector<TerminalChange>& out) {
          for (std::size_t i = first; i < last; ++i) {
            if (node_values_[i] == graph.node_values[i]) continue;
            list_node_change(kind, i, graph.node_values[i], node_values_[i], out);
            graph.node_values[i] = node_values_[i];
          }
        },
        parts_threads_);
    edge_changes_.clear();
    detail::append_by_bands(
        pairs_.size(), band_edges_, edge_changes_,
        [&](std::size_t first, std::size_t last, LargeVector<EdgeChange>& out) {
          for (std::size_t e = first; e < last; ++e) {
            if (p[e] == graph.pair_values[e]) continue;
            list_pair_change(kind, e, graph.pair_values[e], p[e], out);
            graph.pair_values[e] = p[e];
          }
        },
        parts_threads_);
    Backend& g = graph.graph;
    if constexpr (PartedMaxFlow<Backend>) {
      g.change_in_parts(terminal_changes_, edge_changes_, parts_threads_);
    } else {
      for (const TerminalChange& change : terminal_changes_)
        g.change_terminal(change.node, change.delta);
      for (const EdgeChange& change : edge_changes_)
        g.change_edge(change.edge, change.delta_forward, change.delta_backward);
    }
  }

  /// change_graph in parts (parts_ > 1): part k's changes found on one thread, its nodes in
  /// index order and then the pairs inside it (pairs_of_part_) in theirs, all parts at once on
  /// the parts' threads; then the pairs between parts. Made by the backend's change_by_parts
  /// (each part's on one thread, no sorting): the same changes, in the same order per part, as
  /// the joined lists change_in_parts would sort.
  void change_graph_by_parts(MoveGraph& graph, GraphKind kind,
                             std::span<const double> p) requires PartedMaxFlow<Backend> {
    if (pairs_of_part_.empty()) list_pairs_by_part();
    changes_by_part_.clear(parts_);
    const auto list_pairs = [&](std::span<const std::uint32_t> pairs,
                                LargeVector<EdgeChange>& out) {
      for (const std::uint32_t e : pairs) {
        if (p[e] == graph.pair_values[e]) continue;
        list_pair_change(kind, e, graph.pair_values[e], p[e], out);
        graph.pair_values[e] = p[e];
      }
    };
    detail::for_each_band(  // bands of one part
        parts_,
        [&](std::size_t k, std::size_t, std::size_t) {
          LargeVector<TerminalChange>& terminals = changes_by_part_.terminals[k];
          for (std::size_t i = first_node_of_part(k); i < first_node_of_part(k + 1); ++i) {
            if (node_values_[i] == graph.node_values[i]) continue;
            list_node_change(kind, i, graph.node_values[i], node_values_[i], terminals);
            graph.node_values[i] = node_values_[i];
          }
          list_pairs(pairs_of_part_[k], changes_by_part_.edges[k]);
        },
        parts_threads_, 1);
    list_pairs(pairs_of_part_[parts_], changes_by_part_.edges[parts_]);
    graph.graph.change_by_parts(changes_by_part_, parts_threads_);
  }

  /// The first node of part k (the least i with part_of(i) = k), n for k = parts_.
  [[nodiscard]] std::size_t first_node_of_part(std::size_t k) const noexcept {
    return (k * num_nodes_ + parts_ - 1) / parts_;
  }

  /// pairs_of_part_: for each part the pairs whose nodes are both in it, then the pairs
  /// between parts, each list ascending. A pair's QPBO edges join the same parts as the pair
  /// (node n + i is in node i's part), so the lists serve both kinds of graph.
  void list_pairs_by_part() {
    pairs_of_part_.assign(parts_ + 1, {});
    for (std::size_t e = 0; e < pairs_.size(); ++e) {
      const std::size_t from = part_of(pairs_[e].from);
      const std::size_t to = part_of(pairs_[e].to);
      pairs_of_part_[from == to ? from : parts_].push_back(static_cast<std::uint32_t>(e));
    }
  }

  /// The terminal changes of node i's coefficient going from `before` to `after`.
  void list_node_change(GraphKind kind, std::size_t i, double before, double after,
                        LargeVector<TerminalChange>& out) const {
    if (kind == GraphKind::plain) {
      out.push_back({static_cast<FlowNode>(i), after - before});
      return;
    }
    const double delta = 0.5 * after - 0.5 * before;
    out.push_back({static_cast<FlowNode>(i), delta});
    out.push_back({static_cast<FlowNode>(num_nodes_ + i), -delta});
  }

  /// The edge changes of pair e's coefficient going from `before` to `after`.
  static void list_pair_change(GraphKind kind, std::size_t e, double before, double after,
                               LargeVector<EdgeChange>& out) {
    if (kind == GraphKind::plain) {
      out.push_back({e, after - before, 0.0});
      return;
    }
    const double submodular = std::max(0.5 * after, 0.0) - std::max(0.5 * before, 0.0);
    const double crossing = std::max(-0.5 * after, 0.0) - std::max(-0.5 * before, 0.0);
    if (submodular != 0.0) {
      out.push_back({4 * e + 0, submodular, 0.0});
      out.push_back({4 * e + 1, submodular, 0.0});
    }
    if (crossing != 0.0) {
      out.push_back({4 * e + 2, crossing, 0.0});
      out.push_back({4 * e + 3, crossing, 0.0});
    }
  }

  /// The QPBO graph's edges (see fill_capacities), by bands of pairs.
  void prepare_qpbo() {
    const auto n = static_cast<FlowNode>(num_nodes_);
    doubled_pairs_.resize(4 * pairs_.size());
    detail::for_each_band(
        pairs_.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t e = first; e < last; ++e) {
            const FlowEdge& pair = pairs_[e];
            doubled_pairs_[4 * e + 0] = {pair.from, pair.to};
            doubled_pairs_[4 * e + 1] = {pair.to + n, pair.from + n};
            doubled_pairs_[4 * e + 2] = {pair.from, pair.to + n};
            doubled_pairs_[4 * e + 3] = {pair.to, pair.from + n};
          }
        },
        parts_threads_);
    qpbo_caps_.resize(2 * num_nodes_, doubled_pairs_.size());
    doubled_ready_ = true;
  }

  std::size_t num_nodes_ = 0;
  std::size_t parts_ = 1;  ///< solve_in_parts
  int parts_threads_ = 1;
  LargeVector<FlowEdge> pairs_;
  std::vector<FlowEdge> doubled_pairs_;  // the QPBO graph's edges, once some move needs them
  bool doubled_ready_ = false;
  // Work arrays of every move, whichever graph solves it.
  LargeVector<double> node_values_;  // d, or QPBO's adjusted d
  FlowCapacities plain_caps_;
  FlowCapacities qpbo_caps_;
  LargeVector<char> in_source_;           // the last solve's source set
  std::vector<std::uint8_t> band_flags_;  // scan_coefficients' findings per band
  std::vector<std::size_t> band_counts_;  // unlabelled variables per band of a QPBO move
  // change_graph's changes, per band and then joined (unwritten until the bands' copies).
  std::vector<LargeVector<TerminalChange>> band_terminals_;
  std::vector<LargeVector<EdgeChange>> band_edges_;
  DefaultInitVector<TerminalChange> terminal_changes_;
  DefaultInitVector<EdgeChange> edge_changes_;
  // change_graph_by_parts' pairs by part (found on its first call after bind or solve_in_parts)
  // and its changes.
  std::vector<std::vector<std::uint32_t>> pairs_of_part_;
  ChangesByPart changes_by_part_;
  detail::MoveGraphs<Backend> graphs_;
};

}  // namespace c2f

#pragma once
// Internal to BinaryMoveSolver: which max-flow graph solves each move (the recycling policy
// that binary_move.hpp describes). Installed only because the solver templates include it.

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>
#include <utility>
#include <vector>

#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#include "c2f/adapters/maxflow/maxflow.hpp"
#include "c2f/core/huge_page_allocator.hpp"

namespace c2f::detail {

/// The n-node graph of submodular moves and the doubled graph of QPBO moves.
enum class GraphKind : std::size_t { plain = 0, qpbo = 1 };

/// A graph and, for a reusing backend, the problem it holds: the node coefficients (d, or
/// QPBO's adjusted d) and the pair coefficients p it was last solved for.
template <MaxFlow Backend>
struct MoveGraph {
  Backend graph;
  bool built = false;   ///< the topology is in place
  bool solved = false;  ///< node_values and pair_values hold its last problem
  LargeVector<double> node_values, pair_values;
};

/// A copy of `graph`; a backend that can (DynamicMaxFlow) faults its new memory in on up to
/// `threads` threads, which is most of what copying a large graph costs.
template <MaxFlow Backend>
std::unique_ptr<MoveGraph<Backend>> copy_of(const MoveGraph<Backend>& graph, int threads) {
  if constexpr (std::is_constructible_v<Backend, const Backend&, int>) {
    return std::unique_ptr<MoveGraph<Backend>>(
        new MoveGraph<Backend>{Backend(graph.graph, threads), graph.built, graph.solved,
                               graph.node_values, graph.pair_values});
  } else {
    return std::make_unique<MoveGraph<Backend>>(graph);
  }
}

/// One shared graph per kind, and for a reusing backend (ReusingMaxFlow) graphs of their own
/// for the keys 0..num_keys-1 from their second move on, while those fit in a memory limit.
/// When a key's graph does not fit, the graphs idle longest are evicted to make room, but only
/// those idle since before the key's own previous move: under a repeating order of keys (a
/// sweep over the labels) every other graph was used more recently, so a full budget keeps
/// the graphs it has rather than trading one miss for another at every move; what it evicts
/// is what stopped being used (a key's graph of the kind its moves no longer need, keys a
/// visit order skips).
template <MaxFlow Backend>
class MoveGraphs {
 public:
  static constexpr std::size_t kNoKey = static_cast<std::size_t>(-1);

  /// Forgets every graph.
  void clear() {
    shared_[0] = MoveGraph<Backend>{};
    shared_[1] = MoveGraph<Backend>{};
    own_.clear();
    last_key_[0] = last_key_[1] = kNoKey;
    owned_bytes_ = 0;
    clock_ = 0;
    evictions_ = 0;
  }

  /// Frees every graph; keys may own graphs again as recycle() allowed.
  void drop() {
    const std::size_t keys = own_.size();
    clear();
    own_.resize(keys);
  }

  /// Keys 0..num_keys-1 may own graphs while all owned graphs take at most memory_limit bytes:
  /// from their second move on, a copy of the graph solved last; with first_move_own, from
  /// their first move on, a graph of their own solved from zero flow
  /// (MoveOptions::first_move_own_graph).
  void recycle(std::size_t num_keys, std::size_t memory_limit, bool first_move_own = false) {
    own_.clear();
    own_.resize(num_keys);
    memory_limit_ = memory_limit;
    first_move_own_ = first_move_own;
    owned_bytes_ = 0;
    evictions_ = 0;
  }

  [[nodiscard]] std::size_t owned_bytes() const noexcept { return owned_bytes_; }
  /// Graphs evicted to make room since recycle().
  [[nodiscard]] std::size_t evictions() const noexcept { return evictions_; }

  /// The graph for a move of this key and kind (graph_bytes: what one such graph with its
  /// problem takes). A key with a graph of its own gets it back (recycled = true). A key seen
  /// before without one gets one when it fits, after evicting graphs idle since before its
  /// previous move if needed: a copy of the graph of this kind solved last (made on up to
  /// `threads` threads, copy_of). Otherwise, and on a key's first move, which has nothing to
  /// recycle, the shared graph. The graph may still need building (built == false).
  MoveGraph<Backend>& acquire(std::size_t key, GraphKind kind, std::size_t graph_bytes,
                              bool& recycled, int threads) {
    const auto k = static_cast<std::size_t>(kind);
    recycled = false;
    ++clock_;
    MoveGraph<Backend>* graph = nullptr;
    if constexpr (ReusingMaxFlow<Backend>) {
      if (key < own_.size()) {
        Owned& own = own_[key];
        std::unique_ptr<MoveGraph<Backend>>& mine = own.graphs[k];
        const std::uint64_t previous_use = own.last_use[k];  // 0: never
        own.last_use[k] = clock_;
        if (mine) {
          recycled = true;
        } else if ((first_move_own_ || previous_use > 0) && make_room(graph_bytes, previous_use)) {
          const MoveGraph<Backend>* last = first_move_own_ ? nullptr : last_graph(kind);
          mine = last != nullptr ? copy_of(*last, threads) : std::make_unique<MoveGraph<Backend>>();
          own.bytes[k] = graph_bytes;
          owned_bytes_ += graph_bytes;
        }
        graph = mine.get();
      }
    }
    if (graph == nullptr) graph = &shared_[k];
    last_key_[k] = graph == &shared_[k] ? kNoKey : key;
    return *graph;
  }

 private:
  struct Owned {  // by GraphKind
    std::array<std::unique_ptr<MoveGraph<Backend>>, 2> graphs;
    std::array<std::size_t, 2> bytes = {0, 0};
    std::array<std::uint64_t, 2> last_use = {0, 0};  // acquire() count at the last move; 0: none
  };

  /// Evicts owned graphs last used before `before`, least recently used first, until `bytes`
  /// more fit in the limit; false when they cannot (then nothing is evicted). The graphs that
  /// solved last (last_key_) are never evicted: they were used after any such key.
  bool make_room(std::size_t bytes, std::uint64_t before) {
    if (bytes > memory_limit_) return false;
    std::size_t freeable = 0;
    std::vector<std::pair<std::uint64_t, std::pair<std::size_t, std::size_t>>> idle;
    if (owned_bytes_ + bytes > memory_limit_) {
      for (std::size_t key = 0; key < own_.size(); ++key) {
        for (std::size_t k = 0; k < 2; ++k) {
          if (own_[key].graphs[k] && own_[key].last_use[k] < before) {
            idle.push_back({own_[key].last_use[k], {key, k}});
            freeable += own_[key].bytes[k];
          }
        }
      }
      if (owned_bytes_ - freeable + bytes > memory_limit_) return false;
      std::sort(idle.begin(), idle.end());
    }
    for (std::size_t i = 0; owned_bytes_ + bytes > memory_limit_; ++i) {
      Owned& own = own_[idle[i].second.first];
      const std::size_t k = idle[i].second.second;
      own.graphs[k].reset();
      if (last_key_[k] == idle[i].second.first) last_key_[k] = kNoKey;
      owned_bytes_ -= own.bytes[k];
      own.bytes[k] = 0;
      ++evictions_;
    }
    return true;
  }

  /// The graph of this kind that solved last (null before the first such solve).
  const MoveGraph<Backend>* last_graph(GraphKind kind) const {
    const auto k = static_cast<std::size_t>(kind);
    if (last_key_[k] == kNoKey) return shared_[k].solved ? &shared_[k] : nullptr;
    return own_[last_key_[k]].graphs[k].get();
  }

  MoveGraph<Backend> shared_[2];                // by GraphKind
  std::vector<Owned> own_;                      // per key
  std::size_t last_key_[2] = {kNoKey, kNoKey};  // whose graph of each kind solved last
  std::size_t memory_limit_ = 0;
  bool first_move_own_ = false;  // recycle()'s first_move_own
  std::size_t owned_bytes_ = 0;
  std::uint64_t clock_ = 0;  // acquire() calls since clear()
  std::size_t evictions_ = 0;
};

}  // namespace c2f::detail

#pragma once
// Internal to BinaryMoveSolver: which max-flow graph solves each move (the recycling policy
// that binary_move.hpp describes). Installed only because the solver templates include it.

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#include "c2f/adapters/maxflow/maxflow.hpp"

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
  std::vector<double> node_values, pair_values;
};

/// One shared graph per kind, and for a reusing backend (ReusingMaxFlow) graphs of their own
/// for the keys 0..num_keys-1 from their second move on, while those fit in a memory limit.
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
  }

  /// Keys 0..num_keys-1 may own graphs while all owned graphs take at most memory_limit bytes.
  void recycle(std::size_t num_keys, std::size_t memory_limit) {
    own_.clear();
    own_.resize(num_keys);
    memory_limit_ = memory_limit;
    owned_bytes_ = 0;
  }

  [[nodiscard]] std::size_t owned_bytes() const noexcept { return owned_bytes_; }

  /// The graph for a move of this key and kind (graph_bytes: what one such graph with its
  /// problem takes). A key with a graph of its own gets it back (recycled = true). A key seen
  /// before without one gets one when it fits: a copy of the graph of this kind solved last.
  /// Otherwise, and on a key's first move, which has nothing to recycle, the shared graph.
  /// The graph may still need building (built == false).
  MoveGraph<Backend>& acquire(std::size_t key, GraphKind kind, std::size_t graph_bytes,
                              bool& recycled) {
    const auto k = static_cast<std::size_t>(kind);
    recycled = false;
    MoveGraph<Backend>* graph = nullptr;
    if constexpr (ReusingMaxFlow<Backend>) {
      if (key < own_.size()) {
        Owned& own = own_[key];
        std::unique_ptr<MoveGraph<Backend>>& mine = own.graphs[k];
        const bool seen = own.seen[k];
        own.seen[k] = true;
        if (mine) {
          recycled = true;
        } else if (seen && owned_bytes_ + graph_bytes <= memory_limit_) {
          const MoveGraph<Backend>* last = last_graph(kind);
          mine = last != nullptr ? std::make_unique<MoveGraph<Backend>>(*last)
                                 : std::make_unique<MoveGraph<Backend>>();
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
    std::array<bool, 2> seen = {false, false};
  };

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
  std::size_t owned_bytes_ = 0;
};

}  // namespace c2f::detail

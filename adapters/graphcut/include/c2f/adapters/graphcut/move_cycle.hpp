#pragma once
// The order in which graph-cut solvers visit labels (expansion) or label pairs (swap).

#include <algorithm>
#include <cstdint>
#include <random>
#include <span>
#include <utility>
#include <vector>

#include "c2f/core/labeling.hpp"
#include "c2f/core/visit_order.hpp"

namespace c2f {

/// How many variables take each label 0..num_labels-1 (labels assumed validated).
inline std::vector<std::size_t> label_counts(std::span<const Label> labeling, int num_labels) {
  std::vector<std::size_t> count(static_cast<std::size_t>(num_labels), 0);
  for (const Label l : labeling) ++count[static_cast<std::size_t>(l)];
  return count;
}

/// Stably sorts moves by decreasing use(move): VisitOrder::frequency's order. (A sort of
/// (use, position) keys rather than std::stable_sort, whose buffer is deprecated in the
/// libstdc++ 12 that clang 19 compiles against.)
template <class Move, class Use>
void sort_most_used_first(std::vector<Move>& moves, Use use) {
  using Key = std::pair<decltype(use(moves.front())), std::size_t>;
  std::vector<Key> keys;
  keys.reserve(moves.size());
  for (std::size_t i = 0; i < moves.size(); ++i) keys.emplace_back(use(moves[i]), i);
  std::sort(keys.begin(), keys.end(), [](const Key& a, const Key& b) {
    return a.first > b.first || (a.first == b.first && a.second < b.second);
  });
  std::vector<Move> sorted;
  sorted.reserve(moves.size());
  for (const Key& key : keys) sorted.push_back(moves[key.second]);
  moves = std::move(sorted);
}

/// Cycles endlessly through a list of moves (labels or label pairs) in the chosen order. The
/// list arrives already in sequential or frequency order; VisitOrder::random reshuffles it at
/// the start of every cycle.
template <class Move>
class MoveCycle {
 public:
  MoveCycle() = default;
  MoveCycle(std::vector<Move> moves, VisitOrder order, std::uint64_t seed)
      : moves_(std::move(moves)), order_(order), rng_(seed) {}

  /// The next move; starts a new (reshuffled, for VisitOrder::random) cycle when one ends.
  /// Requires a non-empty move list.
  const Move& next() {
    if (position_ == 0 && order_ == VisitOrder::random)
      std::shuffle(moves_.begin(), moves_.end(), rng_);
    const Move& move = moves_[position_];
    position_ = (position_ + 1) % moves_.size();
    return move;
  }
  [[nodiscard]] std::size_t cycle_length() const noexcept { return moves_.size(); }

 private:
  std::vector<Move> moves_;
  VisitOrder order_ = VisitOrder::sequential;
  std::mt19937_64 rng_;
  std::size_t position_ = 0;
};

}  // namespace c2f

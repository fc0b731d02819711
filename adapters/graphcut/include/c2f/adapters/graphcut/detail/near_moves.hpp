#pragma once
// Internal to ExpansionSolver: the binary problem of an expansion move restricted to the
// variables near its label (ExpansionOptions::near_radius). Every other variable keeps its label,
// so its edges to free variables become unary terms of those variables, and the restricted
// problem's minimum is the minimum of the whole move's problem over the labelings that keep the
// held variables: an exact move on a smaller graph.

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/bands.hpp"
#include "c2f/adapters/graphcut/detail/shared_incidence.hpp"
#include "c2f/adapters/graphcut/move_options.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/energy.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// Marks a variable that is no node of a restricted problem (restricted_problem's `local`).
inline constexpr std::uint32_t kHeld = 0xffffffffu;

/// Rows [first, last) of the binary problem of the move to alpha from x restricted to `nodes`
/// (ascending): every other variable keeps its label, so its edges to nodes become unary terms
/// of those nodes. local[v] is v's index in `nodes` for a node, kHeld for every other variable.
/// Writes d[k] for first <= k < last (d has a row per node) and appends the pairs whose u is
/// one of these nodes to `pairs` and their p to `p` (in node order, then in edge order): the
/// problem in binary_move.hpp's form, nodes numbered as in `nodes`. Each d[k] is its unary
/// change plus its edges' terms in edge order, so rows computed apart (by bands) have the bits
/// of rows computed together.
inline void restricted_rows(const PairwiseEnergy& energy, const EdgeIncidence& incidence,
                            Label alpha, std::span<const Label> x,
                            std::span<const VariableIndex> nodes,
                            std::span<const std::uint32_t> local, std::size_t first,
                            std::size_t last, std::span<double> d, std::vector<double>& p,
                            std::vector<FlowEdge>& pairs) {
  const auto edges = energy.edges();
  for (std::size_t k = first; k < last; ++k) {
    const VariableIndex v = nodes[k];
    double value = energy.unary(v, alpha) - energy.unary(v, x[v]);
    for (const Incidence& inc : incidence.of(v)) {
      const Edge& edge = edges[inc.edge];
      const VariableIndex other = inc.other;
      if (local[other] == kHeld) {
        value += inc.is_first ? energy.pairwise_cost(edge, alpha, x[other]) -
                                    energy.pairwise_cost(edge, x[v], x[other])
                              : energy.pairwise_cost(edge, x[other], alpha) -
                                    energy.pairwise_cost(edge, x[other], x[v]);
        continue;
      }
      // A pair between nodes: this node's share (add_binary_term), and the pair from u's side.
      const Label xu = x[edge.u];
      const Label xv = x[edge.v];
      const double A = energy.pairwise_cost(edge, xu, xv);
      const double C = energy.pairwise_cost(edge, alpha, xv);
      const double D = energy.pairwise_cost(edge, alpha, alpha);
      if (!inc.is_first) {
        value += D - C;
        continue;
      }
      value += C - A;
      pairs.push_back({static_cast<FlowNode>(k), static_cast<FlowNode>(local[other])});
      p.push_back(energy.pairwise_cost(edge, xu, alpha) + C - A - D);
    }
    d[k] = value;
  }
}

/// Every row of that problem (restricted_rows), on the calling thread.
inline void restricted_problem(const PairwiseEnergy& energy, const EdgeIncidence& incidence,
                               Label alpha, std::span<const Label> x,
                               std::span<const VariableIndex> nodes,
                               std::span<const std::uint32_t> local, std::vector<double>& d,
                               std::vector<double>& p, std::vector<FlowEdge>& pairs) {
  d.resize(nodes.size());
  p.clear();
  pairs.clear();
  restricted_rows(energy, incidence, alpha, x, nodes, local, 0, nodes.size(), d, p, pairs);
}

/// Free variables of the move to alpha from labeling x: every variable not labelled alpha that
/// lies within `radius` edges of a variable labelled alpha or, with NearSeeds::label_and_cheapest,
/// of a variable whose cheapest unary label is alpha (itself included), or with
/// NearSeeds::label_and_adjacent of a variable labelled alpha - 1 or alpha + 1 (bind() takes the
/// seeds as given: near_seeds_in_use says which an expansion solver uses). The problem has
/// binary_move.hpp's form over them, with the free variables numbered in the order of `free()`
/// (ascending).
class NearMoves {
 public:
  /// Precomputes the edge incidences (from `shared` when given) and, with
  /// NearSeeds::label_and_cheapest, each variable's cheapest label (ties: the smallest).
  /// build() writes the problem by bands (detail/bands.hpp) on up to `threads` threads, to the
  /// same bits for every count.
  void bind(const PairwiseEnergy& energy, int radius, NearSeeds seeds,
            SharedIncidence* shared = nullptr, int threads = 1) {
    energy_ = &energy;
    radius_ = radius;
    adjacent_ = seeds == NearSeeds::label_and_adjacent;
    threads_ = threads;
    incidence_ = incidence_of(energy, shared);
    const std::size_t n = energy.num_variables();
    cheapest_.assign(static_cast<std::size_t>(energy.num_labels()), {});
    if (seeds == NearSeeds::label_and_cheapest) {
      for (std::size_t i = 0; i < n; ++i) {
        cheapest_[static_cast<std::size_t>(cheapest_label(energy, i))].push_back(
            static_cast<VariableIndex>(i));
      }
    }
    local_.assign(n, kHeld);
    depth_.assign(n, kUnreached);
  }

  /// Builds the restricted problem of the move to alpha from x.
  void build(Label alpha, std::span<const Label> x) {
    select(alpha, x);
    order_free(alpha, x);
    const std::size_t bands = band_count(free_.size());
    band_p_.resize(bands);
    band_pairs_.resize(bands);
    d_.resize(free_.size());
    for_each_band(
        free_.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t k = first; k < last; ++k)
            local_[free_[k]] = static_cast<std::uint32_t>(k);
        },
        threads_);
    for_each_band(
        free_.size(),
        [&](std::size_t b, std::size_t first, std::size_t last) {
          band_p_[b].clear();
          band_pairs_[b].clear();
          restricted_rows(*energy_, *incidence_, alpha, x, free_, local_, first, last, d_,
                          band_p_[b], band_pairs_[b]);
        },
        threads_);
    p_.clear();
    pairs_.clear();
    for (std::size_t b = 0; b < bands; ++b) {
      p_.insert(p_.end(), band_p_[b].begin(), band_p_[b].end());
      pairs_.insert(pairs_.end(), band_pairs_[b].begin(), band_pairs_[b].end());
    }
  }

  /// Finds the free variables of the move to alpha from x (in no order in free()), without
  /// building the problem: is_free() answers for each variable. Breadth first from the
  /// variables labelled alpha and those whose cheapest label it is (none with NearSeeds::label),
  /// a level at a time, each level's variables by bands on the threads (a variable is claimed by
  /// one of them); which variables are reached, and at what depth, does not depend on the
  /// threads.
  void select(Label alpha, std::span<const Label> x) {
    for_each_band(
        reached_.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t k = first; k < last; ++k) {
            depth_[reached_[k]] = kUnreached;
            local_[reached_[k]] = kHeld;
          }
        },
        threads_);
    reached_.clear();
    gather(x.size(), [&](std::size_t first, std::size_t last, std::vector<VariableIndex>& out) {
      for (std::size_t v = first; v < last; ++v)
        if (is_seed(x[v], alpha)) claim(static_cast<VariableIndex>(v), 0, out);
    });
    const std::vector<VariableIndex>& cheapest = cheapest_[static_cast<std::size_t>(alpha)];
    gather(cheapest.size(),
           [&](std::size_t first, std::size_t last, std::vector<VariableIndex>& out) {
             for (std::size_t k = first; k < last; ++k) claim(cheapest[k], 0, out);
           });
    std::size_t level_begin = 0;  // reached_[level_begin, end): the last level reached
    for (int depth = 1; depth <= radius_; ++depth) {
      const std::size_t level_end = reached_.size();
      gather(
          level_end - level_begin,
          [&](std::size_t first, std::size_t last, std::vector<VariableIndex>& out) {
            for (std::size_t k = level_begin + first; k < level_begin + last; ++k)
              for (const Incidence& inc : incidence_->of(reached_[k])) claim(inc.other, depth, out);
          },
          kLevelBand);
      level_begin = level_end;
    }
    free_.clear();
    for (const VariableIndex v : reached_)
      if (x[v] != alpha) free_.push_back(v);
  }

  /// Puts free() in index order (then the unary table is read nearly sequentially): a sort
  /// when few variables are free, else a scan of every variable by bands (each band's free
  /// variables in order, the bands joined in order).
  void order_free(Label alpha, std::span<const Label> x) {
    if (free_.size() * kSortBelow < x.size()) {
      std::sort(free_.begin(), free_.end());
      return;
    }
    free_.clear();
    append_by_bands(
        x.size(), band_lists_, free_,
        [&](std::size_t first, std::size_t last, std::vector<VariableIndex>& out) {
          for (std::size_t v = first; v < last; ++v)
            if (depth_[v] != kUnreached && x[v] != alpha)
              out.push_back(static_cast<VariableIndex>(v));
        },
        threads_);
  }

  /// Whether the last select() or build() freed v (reached, and not labelled alpha in the x
  /// it was given).
  [[nodiscard]] bool is_free(VariableIndex v, Label alpha, std::span<const Label> x) const {
    return depth_[v] != kUnreached && x[v] != alpha;
  }

  [[nodiscard]] std::span<const VariableIndex> free() const noexcept { return free_; }
  [[nodiscard]] std::span<const FlowEdge> pairs() const noexcept { return pairs_; }
  [[nodiscard]] std::span<const double> d() const noexcept { return d_; }
  [[nodiscard]] std::span<const double> p() const noexcept { return p_; }

 private:
  static constexpr int kUnreached = -1;
  /// Variables of one breadth-first level per band: a level is often a few thousand variables,
  /// which bands of kBandSize would leave to one thread.
  static constexpr std::size_t kLevelBand = 1024;
  /// order_free sorts when fewer than one variable in this many is free.
  static constexpr std::size_t kSortBelow = 16;

  /// Whether a variable labelled `label` seeds the move to alpha: alpha itself and, with
  /// NearSeeds::label_and_adjacent, alpha - 1 and alpha + 1.
  [[nodiscard]] bool is_seed(Label label, Label alpha) const noexcept {
    return label == alpha || (adjacent_ && (label + 1 == alpha || label == alpha + 1));
  }

  /// Marks v reached at `depth` and lists it in `out`, unless it is reached already (an atomic
  /// claim: bands of one level may race for a variable).
  void claim(VariableIndex v, int depth, std::vector<VariableIndex>& out) {
    std::atomic_ref<int> mark(depth_[v]);
    int unreached = kUnreached;
    if (mark.load(std::memory_order_relaxed) == kUnreached &&
        mark.compare_exchange_strong(unreached, depth, std::memory_order_relaxed))
      out.push_back(v);
  }

  /// Runs visit(first, last, out) for the bands of `band` indices of [0, count) on the threads
  /// and appends what they list to reached_ (append_by_bands).
  template <class Visit>
  void gather(std::size_t count, const Visit& visit, std::size_t band = kBandSize) {
    append_by_bands(count, band_lists_, reached_, visit, threads_, band);
  }

  const PairwiseEnergy* energy_ = nullptr;
  int radius_ = 0;
  bool adjacent_ = false;  // NearSeeds::label_and_adjacent
  int threads_ = 1;
  std::shared_ptr<const EdgeIncidence> incidence_;
  // Per label: the variables it is cheapest for (empty with NearSeeds::label).
  std::vector<std::vector<VariableIndex>> cheapest_;
  std::vector<std::uint32_t> local_;  // per variable: index in free_, or kHeld
  std::vector<int> depth_;            // per variable: BFS depth, or kUnreached
  std::vector<VariableIndex> free_, reached_;
  std::vector<double> d_, p_;
  std::vector<FlowEdge> pairs_;
  // Per band of free variables: its pairs and their p, before they are joined in band order.
  std::vector<std::vector<double>> band_p_;
  std::vector<std::vector<VariableIndex>> band_lists_;  // gather's and order_free's, per band
  std::vector<std::vector<FlowEdge>> band_pairs_;
};

}  // namespace c2f::detail

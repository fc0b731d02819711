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

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <span>
#include <stdexcept>
#include <vector>

#include "c2f/adapters/maxflow/maxflow.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

/// The value of one binary variable after a move: 0, 1, or left open by QPBO.
enum class MoveLabel : std::int8_t { zero = 0, one = 1, unlabeled = -1 };

struct BinaryMoveStats {
  bool used_qpbo = false;     ///< some p[e] < 0: solved on the doubled graph
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
  /// Builds the n-node graph now and the 2n-node QPBO graph on first need.
  void bind(std::size_t num_nodes, std::span<const FlowEdge> pairs) {
    check_topology(num_nodes, pairs, "BinaryMoveSolver::bind");
    num_nodes_ = num_nodes;
    pairs_.assign(pairs.begin(), pairs.end());
    plain_.build(num_nodes, pairs_);
    plain_caps_.resize(num_nodes, pairs_.size());
    qpbo_built_ = false;
  }

  /// The topology of the moves of a pairwise energy: one binary variable per variable, one
  /// pair per edge (same order).
  void bind(const PairwiseEnergy& energy) {
    std::vector<FlowEdge> pairs(energy.edges().size());
    for (std::size_t e = 0; e < pairs.size(); ++e)
      pairs[e] = {energy.edges()[e].u, energy.edges()[e].v};
    bind(energy.num_variables(), pairs);
  }

  /// Minimises the problem above. With every p[e] >= 0 one max-flow gives an exact minimiser
  /// and every variable is labelled. Otherwise QPBO (Kolmogorov and Rother 2007) on the doubled
  /// graph gives a partial labelling with weak persistency: the labelled part can be imposed on
  /// any b without increasing the objective, so keeping unlabelled variables at 0 (the current
  /// labels) never does worse than b = 0.
  BinaryMoveStats solve(std::span<const double> d, std::span<const double> p,
                        std::span<MoveLabel> out) {
    if (d.size() != num_nodes_ || out.size() != num_nodes_ || p.size() != pairs_.size()) {
      throw std::invalid_argument("BinaryMoveSolver::solve: sizes do not match the bound topology");
    }
    BinaryMoveStats stats;
    bool submodular = true;
    for (const double value : p) submodular = submodular && value >= 0.0;
    const auto start = std::chrono::steady_clock::now();
    if (submodular) {
      for (std::size_t i = 0; i < num_nodes_; ++i) {
        plain_caps_.source[i] = d[i] > 0.0 ? d[i] : 0.0;
        plain_caps_.sink[i] = d[i] < 0.0 ? -d[i] : 0.0;
      }
      for (std::size_t e = 0; e < pairs_.size(); ++e) {
        plain_caps_.forward[e] = p[e];
        plain_caps_.backward[e] = 0.0;
      }
      plain_.solve(plain_caps_);
      for (std::size_t i = 0; i < num_nodes_; ++i) {
        out[i] = plain_.in_source_set(static_cast<FlowNode>(i)) ? MoveLabel::zero : MoveLabel::one;
      }
    } else {
      stats.used_qpbo = true;
      solve_qpbo(d, p, out);
      for (const MoveLabel label : out) stats.unlabeled += label == MoveLabel::unlabeled;
    }
    stats.flow_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return stats;
  }

 private:
  // Node i stands for b_i and node n + i for its complement (b_i = 0 when n + i is on the sink
  // side). Pair e owns edges 4e..4e+3: (u, v), (v', u'), (u, v'), (v, u'); the first two carry
  // submodular terms, the last two non-submodular ones; backward capacities stay 0.
  void build_qpbo() {
    const auto n = static_cast<FlowNode>(num_nodes_);
    std::vector<FlowEdge> doubled;
    doubled.reserve(4 * pairs_.size());
    for (const FlowEdge& pair : pairs_) {
      doubled.push_back({pair.from, pair.to});
      doubled.push_back({pair.to + n, pair.from + n});
      doubled.push_back({pair.from, pair.to + n});
      doubled.push_back({pair.to, pair.from + n});
    }
    qpbo_.build(2 * num_nodes_, doubled);
    qpbo_caps_.resize(2 * num_nodes_, doubled.size());
    adjusted_d_.resize(num_nodes_);
    qpbo_built_ = true;
  }

  void solve_qpbo(std::span<const double> d, std::span<const double> p, std::span<MoveLabel> out) {
    if (!qpbo_built_) build_qpbo();
    const std::size_t n = num_nodes_;
    adjusted_d_.assign(d.begin(), d.end());
    // p (1 - b_u) b_v with p < 0 equals p (1 - b_u) + |p| (1 - b_u) (1 - b_v): the first part
    // moves |p| onto b_u's coefficient (plus a constant), the second is submodular in (b_u, b'_v).
    for (std::size_t e = 0; e < pairs_.size(); ++e) {
      if (p[e] < 0.0) adjusted_d_[pairs_[e].from] -= p[e];
    }
    for (std::size_t i = 0; i < n; ++i) {
      const double half = 0.5 * adjusted_d_[i];
      qpbo_caps_.source[i] = half > 0.0 ? half : 0.0;
      qpbo_caps_.sink[i] = half < 0.0 ? -half : 0.0;
      qpbo_caps_.source[n + i] = half < 0.0 ? -half : 0.0;
      qpbo_caps_.sink[n + i] = half > 0.0 ? half : 0.0;
    }
    for (std::size_t e = 0; e < pairs_.size(); ++e) {
      const double half = 0.5 * p[e];
      const bool sub = half >= 0.0;
      qpbo_caps_.forward[4 * e + 0] = sub ? half : 0.0;
      qpbo_caps_.forward[4 * e + 1] = sub ? half : 0.0;
      qpbo_caps_.forward[4 * e + 2] = sub ? 0.0 : -half;
      qpbo_caps_.forward[4 * e + 3] = sub ? 0.0 : -half;
    }
    std::fill(qpbo_caps_.backward.begin(), qpbo_caps_.backward.end(), 0.0);
    qpbo_.solve(qpbo_caps_);
    for (std::size_t i = 0; i < n; ++i) {
      const bool node_source = qpbo_.in_source_set(static_cast<FlowNode>(i));
      const bool complement_source = qpbo_.in_source_set(static_cast<FlowNode>(n + i));
      if (node_source == complement_source) {
        out[i] = MoveLabel::unlabeled;
      } else {
        out[i] = node_source ? MoveLabel::zero : MoveLabel::one;
      }
    }
  }

  std::size_t num_nodes_ = 0;
  std::vector<FlowEdge> pairs_;
  Backend plain_;
  FlowCapacities plain_caps_;
  Backend qpbo_;
  FlowCapacities qpbo_caps_;
  std::vector<double> adjusted_d_;
  bool qpbo_built_ = false;
};

}  // namespace c2f

#pragma once
// Internal to ExpansionSolver: the binary problem (d, p) of every label's expansion move, kept
// up to date from a log of the variables that accepted moves changed, so that a move costs in
// proportion to what changed since that label's last move rather than O(N + E).

#include <cstddef>
#include <cstdint>
#include <limits>
#include <memory>
#include <span>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/bands.hpp"
#include "c2f/adapters/graphcut/detail/shared_incidence.hpp"
#include "c2f/core/default_init_allocator.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// The problem of the expansion move to alpha from labeling x (binary_move.hpp's form):
///   d[i] = unary(i, alpha) - unary(i, x_i) + the edges' shares, p[e] = B + C - A - D,
/// with edge e = (u, v) adding C - A to d[u] and D - C to d[v], where A = cost(x_u, x_v),
/// B = cost(x_u, alpha), C = cost(alpha, x_v), D = cost(alpha, alpha).
///
/// A label's problem is computed in full on its first move and afterwards patched: for the
/// variables changed since, their edges' p and their own and their neighbours' d. Either way
/// each d is summed over the variable's incidences, which follow the edge order (the order in
/// which add_binary_term, edge by edge, would add them), so a patched problem is bitwise the
/// problem a full computation gives, and a full one is computed by bands on several threads. Labels
/// keep their problems while num_labels * (N + E) doubles fit in a memory limit; otherwise every
/// move computes in full.
class ExpansionProblems {
 public:
  /// Forgets every problem; keeps one per label when they fit in memory_limit bytes (the edge
  /// incidences from `shared` when given). Problems computed in full are computed by bands
  /// (detail/bands.hpp) on up to `threads` threads, to the same bits for every count.
  void bind(const PairwiseEnergy& energy, std::size_t memory_limit,
            SharedIncidence* shared = nullptr, int threads = 1) {
    energy_ = &energy;
    threads_ = threads;
    const std::size_t per_label = (energy.num_variables() + energy.edges().size()) * sizeof(double);
    const auto labels = static_cast<std::size_t>(energy.num_labels());
    kept_ = per_label > 0 && per_label * labels <= memory_limit;
    problems_.assign(kept_ ? labels : 1, Problem{});
    log_.clear();
    incidence_ = incidence_of(energy, shared);
    if (kept_) {
      node_stamp_.assign(energy.num_variables(), 0);
      edge_stamp_.assign(energy.edges().size(), 0);
      stamp_ = 0;
    }
  }

  /// Bytes the kept problems take (0 when problems are not kept).
  [[nodiscard]] std::size_t memory_bytes() const noexcept {
    if (!kept_ || energy_ == nullptr) return 0;
    return problems_.size() * (energy_->num_variables() + energy_->edges().size()) * sizeof(double);
  }

  /// The problem of the move to alpha from `labeling` (the labeling the logged changes led to).
  /// The spans stay valid until the next call.
  void update(Label alpha, std::span<const Label> labeling, std::span<const double>& d,
              std::span<const double>& p) {
    Problem& problem = problems_[kept_ ? static_cast<std::size_t>(alpha) : 0];
    const std::size_t n = energy_->num_variables();
    const std::size_t pending = log_.size() - problem.mark;
    if (!kept_ || problem.mark == kNever || pending > n / 8) {
      compute_in_full(alpha, labeling, problem);
    } else {
      patch(alpha, labeling, problem);
    }
    problem.mark = log_.size();
    d = problem.d;
    p = problem.p;
  }

  /// Records the variables an accepted move changed.
  void log_changes(std::span<const VariableIndex> changed) {
    if (kept_) log_.insert(log_.end(), changed.begin(), changed.end());
  }

 private:
  static constexpr std::size_t kNever = std::numeric_limits<std::size_t>::max();

  struct Problem {
    // Not zeroed when sized: compute_in_full writes every entry, by bands, so the pages of a
    // label's first problem are first touched on the threads.
    std::vector<double, DefaultInitAllocator<double>> d, p;
    std::size_t mark = kNever;  ///< log size when d and p were last brought up to date
  };

  /// p[e] of the move to alpha from x: B + C - A - D.
  [[nodiscard]] double pair_coefficient(const Edge& edge, Label alpha,
                                        std::span<const Label> x) const noexcept {
    const PairwiseEnergy& energy = *energy_;
    const Label xu = x[edge.u];
    const Label xv = x[edge.v];
    return energy.pairwise_cost(edge, xu, alpha) + energy.pairwise_cost(edge, alpha, xv) -
           energy.pairwise_cost(edge, xu, xv) - energy.pairwise_cost(edge, alpha, alpha);
  }

  /// d[v] of the move to alpha from x: its unary change, then its edges' shares (C - A as an
  /// edge's u, D - C as its v) in edge order, as add_binary_term adds them edge by edge.
  [[nodiscard]] double node_coefficient(VariableIndex v, Label alpha,
                                        std::span<const Label> x) const noexcept {
    const PairwiseEnergy& energy = *energy_;
    const auto edges = energy.edges();
    double value = energy.unary(v, alpha) - energy.unary(v, x[v]);
    for (const Incidence& inc : incidence_->of(v)) {
      const Edge& edge = edges[inc.edge];
      const Label xu = x[edge.u];
      const Label xv = x[edge.v];
      const double C = energy.pairwise_cost(edge, alpha, xv);
      value += inc.is_first ? C - energy.pairwise_cost(edge, xu, xv)
                            : energy.pairwise_cost(edge, alpha, alpha) - C;
    }
    return value;
  }

  /// Every p[e] and d[v], by bands of edges and of variables.
  void compute_in_full(Label alpha, std::span<const Label> x, Problem& problem) const {
    const auto edges = energy_->edges();
    problem.d.resize(energy_->num_variables());
    problem.p.resize(edges.size());
    for_each_band(
        edges.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t e = first; e < last; ++e)
            problem.p[e] = pair_coefficient(edges[e], alpha, x);
        },
        threads_);
    for_each_band(
        problem.d.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t v = first; v < last; ++v)
            problem.d[v] = node_coefficient(static_cast<VariableIndex>(v), alpha, x);
        },
        threads_);
  }

  /// The p of the edges of the variables changed since the problem's mark and the d of those
  /// variables and their neighbours: found in log order, then computed by bands.
  void patch(Label alpha, std::span<const Label> x, Problem& problem) {
    const auto edges = energy_->edges();
    if (++stamp_ == 0) {  // the stamps wrapped: clear them
      std::fill(node_stamp_.begin(), node_stamp_.end(), 0);
      std::fill(edge_stamp_.begin(), edge_stamp_.end(), 0);
      stamp_ = 1;
    }
    affected_.clear();
    affected_edges_.clear();
    auto affect = [&](VariableIndex v) {
      if (node_stamp_[v] == stamp_) return;
      node_stamp_[v] = stamp_;
      affected_.push_back(v);
    };
    for (std::size_t k = problem.mark; k < log_.size(); ++k) {
      const VariableIndex v = log_[k];
      affect(v);
      for (const Incidence& inc : incidence_->of(v)) {
        affect(inc.other);
        if (edge_stamp_[inc.edge] == stamp_) continue;
        edge_stamp_[inc.edge] = stamp_;
        affected_edges_.push_back(inc.edge);
      }
    }
    for_each_band(
        affected_edges_.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t k = first; k < last; ++k) {
            const std::size_t e = affected_edges_[k];
            problem.p[e] = pair_coefficient(edges[e], alpha, x);
          }
        },
        threads_);
    for_each_band(
        affected_.size(),
        [&](std::size_t, std::size_t first, std::size_t last) {
          for (std::size_t k = first; k < last; ++k)
            problem.d[affected_[k]] = node_coefficient(affected_[k], alpha, x);
        },
        threads_);
  }

  const PairwiseEnergy* energy_ = nullptr;
  int threads_ = 1;
  bool kept_ = false;
  std::vector<Problem> problems_;   // per label when kept, else one scratch problem
  std::vector<VariableIndex> log_;  // variables changed by accepted moves, in order
  std::shared_ptr<const EdgeIncidence> incidence_;
  std::vector<std::uint32_t> node_stamp_, edge_stamp_;
  std::uint32_t stamp_ = 0;
  std::vector<VariableIndex> affected_;  // patch's variables and edges
  std::vector<std::uint32_t> affected_edges_;
};

}  // namespace c2f::detail

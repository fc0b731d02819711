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
#include "c2f/adapters/graphcut/detail/shared_incidence.hpp"
#include "c2f/core/edge_incidence.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f::detail {

/// The problem of the expansion move to alpha from labeling x (binary_move.hpp's form):
///   d[i] = unary(i, alpha) - unary(i, x_i) + the edges' shares, p[e] = B + C - A - D,
/// with edge e = (u, v) adding C - A to d[u] and D - C to d[v], where A = cost(x_u, x_v),
/// B = cost(x_u, alpha), C = cost(alpha, x_v), D = cost(alpha, alpha).
///
/// A label's problem is computed in full on its first move (edge by edge, in edge order) and
/// afterwards patched: for the variables changed since, their edges' p and their own and their
/// neighbours' d, each d summed afresh over the variable's incidences, which follow the edge
/// order, so a patched problem is bitwise the problem a full computation gives. Labels keep
/// their problems while num_labels * (N + E) doubles fit in a memory limit; otherwise every move
/// computes in full.
class ExpansionProblems {
 public:
  /// Forgets every problem; keeps one per label when they fit in memory_limit bytes (the edge
  /// incidences from `shared` when given).
  void bind(const PairwiseEnergy& energy, std::size_t memory_limit,
            SharedIncidence* shared = nullptr) {
    energy_ = &energy;
    const std::size_t per_label = (energy.num_variables() + energy.edges().size()) * sizeof(double);
    const auto labels = static_cast<std::size_t>(energy.num_labels());
    kept_ = per_label > 0 && per_label * labels <= memory_limit;
    problems_.assign(kept_ ? labels : 1, Problem{});
    log_.clear();
    if (kept_) {
      incidence_ = incidence_of(energy, shared);
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
    std::vector<double> d, p;
    std::size_t mark = kNever;  ///< log size when d and p were last brought up to date
  };

  void compute_in_full(Label alpha, std::span<const Label> x, Problem& problem) const {
    const PairwiseEnergy& energy = *energy_;
    problem.d.resize(energy.num_variables());
    problem.p.assign(energy.edges().size(), 0.0);
    for (std::size_t i = 0; i < problem.d.size(); ++i)
      problem.d[i] = energy.unary(i, alpha) - energy.unary(i, x[i]);
    const auto edges = energy.edges();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Edge& edge = edges[e];
      const Label xu = x[edge.u];
      const Label xv = x[edge.v];
      add_binary_term(problem.d, problem.p, e, edge.u, edge.v, energy.pairwise_cost(edge, xu, xv),
                      energy.pairwise_cost(edge, xu, alpha), energy.pairwise_cost(edge, alpha, xv),
                      energy.pairwise_cost(edge, alpha, alpha));
    }
  }

  void patch(Label alpha, std::span<const Label> x, Problem& problem) {
    const PairwiseEnergy& energy = *energy_;
    const auto edges = energy.edges();
    if (++stamp_ == 0) {  // the stamps wrapped: clear them
      std::fill(node_stamp_.begin(), node_stamp_.end(), 0);
      std::fill(edge_stamp_.begin(), edge_stamp_.end(), 0);
      stamp_ = 1;
    }
    affected_.clear();
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
        const Edge& edge = edges[inc.edge];
        const Label xu = x[edge.u];
        const Label xv = x[edge.v];
        problem.p[inc.edge] =
            energy.pairwise_cost(edge, xu, alpha) + energy.pairwise_cost(edge, alpha, xv) -
            energy.pairwise_cost(edge, xu, xv) - energy.pairwise_cost(edge, alpha, alpha);
      }
    }
    for (const VariableIndex v : affected_) {
      double value = energy.unary(v, alpha) - energy.unary(v, x[v]);
      for (const Incidence& inc : incidence_->of(v)) {
        const Edge& edge = edges[inc.edge];
        const Label xu = x[edge.u];
        const Label xv = x[edge.v];
        const double C = energy.pairwise_cost(edge, alpha, xv);
        value += inc.is_first ? C - energy.pairwise_cost(edge, xu, xv)
                              : energy.pairwise_cost(edge, alpha, alpha) - C;
      }
      problem.d[v] = value;
    }
  }

  const PairwiseEnergy* energy_ = nullptr;
  bool kept_ = false;
  std::vector<Problem> problems_;   // per label when kept, else one scratch problem
  std::vector<VariableIndex> log_;  // variables changed by accepted moves, in order
  std::shared_ptr<const EdgeIncidence> incidence_;
  std::vector<std::uint32_t> node_stamp_, edge_stamp_;
  std::uint32_t stamp_ = 0;
  std::vector<VariableIndex> affected_;
};

}  // namespace c2f::detail

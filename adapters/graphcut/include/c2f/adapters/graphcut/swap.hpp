#pragma once
// Alpha-beta swap (Boykov, Veksler and Zabih) as an AnytimeSolver for PairwiseEnergy.
//
// One step() = one swap move for one label pair (alpha, beta): every variable labelled alpha
// or beta may take either of the two. Pairs (a < b) are cycled in the configured order
// (VisitOrder::frequency: pairs whose labels the start labeling uses most first). Swap
// moves are submodular, so one max-flow solves each exactly, when every pairwise term is a
// semi-metric (cost(a, a) = 0, cost(a, b) = cost(b, a) >= 0) and every weight is >= 0;
// bind() rejects other energies with a message naming the term or edge.

#include <cstddef>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

#include "c2f/adapters/graphcut/binary_move.hpp"
#include "c2f/adapters/graphcut/detail/move_state.hpp"
#include "c2f/adapters/graphcut/move_cycle.hpp"
#include "c2f/adapters/graphcut/move_options.hpp"
#include "c2f/adapters/maxflow/dynamic_maxflow.hpp"
#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

/// Throws std::invalid_argument unless every term used by an edge is a semi-metric and every
/// edge weight is >= 0 (what swap moves need to be submodular).
void require_semi_metric(const PairwiseEnergy& energy, const char* who);

template <MaxFlow Backend = DynamicMaxFlow>
class SwapSolver {
 public:
  /// Throws std::invalid_argument when options.validate() reports a problem.
  explicit SwapSolver(SwapOptions options = {}) : options_(options) {
    if (const std::string problem = options_.validate(); !problem.empty()) {
      throw std::invalid_argument("SwapOptions: " + problem);
    }
  }

  /// One sweep (one move per label pair): that many steps without a decrease on `energy` mean
  /// no single swap move lowers it.
  [[nodiscard]] std::size_t quiet_steps_to_converge(const PairwiseEnergy& energy) const noexcept {
    const auto l = static_cast<std::size_t>(energy.num_labels());
    return l > 1 ? l * (l - 1) / 2 : 1;
  }

  void bind(const PairwiseEnergy& energy, std::span<const Label> start) {
    require_semi_metric(energy, "SwapSolver::bind");
    const auto num_labels = static_cast<std::size_t>(energy.num_labels());
    state_.bind(energy, start, "SwapSolver::bind: start", num_labels * num_labels,
                options_.graph_memory_limit, options_.first_move_own_graph);
    std::vector<std::pair<Label, Label>> label_pairs;
    for (Label a = 0; a < energy.num_labels(); ++a) {
      for (Label b = a + 1; b < energy.num_labels(); ++b) label_pairs.emplace_back(a, b);
    }
    if (options_.order == VisitOrder::frequency) {
      const std::vector<std::size_t> count = label_counts(state_.labeling, energy.num_labels());
      sort_most_used_first(label_pairs, [&](const std::pair<Label, Label>& pair) {
        return count[static_cast<std::size_t>(pair.first)] +
               count[static_cast<std::size_t>(pair.second)];
      });
    }
    if (label_pairs.empty()) label_pairs.emplace_back(0, 0);  // one label: every move is empty
    cycle_ =
        MoveCycle<std::pair<Label, Label>>(std::move(label_pairs), options_.order, options_.seed);
    last_ = {};
  }

  /// One swap move; returns the energy afterwards (never larger than before).
  double step() {
    if (state_.energy == nullptr) throw std::logic_error("SwapSolver::step: call bind() first");
    const PairwiseEnergy& energy = *state_.energy;
    const Labeling& labeling = state_.labeling;
    LargeVector<double>& d = state_.d;
    LargeVector<double>& p = state_.p;
    const auto [alpha, beta] = cycle_.next();
    auto in_move = [&](Label l) { return l == alpha || l == beta; };
    for (std::size_t i = 0; i < d.size(); ++i) {
      d[i] = in_move(labeling[i]) ? energy.unary(i, beta) - energy.unary(i, alpha) : 0.0;
    }
    std::fill(p.begin(), p.end(), 0.0);
    const auto edges = energy.edges();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Edge& edge = edges[e];
      const Label xu = labeling[edge.u];
      const Label xv = labeling[edge.v];
      const bool u_in = in_move(xu);
      const bool v_in = in_move(xv);
      if (u_in && v_in) {
        add_binary_term(d, p, e, edge.u, edge.v, energy.pairwise_cost(edge, alpha, alpha),
                        energy.pairwise_cost(edge, alpha, beta),
                        energy.pairwise_cost(edge, beta, alpha),
                        energy.pairwise_cost(edge, beta, beta));
      } else if (u_in) {
        d[edge.u] += energy.pairwise_cost(edge, beta, xv) - energy.pairwise_cost(edge, alpha, xv);
      } else if (v_in) {
        d[edge.v] += energy.pairwise_cost(edge, xu, beta) - energy.pairwise_cost(edge, xu, alpha);
      }
    }
    const auto pair_key =
        static_cast<std::size_t>(alpha) * static_cast<std::size_t>(state_.energy->num_labels()) +
        static_cast<std::size_t>(beta);
    last_ = state_.solve_move(alpha, beta, pair_key);
    std::size_t changed = 0;
    for (std::size_t i = 0; i < labeling.size(); ++i) {
      state_.candidate[i] = labeling[i];
      if (in_move(labeling[i]))
        state_.candidate[i] = state_.out[i] == MoveLabel::one ? beta : alpha;
      changed += state_.candidate[i] != labeling[i];
    }
    // Strict: a move that keeps the energy equal is not taken (no equal-energy churn).
    return state_.finish_move(last_, changed, options_.tolerance);
  }

  [[nodiscard]] double energy() const noexcept { return state_.value; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return state_.labeling; }
  /// What the last step() did (all zero before the first step of a binding).
  [[nodiscard]] const MoveStep& last_step() const noexcept { return last_; }
  /// The optional memory in use (within options.graph_memory_limit): the recycled move graphs.
  [[nodiscard]] std::size_t kept_bytes() const noexcept { return state_.moves.recycled_bytes(); }

 private:
  SwapOptions options_;
  detail::MoveState<Backend> state_;
  MoveCycle<std::pair<Label, Label>> cycle_;
  MoveStep last_;
};

static_assert(AnytimeSolver<SwapSolver<>, PairwiseEnergy>);

}  // namespace c2f

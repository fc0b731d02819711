#pragma once
// Alpha-beta swap (Boykov, Veksler and Zabih) as an AnytimeSolver for PairwiseEnergy.
//
// One step() = one swap move for one label pair (alpha, beta): every variable labelled alpha
// or beta may take either of the two. Pairs (a < b) are cycled in the configured order
// (LabelOrder::frequency: pairs whose labels the start labeling uses most first). Swap
// moves are submodular, so one max-flow solves each exactly, when every pairwise term is a
// semi-metric (cost(a, a) = 0, cost(a, b) = cost(b, a) >= 0) and every weight is >= 0;
// bind() rejects other energies with a message naming the term or edge.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "c2f/adapters/binary_move.hpp"
#include "c2f/adapters/boost_maxflow.hpp"
#include "c2f/adapters/move_order.hpp"
#include "c2f/core/anytime_solver.hpp"
#include "c2f/core/pairwise_energy.hpp"

namespace c2f {

struct SwapOptions {
  LabelOrder order = LabelOrder::sequential;
  std::uint64_t seed = 1;  ///< for LabelOrder::random
};

/// Throws std::invalid_argument unless every term used by an edge is a semi-metric and every
/// edge weight is >= 0 (what swap moves need to be submodular).
void require_semi_metric(const PairwiseEnergy& energy, const char* who);

template <MaxFlow Backend = BoostMaxFlow>
class SwapSolver {
 public:
  explicit SwapSolver(SwapOptions options = {}) : options_(options) {}

  void bind(const PairwiseEnergy& energy, std::span<const Label> start) {
    validate_labeling(start, energy.num_variables(), energy.num_labels(),
                      "SwapSolver::bind: start");
    require_semi_metric(energy, "SwapSolver::bind");
    energy_ = &energy;
    labeling_.assign(start.begin(), start.end());
    candidate_.resize(labeling_.size());
    moves_.bind(energy);
    d_.resize(energy.num_variables());
    p_.resize(energy.edges().size());
    out_.resize(energy.num_variables());
    std::vector<std::pair<Label, Label>> label_pairs;
    for (Label a = 0; a < energy.num_labels(); ++a) {
      for (Label b = a + 1; b < energy.num_labels(); ++b) label_pairs.emplace_back(a, b);
    }
    if (options_.order == LabelOrder::frequency) {
      const std::vector<std::size_t> count = label_counts(labeling_, energy.num_labels());
      std::stable_sort(label_pairs.begin(), label_pairs.end(), [&](const auto& x, const auto& y) {
        return count[static_cast<std::size_t>(x.first)] +
                   count[static_cast<std::size_t>(x.second)] >
               count[static_cast<std::size_t>(y.first)] + count[static_cast<std::size_t>(y.second)];
      });
    }
    if (label_pairs.empty()) label_pairs.emplace_back(0, 0);  // one label: every move is empty
    cycle_ =
        MoveCycle<std::pair<Label, Label>>(std::move(label_pairs), options_.order, options_.seed);
    energy_value_ = energy.evaluate_unchecked(labeling_);
  }

  /// One swap move; returns the energy afterwards (never larger than before).
  double step() {
    if (energy_ == nullptr) throw std::logic_error("SwapSolver::step: call bind() first");
    const PairwiseEnergy& energy = *energy_;
    const auto [alpha, beta] = cycle_.next();
    last_pair_ = {alpha, beta};
    auto in_move = [&](Label l) { return l == alpha || l == beta; };
    for (std::size_t i = 0; i < d_.size(); ++i) {
      d_[i] = in_move(labeling_[i]) ? energy.unary(i, beta) - energy.unary(i, alpha) : 0.0;
    }
    std::fill(p_.begin(), p_.end(), 0.0);
    const auto edges = energy.edges();
    for (std::size_t e = 0; e < edges.size(); ++e) {
      const Edge& edge = edges[e];
      const Label xu = labeling_[edge.u];
      const Label xv = labeling_[edge.v];
      const bool u_in = in_move(xu);
      const bool v_in = in_move(xv);
      if (u_in && v_in) {
        add_binary_term(d_, p_, e, edge.u, edge.v, energy.pairwise_cost(edge, alpha, alpha),
                        energy.pairwise_cost(edge, alpha, beta),
                        energy.pairwise_cost(edge, beta, alpha),
                        energy.pairwise_cost(edge, beta, beta));
      } else if (u_in) {
        d_[edge.u] += energy.pairwise_cost(edge, beta, xv) - energy.pairwise_cost(edge, alpha, xv);
      } else if (v_in) {
        d_[edge.v] += energy.pairwise_cost(edge, xu, beta) - energy.pairwise_cost(edge, xu, alpha);
      }
    }
    moves_.solve(d_, p_, out_);
    changed_ = 0;
    for (std::size_t i = 0; i < labeling_.size(); ++i) {
      candidate_[i] = labeling_[i];
      if (in_move(labeling_[i])) candidate_[i] = out_[i] == MoveLabel::one ? beta : alpha;
      changed_ += candidate_[i] != labeling_[i];
    }
    if (changed_ == 0) return energy_value_;
    const double candidate_energy = energy.evaluate_unchecked(candidate_);
    if (candidate_energy < energy_value_) {  // strict: no equal-energy churn
      labeling_.swap(candidate_);
      energy_value_ = candidate_energy;
    } else {
      changed_ = 0;
    }
    return energy_value_;
  }

  [[nodiscard]] double energy() const noexcept { return energy_value_; }
  [[nodiscard]] std::span<const Label> labeling() const noexcept { return labeling_; }
  /// The pair of the last step and how many variables it changed.
  [[nodiscard]] std::pair<Label, Label> last_pair() const noexcept { return last_pair_; }
  [[nodiscard]] std::size_t changed_in_last_step() const noexcept { return changed_; }

 private:
  SwapOptions options_;
  const PairwiseEnergy* energy_ = nullptr;
  Labeling labeling_, candidate_;
  double energy_value_ = 0.0;
  BinaryMoveSolver<Backend> moves_;
  std::vector<double> d_, p_;
  std::vector<MoveLabel> out_;
  MoveCycle<std::pair<Label, Label>> cycle_;
  std::pair<Label, Label> last_pair_{0, 0};
  std::size_t changed_ = 0;
};

static_assert(AnytimeSolver<SwapSolver<>, PairwiseEnergy>);

}  // namespace c2f

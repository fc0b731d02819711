#pragma once
// PairwiseEnergy: unary costs plus weighted pairwise terms on undirected edges.
//
//   E(x) = sum_v unary(v, x_v) + sum_{edges (u, v, w, t)} w * terms[t].cost(x_u, x_v)
//
// Layout is flat: unaries are one row-major array of num_variables * num_labels costs, edges
// one array. The unaries are stored in double or, to halve the largest array, in float; the
// energy is what the stored costs define. evaluate() and reduce() convert every stored cost to
// double exactly and sum in double, so a float energy equals the double energy of the same
// (float-rounded) costs. Reduced energies are always double: the reduced energy of a partition
// sums the unaries of whole groups, and reduction must stay exact (Theorem 1) to rounding of
// double sums so that transfers between levels keep the energy.

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "c2f/core/default_init_allocator.hpp"
#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_term.hpp"
#include "c2f/core/unary_costs.hpp"

namespace c2f {

/// An undirected edge: cost weight * terms[term].cost(x_u, x_v). For an asymmetric table term
/// the orientation (u first) matters.
struct Edge {
  VariableIndex u = 0;
  VariableIndex v = 0;
  double weight = 0.0;
  std::uint32_t term = 0;

  friend bool operator==(const Edge&, const Edge&) = default;
};

class PairwiseEnergy {
 public:
  /// Validates everything and throws std::invalid_argument naming the offending field:
  /// num_labels >= 1; unaries has num_variables * num_labels finite entries; every term fits
  /// num_labels; every edge has endpoints < num_variables, u != v, a finite weight and a term
  /// index < terms.size(). num_variables must fit VariableIndex.
  PairwiseEnergy(std::size_t num_variables, int num_labels, std::vector<double> unaries,
                 std::vector<PairwiseTerm> terms, std::vector<Edge> edges);
  /// As the constructor, with the unaries stored in float (single_precision()): half the
  /// memory of the largest array; the energy is what the float costs define. The unaries are
  /// taken as FloatValues (a std::vector<float> whose allocation writes nothing, so that a
  /// producer can write a large array in parallel); a braced list converts, and a
  /// std::vector<float> v is passed as {v.begin(), v.end()}.
  [[nodiscard]] static PairwiseEnergy with_float_unaries(std::size_t num_variables, int num_labels,
                                                         FloatValues unaries,
                                                         std::vector<PairwiseTerm> terms,
                                                         std::vector<Edge> edges);

  [[nodiscard]] std::size_t num_variables() const noexcept { return num_variables_; }
  [[nodiscard]] int num_labels() const noexcept { return num_labels_; }

  [[nodiscard]] double unary(std::size_t v, Label l) const noexcept {
    const std::size_t i = v * static_cast<std::size_t>(num_labels_) + static_cast<std::size_t>(l);
    return single_precision_ ? static_cast<double>(float_unaries_[i]) : unaries_[i];
  }
  /// The unary costs as stored (row(v): the num_labels costs of variable v).
  [[nodiscard]] UnaryCosts unaries() const noexcept {
    if (single_precision_) return {std::span<const float>(float_unaries_), num_labels_};
    return {std::span<const double>(unaries_), num_labels_};
  }
  /// True when the unaries are stored in float.
  [[nodiscard]] bool single_precision() const noexcept { return single_precision_; }
  [[nodiscard]] std::span<const PairwiseTerm> terms() const noexcept { return terms_; }
  [[nodiscard]] std::span<const Edge> edges() const noexcept { return edges_; }

  /// The cost of edge e when its endpoints take labels a (at e.u) and b (at e.v).
  [[nodiscard]] double pairwise_cost(const Edge& e, Label a, Label b) const noexcept {
    return e.weight * terms_[e.term].cost(a, b);
  }

  /// E(x) in double. Throws std::invalid_argument when x is not a labeling of this energy.
  [[nodiscard]] double evaluate(std::span<const Label> labeling) const;
  /// E(x) without validating x (x must be a valid labeling). O(N + E). Sums the unaries, then
  /// the edges, in chunks of kEvaluationChunk (unary_sum and pairwise_sum of each chunk in
  /// order, those sums added in order from zero), so that EnergyTally can evaluate a labeling
  /// that differs in a few variables chunk by chunk to the same bits.
  [[nodiscard]] double evaluate_unchecked(std::span<const Label> labeling) const noexcept;
  /// evaluate_unchecked with its chunks summed on up to `threads` threads (0: the machine's
  /// cores), then added in the same order: the same bits for every count.
  [[nodiscard]] double evaluate_unchecked(std::span<const Label> labeling, int threads) const;

  /// The variables and the edges evaluate_unchecked sums apart, chunk by chunk.
  static constexpr std::size_t kEvaluationChunk = 4096;
  /// The sum from zero of unary(v, x_v) over first <= v < last, in order.
  [[nodiscard]] double unary_sum(std::span<const Label> x, std::size_t first,
                                 std::size_t last) const noexcept;
  /// The sum from zero of the costs of edges[first..last) under x, in order.
  [[nodiscard]] double pairwise_sum(std::span<const Label> x, std::size_t first,
                                    std::size_t last) const noexcept;

 private:
  std::size_t num_variables_;
  int num_labels_;
  std::vector<double> unaries_;  ///< empty when single_precision_
  FloatValues float_unaries_;    ///< empty unless single_precision_
  bool single_precision_ = false;
  std::vector<PairwiseTerm> terms_;
  std::vector<Edge> edges_;

  struct FloatUnaries {};
  PairwiseEnergy(FloatUnaries, std::size_t num_variables, int num_labels, FloatValues unaries,
                 std::vector<PairwiseTerm> terms, std::vector<Edge> edges);
  void validate() const;
};

}  // namespace c2f

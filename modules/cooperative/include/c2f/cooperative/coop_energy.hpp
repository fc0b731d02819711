#pragma once
// The cooperative-cut energy of multi-label segmentation (Kohli, Osokin and Jegelka, CVPR
// 2013), exact, and closed under reduction by a partition.
//
//   E(x) = sum_i phi_i(x_i) + lambda [ sum_{l, g < K} F_g(S_lg(x)) + linear(x) ]
//   S_lg(x) = sum over cut edges (x_u != x_v) of w/2 for each entry (g, w) on the side whose
//             label is l (an edge's u side holds the classes of c(u) - c(v), its v side those
//             of c(v) - c(u): each side its own colour minus the other's)
//   F_g(s)  = min(s, alpha s + (1 - alpha) theta T_g), T_g = the ground energy's total weight
//             of class g over both sides of every edge (full weights)
//   linear  = sum over cut edges of w/2 for each entry of class K (near-zero differences)
//
// An edge of a reduced energy joins two groups and keeps, per side, the summed weight of each
// class of the ground edges it merges; edges inside a group can never be cut and are dropped.

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "c2f/core/labeling.hpp"
#include "c2f/core/pairwise_energy.hpp"
#include "c2f/lift/dense_partition.hpp"
#include "c2f/lift/lifting_view.hpp"

namespace c2f {

/// The defaults are the model chosen by cross-validation over the labelled coopCuts images for
/// majorise-minimise on superpixel levels with the default data preparation (c2f-segment's
/// default method; docs/history/results-2026-11.md, "Parameters chosen on other images");
/// coopcuts_example_parameters() are the released example's.
struct CoopParameters {
  double lambda = 0.5;    ///< weight of the pairwise part
  double theta = 0.0007;  ///< breakpoint of F_g as a fraction of the class's total weight T_g
  double alpha = 0.2;     ///< slope of F_g after the breakpoint, in [0, 1)

  /// Empty when usable, else a message naming the field.
  [[nodiscard]] std::string validate() const;
  bool operator==(const CoopParameters&) const = default;
};

/// The coopCuts example's parameters (exampleMultilabel.m: lambda 1.5, theta 0.005, alpha 0).
constexpr CoopParameters coopcuts_example_parameters() {
  return {1.5, 0.005, 0.0};
}

/// One class entry of one side of an edge.
struct ClassWeight {
  std::uint32_t edge_class = 0;  ///< 0..K-1, or K for the linear (near-zero difference) class
  double weight = 0.0;           ///< full weight (the energy takes half of it per side)
};

/// An edge (u, v): entries [first, middle) are u's side, [middle, last) v's side.
struct CoopEdge {
  VariableIndex u = 0;
  VariableIndex v = 0;
  std::uint32_t first = 0, middle = 0, last = 0;
};

class CoopEnergy {
 public:
  /// Validates everything and throws std::invalid_argument naming the field: finite unaries
  /// (num_variables * num_labels), num_labels >= 1, num_classes >= 1, class_totals with
  /// num_classes finite entries >= 0, edges with endpoints < num_variables and u != v whose
  /// entry ranges lie in `entries`, entries with class <= num_classes and finite weights >= 0.
  CoopEnergy(std::size_t num_variables, int num_labels, std::vector<double> unaries,
             int num_classes, std::vector<double> class_totals, CoopParameters parameters,
             std::vector<CoopEdge> edges, std::vector<ClassWeight> entries);

  [[nodiscard]] std::size_t num_variables() const noexcept { return num_variables_; }
  [[nodiscard]] int num_labels() const noexcept { return num_labels_; }
  /// K: classes 0..K-1 are cooperative, class K is linear.
  [[nodiscard]] int num_classes() const noexcept { return num_classes_; }
  [[nodiscard]] const CoopParameters& parameters() const noexcept { return parameters_; }
  [[nodiscard]] double unary(std::size_t v, Label l) const noexcept {
    return unaries_[v * static_cast<std::size_t>(num_labels_) + static_cast<std::size_t>(l)];
  }
  [[nodiscard]] std::span<const double> unaries() const noexcept { return unaries_; }
  [[nodiscard]] std::span<const CoopEdge> edges() const noexcept { return edges_; }
  [[nodiscard]] std::span<const ClassWeight> u_side(const CoopEdge& e) const noexcept {
    return {entries_.data() + e.first, e.middle - e.first};
  }
  [[nodiscard]] std::span<const ClassWeight> v_side(const CoopEdge& e) const noexcept {
    return {entries_.data() + e.middle, e.last - e.middle};
  }
  [[nodiscard]] std::span<const ClassWeight> entries() const noexcept { return entries_; }
  /// T_g for g < K.
  [[nodiscard]] std::span<const double> class_totals() const noexcept { return class_totals_; }
  /// theta * T_g: where F_g bends.
  [[nodiscard]] double breakpoint(int edge_class) const noexcept {
    return parameters_.theta * class_totals_[static_cast<std::size_t>(edge_class)];
  }
  /// F_g(s).
  [[nodiscard]] double concave_cost(int edge_class, double s) const noexcept;

  /// E(x). Throws std::invalid_argument when x is not a labeling of this energy.
  [[nodiscard]] double evaluate(std::span<const Label> labeling) const;
  /// E(x) for a valid labeling. O(N + E + L K).
  [[nodiscard]] double evaluate_unchecked(std::span<const Label> labeling) const;
  /// S_lg(x) for l < L, g < K, row-major (l * K + g), and in `linear` the linear part.
  [[nodiscard]] std::vector<double> cut_sizes(std::span<const Label> labeling,
                                              double* linear = nullptr) const;

 private:
  std::size_t num_variables_;
  int num_labels_;
  std::vector<double> unaries_;
  int num_classes_;
  std::vector<double> class_totals_;
  CoopParameters parameters_;
  std::vector<CoopEdge> edges_;
  std::vector<ClassWeight> entries_;
};

/// The bytes the arrays of `energy` take (as energy_memory_bytes of a PairwiseEnergy, in
/// c2f/core/memory_budget.hpp).
[[nodiscard]] std::size_t energy_memory_bytes(const CoopEnergy& energy);

/// The reduced energy over the groups of `partition`: group unaries are sums, edges inside a
/// group are dropped, edges between two groups are merged per group pair (smaller group id as
/// u) with the weights of equal classes summed per side; the class totals T_g and parameters
/// are kept. reduce(e, p).evaluate(y) == e.evaluate(expand(y, p)) up to rounding. Throws
/// std::invalid_argument when the partition does not cover the energy's variables.
CoopEnergy reduce(const CoopEnergy& energy, const GroupIds& groups);

/// reduce(energy, GroupIds(partition)) for any Partition type.
template <Partition P>
CoopEnergy reduce(const CoopEnergy& energy, const P& partition) {
  return reduce(energy, GroupIds(partition));
}

/// What colour passing reads of a cooperative-cut energy: its unaries, and one factor per edge
/// coloured by its (u-side classes, v-side classes), ordered (weights are not part of the
/// colour). The energy must outlive the view.
LiftingView lifting_view(const CoopEnergy& energy);

/// The auxiliary variables of the cooperative cut: h(l, g) = 1 takes S_lg linearly (slope 1),
/// h(l, g) = 0 takes the flat branch alpha S_lg + (1 - alpha) theta T_g. F_g(s) is the minimum
/// of the two, so E(x) = min_h E_h(x) with E_h pairwise in x.
class CoopAuxiliary {
 public:
  CoopAuxiliary() = default;
  /// All h(l, g) = 1 (the plain Potts-like energy).
  CoopAuxiliary(int num_labels, int num_classes);
  /// The h minimising E_h(x) for a labeling: h(l, g) = [S_lg(x) <= theta T_g].
  static CoopAuxiliary optimal_for(const CoopEnergy& energy, std::span<const Label> labeling);
  /// The same from (relaxed) cut sizes S_lg, row-major l * K + g.
  static CoopAuxiliary optimal_for(const CoopEnergy& energy, std::span<const double> cut_sizes);

  [[nodiscard]] int num_labels() const noexcept { return num_labels_; }
  [[nodiscard]] int num_classes() const noexcept { return num_classes_; }
  [[nodiscard]] bool linear(int label, int edge_class) const noexcept {
    return on_[static_cast<std::size_t>(label * num_classes_ + edge_class)] != 0;
  }
  void set(int label, int edge_class, bool linear) noexcept {
    on_[static_cast<std::size_t>(label * num_classes_ + edge_class)] = linear ? 1 : 0;
  }
  /// How many entries differ from `other` (same shape).
  [[nodiscard]] std::size_t differences(const CoopAuxiliary& other) const noexcept;
  friend bool operator==(const CoopAuxiliary&, const CoopAuxiliary&) = default;

 private:
  int num_labels_ = 0;
  int num_classes_ = 0;
  std::vector<std::uint8_t> on_;
};

/// E_h as a pairwise energy, without its constant (aux_constant): per cut edge
///   lambda/2 (sum over u-side entries (g, w) of w a(x_u, g) + the same for v's side with x_v)
/// with a(l, g) = 1 for g = K or h(l, g) = 1, else alpha. Edges whose sides have the same
/// class composition share a table term. E_h(x) + aux_constant >= E(x), with equality for
/// the h of CoopAuxiliary::optimal_for(x). Throws std::invalid_argument for an h of another
/// shape.
PairwiseEnergy pairwise_energy(const CoopEnergy& energy, const CoopAuxiliary& h);
/// lambda * sum over h(l, g) = 0 of (1 - alpha) theta T_g.
double aux_constant(const CoopEnergy& energy, const CoopAuxiliary& h);

/// The plain pairwise energy of the same data (the cooperative-cuts papers' alpha-expansion
/// baseline): the same unaries and, per edge, a Potts term of weight lambda * w (w the edge's
/// total weight). Equal to E_h for h all 1.
PairwiseEnergy potts_energy(const CoopEnergy& energy);

}  // namespace c2f

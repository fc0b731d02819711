#pragma once
// Pairwise terms: an L x L cost shared by many edges, scaled by each edge's weight.

#include <cstdlib>
#include <string_view>
#include <vector>

#include "c2f/core/labeling.hpp"

namespace c2f {

/// The shape of a pairwise term.
enum class TermKind {
  potts,             ///< cost(a, b) = [a != b]
  truncated_linear,  ///< cost(a, b) = min(|a - b|, truncation)
  tsgo_step,         ///< cost(a, b) = 0, 1/6, 1 for |a - b| = 0, 1, >= 2 (TSGO step 2)
  table,             ///< cost(a, b) = table[a * L + b], any finite L x L table
};

std::string_view to_string(TermKind kind);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
TermKind term_kind_from_string(std::string_view text);

/// A pairwise cost function of two labels. Copyable value type; cost() is the hot path.
class PairwiseTerm {
 public:
  static PairwiseTerm potts();
  /// Throws std::invalid_argument unless truncation is finite and > 0.
  static PairwiseTerm truncated_linear(double truncation);
  static PairwiseTerm tsgo_step();
  /// costs is row-major: costs[a * num_labels + b] = cost(a, b). Throws std::invalid_argument
  /// unless it has num_labels^2 finite entries and num_labels >= 1.
  static PairwiseTerm table(int num_labels, std::vector<double> costs);

  [[nodiscard]] TermKind kind() const noexcept { return kind_; }
  /// The truncation of a truncated-linear term (0 for other kinds).
  [[nodiscard]] double truncation() const noexcept { return truncation_; }
  /// Number of labels of a table term (0 for parametric kinds, which fit any label count).
  [[nodiscard]] int table_labels() const noexcept { return table_labels_; }
  [[nodiscard]] const std::vector<double>& table_costs() const noexcept { return table_; }

  /// cost(a, b) for labels valid for this term (unchecked).
  [[nodiscard]] double cost(Label a, Label b) const noexcept {
    switch (kind_) {
      case TermKind::potts:
        return a == b ? 0.0 : 1.0;
      case TermKind::truncated_linear: {
        const double d = std::abs(a - b);
        return d < truncation_ ? d : truncation_;
      }
      case TermKind::tsgo_step: {
        const int d = std::abs(a - b);
        return d == 0 ? 0.0 : (d == 1 ? 1.0 / 6.0 : 1.0);
      }
      case TermKind::table:
        return table_[static_cast<std::size_t>(a) * static_cast<std::size_t>(table_labels_) +
                      static_cast<std::size_t>(b)];
    }
    return 0.0;
  }

  /// True when cost(a, b) == cost(b, a) for all labels.
  [[nodiscard]] bool is_symmetric() const noexcept;

  /// Whether the term can be used with num_labels labels: a table term must have exactly
  /// num_labels labels.
  [[nodiscard]] bool fits(int num_labels) const noexcept {
    return kind_ != TermKind::table || table_labels_ == num_labels;
  }
  /// Throws std::invalid_argument (naming `what`) unless the term fits num_labels labels.
  void validate_for(int num_labels, std::string_view what) const;

  friend bool operator==(const PairwiseTerm&, const PairwiseTerm&) = default;

 private:
  PairwiseTerm(TermKind kind, double truncation, int table_labels, std::vector<double> table)
      : kind_(kind),
        truncation_(truncation),
        table_labels_(table_labels),
        table_(std::move(table)) {}

  TermKind kind_;
  double truncation_;
  int table_labels_;
  std::vector<double> table_;
};

}  // namespace c2f

#include "c2f/core/pairwise_term.hpp"
#include "c2f/support/enum_names.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace c2f {

std::string_view to_string(TermKind kind) {
  switch (kind) {
    case TermKind::potts:
      return "potts";
    case TermKind::truncated_linear:
      return "truncated_linear";
    case TermKind::tsgo_step:
      return "tsgo_step";
    case TermKind::table:
      return "table";
  }
  return "unknown";
}

TermKind term_kind_from_string(std::string_view text) {
  constexpr TermKind kAll[] = {TermKind::potts, TermKind::truncated_linear, TermKind::tsgo_step,
                               TermKind::table};
  return enum_from_string(text, kAll, "pairwise term kind");
}

PairwiseTerm PairwiseTerm::potts() {
  return {TermKind::potts, 0.0, 0, {}};
}

PairwiseTerm PairwiseTerm::truncated_linear(double truncation) {
  if (!std::isfinite(truncation) || truncation <= 0.0) {
    throw std::invalid_argument("truncated_linear: truncation must be finite and > 0, got " +
                                std::to_string(truncation));
  }
  return {TermKind::truncated_linear, truncation, 0, {}};
}

PairwiseTerm PairwiseTerm::tsgo_step() {
  return {TermKind::tsgo_step, 0.0, 0, {}};
}

PairwiseTerm PairwiseTerm::table(int num_labels, std::vector<double> costs) {
  if (num_labels < 1) {
    throw std::invalid_argument("table term: num_labels must be >= 1, got " +
                                std::to_string(num_labels));
  }
  const auto expected = static_cast<std::size_t>(num_labels) * static_cast<std::size_t>(num_labels);
  if (costs.size() != expected) {
    throw std::invalid_argument("table term: costs has " + std::to_string(costs.size()) +
                                " entries, expected num_labels^2 = " + std::to_string(expected));
  }
  for (std::size_t i = 0; i < costs.size(); ++i) {
    if (!std::isfinite(costs[i])) {
      throw std::invalid_argument("table term: cost(" + std::to_string(i / num_labels) + ", " +
                                  std::to_string(i % num_labels) + ") is not finite");
    }
  }
  return {TermKind::table, 0.0, num_labels, std::move(costs)};
}

bool PairwiseTerm::is_symmetric() const noexcept {
  if (kind_ != TermKind::table) return true;
  for (Label a = 0; a < table_labels_; ++a) {
    for (Label b = a + 1; b < table_labels_; ++b) {
      if (cost(a, b) != cost(b, a)) return false;
    }
  }
  return true;
}

void PairwiseTerm::validate_for(int num_labels, std::string_view what) const {
  if (!fits(num_labels)) {
    throw std::invalid_argument(std::string(what) + ": table term has " +
                                std::to_string(table_labels_) + " labels, the energy has " +
                                std::to_string(num_labels));
  }
}

}  // namespace c2f

#pragma once
// The order in which a solver visits its moves: labels (expansion), label pairs (swap) or
// variables (ICM). One vocabulary for every solver's options and every command line.

#include <string_view>

namespace c2f {

enum class VisitOrder {
  sequential,  ///< 0, 1, 2, ... and again (the reference implementation's order)
  random,      ///< a fresh random permutation for every cycle, drawn from the options' seed
  frequency,   ///< label moves only: labels the start labeling uses most first (ties: lower label)
};

std::string_view to_string(VisitOrder order);
/// Parses the names to_string produces; throws std::invalid_argument naming the text.
VisitOrder visit_order_from_string(std::string_view text);

}  // namespace c2f

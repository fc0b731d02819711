#pragma once
// Parsing enums by the names their to_string gives, so command-line flags, schedules and
// trace files share one vocabulary.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>

#include "c2f/support/text_input.hpp"

namespace c2f {

/// The enumerator e of `all` with to_string(e) == text (to_string is found by argument-
/// dependent lookup). Otherwise throws std::invalid_argument
/// "unknown <what> '<text>' (expected a, b or c)", the text shown by printable().
template <class Enum, std::size_t N>
Enum enum_from_string(std::string_view text, const Enum (&all)[N], std::string_view what) {
  std::string expected;
  for (std::size_t i = 0; i < N; ++i) {
    if (to_string(all[i]) == text) return all[i];
    if (i > 0) expected += i + 1 == N ? " or " : ", ";
    expected += to_string(all[i]);
  }
  throw std::invalid_argument("unknown " + std::string(what) + " '" + printable(text) +
                              "' (expected " + expected + ")");
}

}  // namespace c2f

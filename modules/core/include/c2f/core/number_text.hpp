#pragma once
// Numbers as text. Strict parsing of numbers from text (command lines, schedules, model files): the
// whole text must be the number, with no leading or trailing characters, and a real must be finite.
// The functions return std::nullopt instead of throwing, so each caller's message names its own
// input ("--blocks: ...", "schedule: level ...", "model.uai: token 12: ...").

#include <optional>
#include <string>
#include <string_view>

namespace c2f {

/// A finite decimal real ("0.5", "-3", "1e-4", an optional leading '+'); nullopt otherwise.
std::optional<double> parse_real(std::string_view text);

/// A decimal integer ("42", "-7", an optional leading '+') that fits in long long; nullopt
/// otherwise (also for "1.0" or "1e3").
std::optional<long long> parse_integer(std::string_view text);

/// The shortest usual text of a real ("%g": 0.5, 3, 1e-05), as schedules and reports print it.
std::string format_real(double value);

}  // namespace c2f

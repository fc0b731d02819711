#pragma once
// Numbers as text. Strict parsing of numbers from text (command lines, schedules, model files): the
// whole text must be the number, with no leading or trailing characters, and a real must be finite.
// The functions return std::nullopt instead of throwing, so each caller's message names its own
// input ("--blocks: ...", "schedule: level ...", "model.uai: token 12: ...").
// Numbers are written in the "C" locale whatever the process's: a program that embeds the
// library (Python after locale.setlocale) gets decimal points, never commas, in model files,
// traces, reports and messages.

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

/// std::snprintf's text for `format` and its arguments in the "C" locale, whatever locale the
/// process or thread has set. Every number the library writes goes through here.
std::string c_format(const char* format, ...) __attribute__((format(printf, 1, 2)));

}  // namespace c2f

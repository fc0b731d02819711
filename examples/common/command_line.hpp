#pragma once
// What the command-line tools share when they read their arguments (Boost.Program_options).

#include <boost/program_options.hpp>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace c2f::examples {

/// Throws std::invalid_argument "<flag>: file '<path>' does not exist" unless `path` is empty
/// or names a regular file.
void require_file(const std::string& path, const char* flag);

/// Parses argv against `visible` (which must have a "help" switch) plus any number of
/// positional arguments, stores the values and returns the positional arguments; returns
/// std::nullopt after printing `visible` for --help. Boost's errors become
/// std::invalid_argument.
std::optional<std::vector<std::string>> parse_command_line(
    int argc, char** argv, const boost::program_options::options_description& visible);

/// parse(), with "<flag>: " put before the message of an std::invalid_argument it throws.
template <class Parse>
auto with_flag(const char* flag, Parse parse) {
  try {
    return parse();
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(std::string(flag) + ": " + error.what());
  }
}

}  // namespace c2f::examples

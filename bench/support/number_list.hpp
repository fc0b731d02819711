#pragma once
// Comma-separated lists of numbers on the benchmarks' command lines (parameter grids).

#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "tool_options.hpp"

namespace c2f::bench {

/// A comma-separated list of numbers in `range`, each checked as the option's value. Throws
/// std::invalid_argument naming `option` for an empty list, an empty item or a bad number.
inline std::vector<double> number_list(const std::string& option, const std::string& text,
                                       examples::RealRange range) {
  std::vector<double> values;
  std::stringstream stream(text);
  for (std::string item; std::getline(stream, item, ',');)
    values.push_back(examples::parse_real_option(option, item, range));
  if (values.empty() || text.back() == ',')
    throw std::invalid_argument(option + ": expected a comma-separated list, got '" + text + "'");
  return values;
}

}  // namespace c2f::bench

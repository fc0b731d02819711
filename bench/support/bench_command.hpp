#pragma once
// The two commands of the per-scene benchmark tools: `run NAMES...` (one scene or image, one
// row per configuration) and `summarize ROWS.tsv` (the table over the collected rows).

#include <stdexcept>
#include <string>
#include <vector>

namespace c2f::bench {

struct BenchCommand {
  bool summarize = false;
  std::string rows;                ///< summarize: the rows file
  std::vector<std::string> names;  ///< run: its arguments after `run`
};

/// Reads the positional arguments: "summarize ROWS.tsv", or "run" followed by exactly as many
/// names as `run_usage` lists ("SCENE", "SET NAME"). Throws std::invalid_argument otherwise.
inline BenchCommand bench_command(const std::vector<std::string>& arguments,
                                  const std::string& run_usage) {
  std::size_t names = 1;
  for (const char c : run_usage) names += c == ' ';
  if (arguments.size() == 2 && arguments[0] == "summarize") return {true, arguments[1], {}};
  if (arguments.size() != names + 1 || arguments[0] != "run") {
    throw std::invalid_argument("expected 'run " + run_usage +
                                "' or 'summarize ROWS.tsv' (see --help)");
  }
  return {false, {}, {arguments.begin() + 1, arguments.end()}};
}

}  // namespace c2f::bench

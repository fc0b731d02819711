#pragma once
// Runs a command-line tool for the CLI tests: its exit code and everything it printed.

#include <string>

namespace c2f::test {

struct ToolResult {
  int exit_code;       ///< -1 when the tool did not exit normally
  std::string output;  ///< stdout and stderr together
  long peak_kib = 0;   ///< run_tool_measured: the tool's peak resident size (ru_maxrss), KiB
};

/// Runs `binary arguments` through the shell. Throws std::runtime_error when it cannot start.
ToolResult run_tool(const std::string& binary, const std::string& arguments);

/// run_tool, also measuring the tool's peak resident size (the shell execs it, so the
/// process measured is the tool's).
ToolResult run_tool_measured(const std::string& binary, const std::string& arguments);

/// Runs `binary arguments` (through the shell, which execs it), sends it `signal` after
/// `seconds`, and waits for it. Throws std::runtime_error when it cannot start.
ToolResult run_tool_interrupted(const std::string& binary, const std::string& arguments,
                                double seconds, int signal);

}  // namespace c2f::test

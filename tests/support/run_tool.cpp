#include "support/run_tool.hpp"

#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include <array>
#include <cstdio>
#include <stdexcept>

namespace c2f::test {

ToolResult run_tool(const std::string& binary, const std::string& arguments) {
  const std::string command = binary + " " + arguments + " 2>&1";
  FILE* pipe = popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("cannot run '" + command + "'");
  std::string output;
  std::array<char, 512> buffer{};
  while (fgets(buffer.data(), buffer.size(), pipe)) output += buffer.data();
  const int status = pclose(pipe);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output};
}

namespace {

/// `binary arguments` started through the shell, which execs it, with stdout and stderr in
/// `log`. Throws std::runtime_error when it cannot fork.
pid_t start_logged(const std::string& binary, const std::string& arguments,
                   const std::filesystem::path& log) {
  const std::string command = "exec " + binary + " " + arguments + " > " + log.string() + " 2>&1";
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("cannot fork for '" + command + "'");
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  return child;
}

/// Waits for `child` and returns its result (with its peak resident size), `log` read and removed.
ToolResult finish_logged(pid_t child, const std::filesystem::path& log) {
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  std::ifstream in(log);
  std::stringstream output;
  output << in.rdbuf();
  std::filesystem::remove(log);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output.str(), usage.ru_maxrss};
}

std::filesystem::path log_path(const std::string& tag) {
  return std::filesystem::temp_directory_path() /
         ("c2f-" + tag + "-" + std::to_string(getpid()) + ".log");
}

}  // namespace

ToolResult run_tool_measured(const std::string& binary, const std::string& arguments) {
  const auto log = log_path("measured");
  return finish_logged(start_logged(binary, arguments, log), log);
}

ToolResult run_tool_interrupted(const std::string& binary, const std::string& arguments,
                                double seconds, int signal) {
  const auto log = log_path("interrupted");
  const pid_t child = start_logged(binary, arguments, log);
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  kill(child, signal);
  ToolResult result = finish_logged(child, log);
  result.peak_kib = 0;  // the contract measures peaks only for run_tool_measured
  return result;
}

}  // namespace c2f::test

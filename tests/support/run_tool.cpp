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

ToolResult run_tool_measured(const std::string& binary, const std::string& arguments) {
  const auto log = std::filesystem::temp_directory_path() /
                   ("c2f-measured-" + std::to_string(getpid()) + ".log");
  const std::string command = "exec " + binary + " " + arguments + " > " + log.string() + " 2>&1";
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("cannot fork for '" + command + "'");
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  wait4(child, &status, 0, &usage);
  std::ifstream in(log);
  std::stringstream output;
  output << in.rdbuf();
  std::filesystem::remove(log);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output.str(), usage.ru_maxrss};
}

ToolResult run_tool_interrupted(const std::string& binary, const std::string& arguments,
                                double seconds, int signal) {
  const auto log = std::filesystem::temp_directory_path() /
                   ("c2f-interrupted-" + std::to_string(getpid()) + ".log");
  const std::string command = "exec " + binary + " " + arguments + " > " + log.string() + " 2>&1";
  const pid_t child = fork();
  if (child < 0) throw std::runtime_error("cannot fork for '" + command + "'");
  if (child == 0) {
    execl("/bin/sh", "sh", "-c", command.c_str(), static_cast<char*>(nullptr));
    _exit(127);
  }
  std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
  kill(child, signal);
  int status = 0;
  waitpid(child, &status, 0);
  std::ifstream in(log);
  std::stringstream output;
  output << in.rdbuf();
  std::filesystem::remove(log);
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, output.str()};
}

}  // namespace c2f::test

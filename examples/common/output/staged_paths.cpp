#include "staged_paths.hpp"

#include <algorithm>
#include <mutex>
#include <utility>
#include <vector>

namespace c2f::examples {

namespace {

std::mutex& registry_mutex() {
  static std::mutex mutex;
  return mutex;
}

std::vector<std::pair<std::string, std::string>>& registry() {
  static std::vector<std::pair<std::string, std::string>> entries;
  return entries;
}

}  // namespace

void note_staged_path(const std::string& staging, const std::string& target) {
  if (staging.empty() || staging == target) return;
  const std::lock_guard lock(registry_mutex());
  registry().emplace_back(staging, target);
}

std::string with_target_paths(std::string message) {
  const std::lock_guard lock(registry_mutex());
  // Longest staging paths first, so that a folder's entry does not cut a file's.
  auto entries = registry();
  std::sort(entries.begin(), entries.end(),
            [](const auto& a, const auto& b) { return a.first.size() > b.first.size(); });
  for (const auto& [staging, target] : entries) {
    for (std::size_t at = message.find(staging); at != std::string::npos;
         at = message.find(staging, at + target.size())) {
      message.replace(at, staging.size(), target);
    }
  }
  return message;
}

}  // namespace c2f::examples

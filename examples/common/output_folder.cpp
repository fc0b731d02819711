#include "output_folder.hpp"

#include "c2f/core/number_text.hpp"

#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <optional>

#include <fstream>
#include <stdexcept>
#include <system_error>

namespace c2f::examples {

bool name_matches(const std::string& pattern, const std::string& name) {
  if (!pattern.empty() && pattern.back() == '*') {
    const std::string prefix = pattern.substr(0, pattern.size() - 1);
    return name.compare(0, prefix.size(), prefix) == 0;
  }
  const std::size_t star = pattern.find('*');
  if (star == std::string::npos) return pattern == name;
  const std::string prefix = pattern.substr(0, star);
  const std::string suffix = pattern.substr(star + 1);
  return name.size() >= prefix.size() + suffix.size() &&
         name.compare(0, prefix.size(), prefix) == 0 &&
         name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0;
}

OutputFolder::OutputFolder(const std::filesystem::path& folder, std::vector<std::string> owned)
    : folder_(folder), owned_(std::move(owned)) {
  std::error_code error;
  created_ = !std::filesystem::exists(folder_, error);
  std::filesystem::create_directories(folder_, error);
  if (error || !std::filesystem::is_directory(folder_)) {
    throw std::runtime_error("cannot create the output folder '" + folder_.string() +
                             "': " + (error ? error.message() : "not a folder"));
  }
  // Staging folders of runs that were killed (their process is gone) are left-overs.
  const std::string prefix = ".c2f-staging-";
  for (const auto& entry : std::filesystem::directory_iterator(folder_, error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(prefix, 0) != 0) continue;
    const std::optional<long long> pid = parse_integer(name.substr(prefix.size()));
    if (pid && *pid > 0 && kill(static_cast<pid_t>(*pid), 0) == -1 && errno == ESRCH) {
      std::error_code ignored;
      std::filesystem::remove_all(entry.path(), ignored);
    }
  }
  staging_ = folder_ / (prefix + std::to_string(getpid()));
  std::filesystem::remove_all(staging_, error);
  std::filesystem::create_directory(staging_, error);
  if (error) {
    throw std::runtime_error("cannot create a staging folder in '" + folder_.string() +
                             "': " + error.message());
  }
}

OutputFolder::~OutputFolder() {
  std::error_code ignored;
  std::filesystem::remove_all(staging_, ignored);
  if (!committed_) {
    for (const auto& [partial, target] : elsewhere_) std::filesystem::remove(partial, ignored);
    // A folder this run created and did not fill goes again (remove() leaves a non-empty one).
    if (created_) std::filesystem::remove(folder_, ignored);
  }
}

std::filesystem::path OutputFolder::stage(const std::filesystem::path& target) {
  std::error_code error;
  const auto parent = target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
  if (std::filesystem::equivalent(parent, folder_, error)) return staging_ / target.filename();
  // A device or pipe (/dev/stdout, /dev/full) is written directly: it cannot be replaced.
  const auto status = std::filesystem::status(target, error);
  if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) return target;
  std::filesystem::path partial = target;
  partial += ".c2f-partial";
  elsewhere_.emplace_back(partial, target);
  return partial;
}

bool OutputFolder::owns(const std::string& name) const {
  for (const std::string& pattern : owned_)
    if (name_matches(pattern, name)) return true;
  return false;
}

std::vector<std::string> OutputFolder::commit() {
  if (committed_) throw std::logic_error("OutputFolder::commit: already committed");
  std::vector<std::string> written;
  for (const auto& entry : std::filesystem::directory_iterator(staging_)) {
    if (entry.is_regular_file()) written.push_back(entry.path().filename().string());
  }
  for (const std::string& name : written) {
    std::error_code error;
    std::filesystem::rename(staging_ / name, folder_ / name, error);
    if (error) {
      throw std::runtime_error("cannot move '" + name + "' into '" + folder_.string() +
                               "': " + error.message());
    }
  }
  for (const auto& [partial, target] : elsewhere_) {
    std::error_code error;
    std::filesystem::rename(partial, target, error);
    if (error) {
      throw std::runtime_error("cannot move '" + partial.string() + "' to '" + target.string() +
                               "': " + error.message());
    }
  }
  for (const auto& entry : std::filesystem::directory_iterator(folder_)) {
    if (!entry.is_regular_file()) continue;
    const std::string name = entry.path().filename().string();
    if (!owns(name)) continue;
    bool fresh = false;
    for (const std::string& w : written) fresh = fresh || w == name;
    std::error_code ignored;
    if (!fresh) std::filesystem::remove(entry.path(), ignored);
  }
  committed_ = true;
  return written;
}

}  // namespace c2f::examples

#include "output_folder.hpp"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>

#include <stdexcept>
#include <system_error>

#include "c2f/core/number_text.hpp"
#include "folder_swap.hpp"
#include "staged_paths.hpp"

namespace c2f::examples {

namespace fs = std::filesystem;

namespace {

/// Sibling folders of `folder` that runs on it use: ".NAME.c2f-staging-PID-N" while a run
/// writes, ".NAME.c2f-retired-PID-N" for the old version during a fallback commit (N counts the
/// OutputFolders of one process).
std::string sibling_prefix(const fs::path& folder, const std::string& kind) {
  return "." + folder.filename().string() + ".c2f-" + kind + "-";
}

fs::path sibling(const fs::path& folder, const std::string& kind, int number) {
  return folder.parent_path() /
         (sibling_prefix(folder, kind) + std::to_string(::getpid()) + "-" + std::to_string(number));
}

std::atomic<int> folders_opened{0};

/// Whether the process that named sibling `name` ("PREFIX" PID "-" N) has ended.
bool process_gone(const std::string& name, const std::string& prefix) {
  const std::size_t dash = name.find('-', prefix.size());
  const std::optional<long long> pid = parse_integer(
      name.substr(prefix.size(), dash == std::string::npos ? dash : dash - prefix.size()));
  return pid && *pid > 0 && ::kill(static_cast<pid_t>(*pid), 0) == -1 && errno == ESRCH;
}

/// Staging folders that runs of earlier versions created inside the output folder.
bool legacy_staging(const std::string& name) {
  return name.rfind(".c2f-staging-", 0) == 0;
}

/// Whether `inner` is `outer` or lies inside it (both absolute and normal).
bool within(const fs::path& inner, const fs::path& outer) {
  const fs::path relative = inner.lexically_relative(outer);
  return !relative.empty() && *relative.begin() != "..";
}

[[noreturn]] void refuse(const fs::path& folder, const std::string& why) {
  throw std::runtime_error("the output folder '" + folder.string() + "' " + why);
}

}  // namespace

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

OutputFolder::OutputFolder(const fs::path& folder, const std::string& tool,
                           std::vector<std::string> owned, Sharing sharing)
    : tool_(tool), owned_(std::move(owned)), sharing_(sharing) {
  std::error_code error;
  folder_ = fs::weakly_canonical(fs::absolute(folder), error);
  if (error) folder_ = fs::absolute(folder).lexically_normal();
  if (folder_.filename().empty()) folder_ = folder_.parent_path();  // "out/" names "out"
  if (folder_ == folder_.root_path()) refuse(folder, "is the root folder: give a folder in it");
  const fs::path current = fs::weakly_canonical(fs::current_path(error), error);
  if (!error && within(current, folder_)) {
    refuse(folder,
           "is the current folder or holds it: a run replaces its output folder as a "
           "whole; give a folder inside it");
  }
  const int number = folders_opened++;
  staging_ = sibling(folder_, "staging", number);
  retired_ = sibling(folder_, "retired", number);
  // A run killed between the two renames of a fallback commit left no folder, only the old one
  // aside: it is put back before anything else (not one a live run has aside for a moment).
  const std::string retired_prefix = sibling_prefix(folder_, "retired");
  for (const auto& entry : fs::directory_iterator(folder_.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(retired_prefix, 0) == 0 && process_gone(name, retired_prefix))
      restore_retired_folder(entry.path(), folder_);
  }
  claim_.emplace(folder_, tool, sharing_ == Sharing::by_files);
  created_ = claim_->created();
  marked_ = claim_->marked();
  struct stat inner {};
  struct stat outer {};
  if (::stat(folder_.c_str(), &inner) == 0 && ::stat(folder_.parent_path().c_str(), &outer) == 0 &&
      inner.st_dev != outer.st_dev) {
    refuse(folder,
           "is a mount point: a run replaces its output folder as a whole; give a "
           "folder inside it");
  }
  remove_stale_siblings();
  check_carriable(folder_, [this](const std::string& name) { return keeps(name); });
  fs::create_directory(staging_, error);
  if (error) {
    refuse(folder, "cannot have its new version staged beside it ('" + staging_.string() +
                       "'): " + error.message());
  }
  note_staged_path(staging_.string(), folder_.string());
  if (sharing_ == Sharing::by_files) claim_.reset();  // taken again to commit
}

OutputFolder::~OutputFolder() {
  std::error_code ignored;
  fs::remove_all(staging_, ignored);
  if (committed_ || sharing_ == Sharing::by_files) return;
  // A folder this run created, or a marker it added to an empty folder, goes again.
  if (marked_) fs::remove(folder_ / FolderClaim::kMarker, ignored);
  if (created_) fs::remove(folder_, ignored);  // remove() leaves a non-empty folder
}

void OutputFolder::remove_stale_siblings() const {
  // Staging and retired folders of this folder whose process is gone are from runs that were
  // killed (runs sharing the folder stage at the same time, each in its own).
  std::error_code error;
  std::vector<fs::path> stale;
  for (const char* kind : {"staging", "retired"}) {
    const std::string prefix = sibling_prefix(folder_, kind);
    for (const auto& entry : fs::directory_iterator(folder_.parent_path(), error)) {
      const std::string name = entry.path().filename().string();
      if (name.rfind(prefix, 0) == 0 && process_gone(name, prefix)) stale.push_back(entry.path());
    }
  }
  for (const auto& entry : fs::directory_iterator(folder_, error)) {
    if (legacy_staging(entry.path().filename().string())) stale.push_back(entry.path());
  }
  for (const fs::path& path : stale) fs::remove_all(path, error);
}

fs::path OutputFolder::stage(const fs::path& target) {
  // Whatever stands at a path in the output folder now (a file, a folder) is replaced.
  std::error_code error;
  fs::path resolved = fs::weakly_canonical(fs::absolute(target), error);
  if (error) resolved = fs::absolute(target).lexically_normal();
  if (resolved.parent_path() == folder_) return staging_ / resolved.filename();
  if (within(resolved, folder_)) {
    throw std::invalid_argument("'" + target.string() +
                                "' lies in a folder inside the output folder '" + folder_.string() +
                                "': name a file directly in it, or outside it");
  }
  elsewhere_.emplace_back(target);
  return elsewhere_.back().path();
}

bool OutputFolder::owns(const std::string& name) const {
  for (const std::string& pattern : owned_)
    if (name_matches(pattern, name)) return true;
  return false;
}

bool OutputFolder::keeps(const std::string& name) const {
  return !owns(name) && !legacy_staging(name);
}

std::vector<std::string> OutputFolder::commit() {
  if (committed_) throw std::logic_error("OutputFolder::commit: already committed");
  if (!claim_) claim_.emplace(folder_, tool_, true);  // a shared folder: wait for its lock
  std::vector<std::string> written;
  for (const auto& entry : fs::directory_iterator(staging_)) {
    written.push_back(entry.path().filename().string());
  }
  carry_over(folder_, staging_, [this](const std::string& name) { return keeps(name); });
  swap_in(staging_, folder_, retired_);
  committed_ = true;  // from here on the new version is in place
  std::error_code ignored;
  fs::remove_all(staging_, ignored);  // the old version
  for (StagedFile& file : elsewhere_) file.commit();
  if (sharing_ == Sharing::by_files) claim_.reset();  // the next run sharing the folder may commit
  return written;
}

}  // namespace c2f::examples

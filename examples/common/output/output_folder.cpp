#include "output_folder.hpp"

#include <fcntl.h>
#include <limits.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <stdexcept>
#include <system_error>

#include "c2f/support/number_text.hpp"
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

/// Whether `folder` holds, as FolderClaim::kMarker, a hard link of the marker `marker` (an
/// lstat of it): a run's staging folder, or a folder's old version.
bool holds_marker(const fs::path& folder, const struct stat& marker) {
  struct stat held {};
  return ::lstat((folder / FolderClaim::kMarker).c_str(), &held) == 0 && S_ISREG(held.st_mode) &&
         held.st_dev == marker.st_dev && held.st_ino == marker.st_ino;
}

/// The siblings of `folder` named as runs' staging or retired folders that hold a link of its
/// marker, with whether their process is gone.
std::vector<std::pair<fs::path, bool>> run_siblings(const fs::path& folder) {
  std::vector<std::pair<fs::path, bool>> found;
  struct stat marker {};
  if (::lstat((folder / FolderClaim::kMarker).c_str(), &marker) != 0) return found;
  std::error_code error;
  for (const auto& entry : fs::directory_iterator(folder.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    for (const char* kind : {"staging", "retired"}) {
      const std::string prefix = sibling_prefix(folder, kind);
      if (name.rfind(prefix, 0) == 0 && holds_marker(entry.path(), marker))
        found.emplace_back(entry.path(), process_gone(name, prefix));
    }
  }
  return found;
}

/// Removes `path` and everything in it, making folders writable where a permission stops it.
void remove_tree(const fs::path& path) {
  std::error_code error;
  fs::remove_all(path, error);
  if (!error || !fs::exists(fs::symlink_status(path, error))) return;
  for (auto entry = fs::recursive_directory_iterator(path, error);
       entry != fs::recursive_directory_iterator(); entry.increment(error)) {
    if (entry->is_directory(error) && !entry->is_symlink(error))
      fs::permissions(entry->path(), fs::perms::owner_all, fs::perm_options::add, error);
  }
  fs::permissions(path, fs::perms::owner_all, fs::perm_options::add, error);
  fs::remove_all(path, error);
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
                           std::vector<std::string> owned, Sharing sharing,
                           std::chrono::milliseconds wait_limit)
    : tool_(tool), owned_(std::move(owned)), sharing_(sharing), wait_limit_(wait_limit) {
  std::error_code error;
  folder_ = fs::weakly_canonical(fs::absolute(folder), error);
  if (error) folder_ = fs::absolute(folder).lexically_normal();
  if (folder_.filename().empty()) folder_ = folder_.parent_path();  // "out/" names "out"
  if (folder_ == folder_.root_path()) refuse(folder, "is the root folder: give a folder in it");
  // Room for the staging folder's name beside it, and the names inside.
  if (folder_.string().size() + 2 * NAME_MAX > PATH_MAX) {
    refuse(folder, "is " + std::to_string(folder_.string().size()) +
                       " bytes long as an absolute path ('" + folder_.string().substr(0, 60) +
                       "...'), too long for this system's " + std::to_string(PATH_MAX) +
                       "-byte paths with room for the run's files: give a shorter path, or run "
                       "from a shallower folder");
  }
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
  // aside (holding a c2f marker): it is put back before anything else (not one a live run has
  // aside for a moment).
  const std::string retired_prefix = sibling_prefix(folder_, "retired");
  for (const auto& entry : fs::directory_iterator(folder_.parent_path(), error)) {
    const std::string name = entry.path().filename().string();
    if (name.rfind(retired_prefix, 0) == 0 && process_gone(name, retired_prefix) &&
        fs::is_regular_file(fs::symlink_status(entry.path() / FolderClaim::kMarker, error)))
      restore_retired_folder(entry.path(), folder_);
  }
  take_claim(sharing_ == Sharing::by_files);
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
  if (::access(folder_.c_str(), W_OK | X_OK) != 0) {
    refuse(folder, "cannot be written (" + std::string(std::strerror(errno)) +
                       "): a run replaces its output folder as a whole; give a folder it may "
                       "write");
  }
  remove_stale_siblings();
  const std::optional<FileRecord>& record = claim_->record();
  check_carriable(folder_, [&](const std::string& name) { return keeps(name, record); });
  std::vector<std::string> fixed_names;
  for (const std::string& pattern : owned_)
    if (pattern.find('*') == std::string::npos) fixed_names.push_back(pattern);
  refuse_taken_names(fixed_names, record);
  fs::create_directory(staging_, error);
  if (!error)
    fs::create_hard_link(folder_ / FolderClaim::kMarker, staging_ / FolderClaim::kMarker, error);
  if (error) {
    remove_tree(staging_);
    refuse(folder, "cannot have its new version staged beside it ('" + staging_.string() +
                       "'): " + error.message());
  }
  note_staged_path(staging_.string(), folder_.string());
  if (sharing_ == Sharing::by_files) claim_.reset();  // taken again to commit
}

void OutputFolder::take_claim(bool wait) {
  claim_.emplace(folder_, tool_,
                 wait ? std::optional<std::chrono::milliseconds>(wait_limit_) : std::nullopt,
                 [this] { return static_cast<nlink_t>(run_siblings(folder_).size()); });
}

OutputFolder::~OutputFolder() {
  remove_tree(staging_);
  if (committed_ || sharing_ == Sharing::by_files) return;
  // A folder this run created, or a marker it added to an empty folder, goes again.
  std::error_code ignored;
  if (marked_) fs::remove(folder_ / FolderClaim::kMarker, ignored);
  if (created_) fs::remove(folder_, ignored);  // remove() leaves a non-empty folder
}

void OutputFolder::remove_stale_siblings() const {
  // Staging and retired folders of this folder whose process is gone are from runs that were
  // killed (runs sharing the folder stage at the same time, each in its own). They are known by
  // the marker's link they hold, never by their name alone.
  for (const auto& [path, gone] : run_siblings(folder_))
    if (gone) remove_tree(path);
}

void OutputFolder::refuse_taken_names(const std::vector<std::string>& names,
                                      const std::optional<FileRecord>& record) const {
  std::error_code error;
  for (const std::string& name : names) {
    if (fs::exists(fs::symlink_status(folder_ / name, error)) && !recorded(folder_, name, record)) {
      refuse(folder_, "holds '" + name + "', which this run writes and which no earlier run of " +
                          tool_ + " wrote (" + FolderClaim::kMarker +
                          " records what they wrote): it is left as it is; move it, or give "
                          "another folder");
    }
  }
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

bool OutputFolder::recorded(const fs::path& folder, const std::string& name,
                            const std::optional<FileRecord>& record) const {
  if (!record) return owns(name);  // a marker from before markers held a record
  const auto found = record->find(name);
  struct stat entry {};
  return found != record->end() && ::lstat((folder / name).c_str(), &entry) == 0 &&
         S_ISREG(entry.st_mode) && found->second.count(entry.st_ino) > 0;
}

void OutputFolder::remove_old_version(const std::optional<FileRecord>& old_record) const {
  // Entries made in the old version (now at staging_) while this run carried it over, or while
  // it is being removed, are moved into the new one; the rest (the marker, what this run
  // replaced, what the new version holds already) are removed one by one. Only an empty folder
  // can be removed, so a file another process makes in it after a pass is found by the next.
  std::error_code error;
  for (int pass = 0; pass < kRemovalPasses; ++pass) {
    for (const auto& entry : fs::directory_iterator(staging_, error)) {
      const std::string name = entry.path().filename().string();
      const bool replaced = owns(name) && recorded(staging_, name, old_record);
      if (name != FolderClaim::kMarker && !replaced &&
          !fs::exists(fs::symlink_status(folder_ / name, error))) {
        fs::rename(entry.path(), folder_ / name, error);
        if (!error) continue;
      }
      if (entry.is_directory(error) && !entry.is_symlink(error)) {
        remove_tree(entry.path());
      } else {
        ::unlinkat(AT_FDCWD, entry.path().c_str(), 0);
      }
    }
    if (::rmdir(staging_.c_str()) == 0 || errno != ENOTEMPTY) break;
  }
  remove_tree(staging_);  // what is left when the passes ran out (or nothing)
}

bool OutputFolder::keeps(const std::string& name, const std::optional<FileRecord>& record) const {
  return name != FolderClaim::kMarker && !(owns(name) && recorded(folder_, name, record));
}

std::vector<std::string> OutputFolder::commit() {
  if (committed_) throw std::logic_error("OutputFolder::commit: already committed");
  if (!claim_) take_claim(true);  // a shared folder: wait for its lock
  const std::optional<FileRecord> old_record = claim_->record();
  std::vector<std::string> written;
  for (const auto& entry : fs::directory_iterator(staging_)) {
    const std::string name = entry.path().filename().string();
    if (name != FolderClaim::kMarker) written.push_back(name);
  }
  refuse_taken_names(written, old_record);
  const auto keep = [&](const std::string& name) { return keeps(name, old_record); };
  carry_over(folder_, staging_, keep);
  // The new record: what this run wrote, and the files of other runs it carried (a shared
  // folder). Until the old version is gone, the old record stays in it too, so a run killed
  // before the exchange leaves a folder whose files are still known.
  FileRecord record;
  for (const auto& entry : fs::directory_iterator(staging_)) {
    const std::string name = entry.path().filename().string();
    const bool mine = std::find(written.begin(), written.end(), name) != written.end();
    struct stat file {};
    if ((mine || recorded(folder_, name, old_record)) && name != FolderClaim::kMarker &&
        ::lstat(entry.path().c_str(), &file) == 0 && S_ISREG(file.st_mode))
      record[name].insert(file.st_ino);
  }
  FileRecord during = record;
  if (old_record)
    for (const auto& [name, inodes] : *old_record)
      during[name].insert(inodes.begin(), inodes.end());
  claim_->write_record(during);
  swap_in(staging_, folder_, retired_);
  committed_ = true;  // from here on the new version is in place
  remove_old_version(old_record);
  claim_->write_record(record);
  for (StagedFile& file : elsewhere_) file.commit();
  if (sharing_ == Sharing::by_files) claim_.reset();  // the next run sharing the folder may commit
  return written;
}

}  // namespace c2f::examples

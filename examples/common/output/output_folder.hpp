#pragma once
// A run's output folder changes in one step or not at all: the run writes a new version of the
// folder beside it and exchanges the two with one rename, so any interruption (an error, a
// signal, SIGKILL) leaves either the earlier run's folder or this run's, never a mix.
//
// The output layer (this folder), read in this order: folder_claim.hpp (whose folder it is,
// what the tool wrote there, one run at a time), folder_swap.hpp (a folder replaced in one
// step), staged_file.hpp and staged_paths.hpp (an output elsewhere, and the names messages
// give), output_paths.hpp (outputs checked against inputs), then this file, which puts them
// together for a run.

#include <chrono>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "folder_claim.hpp"
#include "staged_file.hpp"

namespace c2f::examples {

/// Whether the file name `name` matches `pattern`, where one '*' matches any run of characters
/// ("partition-level*.png" matches "partition-level3.png").
bool name_matches(const std::string& pattern, const std::string& name);

/// The output folder of one run of `tool`, which writes the files named by `owned` (patterns
/// for name_matches).
///
/// - Ownership: the folder is claimed (FolderClaim): created with a marker naming the tool, or
///   an existing folder holding that tool's valid marker, or an empty one; any other is refused.
/// - What is the tool's: the marker records the files the tool's runs wrote (name and inode).
///   A run replaces or removes only such a file (one it owns by name, still the same inode); any
///   other entry, whatever its name, is the user's and is kept. A user's entry standing where
///   the run writes is refused (before the run for fixed names, at the commit for the others),
///   never replaced.
/// - One run at a time: the claim's lock is held until the OutputFolder ends; a second run on
///   the folder is refused, naming the first. Runs that write disjoint files into one folder
///   (a benchmark's scenes, run in parallel) share it instead (Sharing::by_files): each holds
///   the lock only to claim the folder and, waiting for it (FolderClaim::kWaitLimit at most), to
///   commit.
/// - One commit: writers write into staging(), a sibling folder ".NAME.c2f-staging-PID-N"
///   holding a hard link of the marker (which alone makes it known as a run's). commit() carries
///   into it, as hard links, every entry of the old folder that stays, exchanges the two folders
///   (folder_swap.hpp), then moves into the new version whatever was created in the old one
///   while it committed, and removes the old version.
/// - Without commit() (an exception, a crash) the folder is as it was before; the destructor
///   removes the staging folder, and the folder too when this run created it. A folder the run
///   could not write or clean (its permissions, an entry it cannot keep) is refused before the
///   run starts.
class OutputFolder {
 public:
  enum class Sharing { none, by_files };

  /// Claims `folder` (symbolic links resolved) and creates the staging folder beside it, after
  /// putting back a folder that a run killed in the middle of a fallback commit left aside and
  /// removing the staging folders of killed runs (siblings holding the marker's link, whose
  /// process is gone; nothing is removed by its name alone). Throws std::runtime_error naming
  /// the folder when it is refused (FolderClaim), is the current folder or holds it, is a mount
  /// point, cannot be written, holds an entry that could not be kept (a FIFO, socket or device, a
  /// folder it cannot read) or a user's entry named as a file the run writes, or when the staging
  /// folder cannot be created.
  /// `wait_limit`: how long a run sharing the folder waits for another run's lock.
  OutputFolder(const std::filesystem::path& folder, const std::string& tool,
               std::vector<std::string> owned, Sharing sharing = Sharing::none,
               std::chrono::milliseconds wait_limit = FolderClaim::kWaitLimit);
  ~OutputFolder();
  OutputFolder(const OutputFolder&) = delete;
  OutputFolder& operator=(const OutputFolder&) = delete;

  [[nodiscard]] const std::filesystem::path& folder() const noexcept { return folder_; }
  [[nodiscard]] const std::filesystem::path& staging() const noexcept { return staging_; }

  /// Where to write `target`: staging() / its name when it lies in the output folder; else a
  /// StagedFile's path (beside the target until commit(), or the target itself for a device or
  /// a pipe). Throws std::invalid_argument naming the target when it lies in a subfolder of the
  /// output folder, or when StagedFile refuses it.
  std::filesystem::path stage(const std::filesystem::path& target);

  /// Puts the new version of the folder in place, then the outputs staged elsewhere; returns the
  /// names written into the folder. Throws std::runtime_error naming the folder or file, also
  /// when a written name is taken by a user's entry (nothing is changed then).
  std::vector<std::string> commit();

  /// Whether `name` matches one of the owned patterns.
  [[nodiscard]] bool owns(const std::string& name) const;

 private:
  static constexpr int kRemovalPasses = 100;

  /// Whether the entry `name` of `folder` is a file the tool's runs wrote (by `record`).
  [[nodiscard]] bool recorded(const std::filesystem::path& folder, const std::string& name,
                              const std::optional<FileRecord>& record) const;
  /// Whether the old folder's entry `name` goes into the new version (not the marker, not a
  /// file of an earlier run that this run replaces).
  [[nodiscard]] bool keeps(const std::string& name, const std::optional<FileRecord>& record) const;
  /// After the exchange: empties and removes the old version at staging_, moving into the new
  /// version what processes made in the old one meanwhile (an entry the new one lacks), pass
  /// by pass until the folder is empty when it is removed (at most kRemovalPasses).
  void remove_old_version(const std::optional<FileRecord>& old_record) const;
  void take_claim(bool wait);
  void remove_stale_siblings() const;
  void refuse_taken_names(const std::vector<std::string>& names,
                          const std::optional<FileRecord>& record) const;

  std::filesystem::path folder_;
  std::filesystem::path staging_;
  std::filesystem::path retired_;
  std::string tool_;
  std::vector<std::string> owned_;
  Sharing sharing_;
  std::chrono::milliseconds wait_limit_;
  std::optional<FolderClaim> claim_;
  bool created_ = false;  ///< the claim created the folder
  bool marked_ = false;   ///< the claim created the folder's marker
  std::vector<StagedFile> elsewhere_;
  bool committed_ = false;
};

}  // namespace c2f::examples
